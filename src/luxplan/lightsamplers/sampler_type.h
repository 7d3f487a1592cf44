// The interface every light sampler type implements (the paper's Section 4): how it
// is read from the scene file, placed in the world, measured by the path tracer,
// combined into one value, described and drawn. Each type is one file of this folder
// (planar.cpp, directional.cpp, volume.cpp) and one line of sampler_registry.cpp;
// docs/architecture.md walks through adding one.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <luxplan/core/math.h>
#include <luxplan/json/fields.h>

namespace luxplan {

class PathTracer;
class Rng;
struct RayStats;

// A value and its standard error.
struct Estimate {
    double value = 0;
    double standardError = 0;
};

// How the floor plan shows a sampler (output/plan.cpp), in world space.
struct SamplerDrawing {
    std::vector<Vec3> outline;     // a polygon, projected onto the plan
    double fillOpacity = 0;        // 0: the outline only
    double lineWidth = 2;
    std::vector<Vec3> dots;        // points worth marking (measurement points, an eye)
    double dotRadius = 2;
    std::optional<Vec3> labelAt;   // where its label goes; default: the outline's centroid
};

// One sampler where the layout puts it, ready to be traced (world frame).
class PlacedSampler {
public:
    virtual ~PlacedSampler() = default;
    // How many independent estimates it is made of: its points, or its strata.
    virtual int items() const = 0;
    // One path's contribution to estimate `item`, in the type's unit.
    virtual double sample(const PathTracer& tracer, int item, Rng& rng, RayStats& stats) const = 0;
    // The sampler's value from its items' means and standard errors. Default: the
    // mean of the items, whose error is the root sum of squares over their count.
    virtual Estimate combine(const std::vector<double>& means, const std::vector<double>& errors) const;
    virtual SamplerDrawing drawing() const = 0;
};

// A sampler type's own parameters, in the frame of the entity that carries it (the
// world for a fixed sampler). Immutable: a scene shares it between copies.
class SamplerType {
public:
    virtual ~SamplerType() = default;
    virtual const char* name() const = 0;  // the scene file's "type"
    virtual const char* unit() const = 0;  // of its value, target and tolerance
    // Where it measures when its frame is at `worldFromFrame`.
    virtual std::unique_ptr<PlacedSampler> place(const Transform& worldFromFrame) const = 0;
    // The same sampler described in another frame: `newFromOld` maps the old frame
    // into the new one (flattenScene moves a group's samplers onto a member).
    virtual std::shared_ptr<const SamplerType> transformed(const Transform& newFromOld) const = 0;
    // One line for people: "4 x 4 points on 1.6 x 0.8 m, facing +z".
    virtual std::string describe() const = 0;
};

// A registered type: its name in the scene file and how its own keys are read. A
// reader reports problems through `f` and reads nothing but `f`, so the loader can
// probe it for the keys it knows.
struct SamplerTypeEntry {
    const char* name;
    std::shared_ptr<const SamplerType> (*read)(const json::Fields& f);
};

// Constructed in C++ (tests, tools), each built as its reader builds it: directions
// are normalized, and what the reader reports as an error throws
// std::invalid_argument. Defined in the type's own file.
std::shared_ptr<const SamplerType> planarSampler(Vec3 center, Vec3 normal, Vec3 up, Vec2 size, std::array<int, 2> grid);
std::shared_ptr<const SamplerType> directionalSampler(Vec3 origin, Vec3 direction, Vec3 up, double fovDeg, int strata);
std::shared_ptr<const SamplerType> volumeSampler(Vec3 center, std::array<Vec3, 3> axes, int points);
std::shared_ptr<const SamplerType> cylindricalSampler(Vec3 center);

// Every sampler type, in the order the docs list them (sampler_registry.cpp).
const std::vector<SamplerTypeEntry>& samplerTypes();
const SamplerTypeEntry* findSamplerType(std::string_view name);
std::vector<std::string> samplerTypeNames();

}  // namespace luxplan
