// The interface every luminaire shape implements: a Lambertian emitter's luminous
// surface, how it is read from the scene file, sampled from a shading point (by
// solid angle), intersected by Embree, drawn on the plan and exported to glTF. Each
// shape is one file of this folder (rect.cpp, disk.cpp, sphere.cpp) and one line of
// emitter_registry.cpp; docs/architecture.md walks through adding one.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <luxplan/core/math.h>
#include <luxplan/json/fields.h>
#include <luxplan/scene/mesh.h>
#include <luxplan/scene/scene.h>

namespace luxplan {

// What Embree intersects for an emitter: triangles, or one of its point primitives.
struct EmitterPrimitive {
    enum class Kind { Triangles, Sphere, Disc } kind = Kind::Triangles;
    TriangleMesh triangles;  // Triangles: wound so that their normal is the emitter's
    Vec3 center, normal;     // Sphere, Disc (the disc faces `normal`)
    double radius = 0;
};

// A point sampled on an emitter as seen from a shading point.
struct EmitterPoint {
    Vec3 position;
    Vec3 normal;     // of the surface there
    double pdf = 0;  // per unit solid angle at the shading point
};

// The emitter as a glTF viewer sees it: a mesh in a frame where it emits towards -z
// (glTF spot lights shine along their node's -z), or all round for a two-sided one.
struct EmitterMesh {
    TriangleMesh mesh;  // in `frame`
    Transform frame;    // in the emitter's owner's frame (world or entity)
};

class EmitterShape {
public:
    virtual ~EmitterShape() = default;
    virtual const char* name() const = 0;  // the scene file's "shape"
    virtual double area() const = 0;        // m^2
    virtual Vec3 center() const = 0;
    // The unit normal of a one-sided emitter, which lights only the half-space it
    // faces; none for one that emits all round.
    virtual std::optional<Vec3> normal() const = 0;
    // The radius of a sphere round center() that holds the whole shape: the distance
    // within which flux / distance^2 stops growing (emitter choice), and the cone a
    // sensor must see for a sample of it to count (Sensor::maySee).
    virtual double reach() const = 0;
    // A rect's first side (unit, from its first corner along the side of length
    // size[0]): where a photometric luminaire's C = 0 points by default.
    virtual std::optional<Vec3> firstSide() const { return std::nullopt; }
    // The same shape in another frame (`newFromOld`): placed in the world for the
    // current layout, or moved onto another entity by flattenScene.
    virtual std::shared_ptr<const EmitterShape> transformed(const Transform& newFromOld) const = 0;
    // A point whose direction from `p` is distributed by pdf(); none when it cannot
    // be seen from there (p on its plane or inside it).
    virtual std::optional<EmitterPoint> sample(const Vec3& p, Vec2 u) const = 0;
    // The solid-angle density of sample() at the point `q` on the shape, from `p`.
    virtual double pdf(const Vec3& p, const Vec3& q) const = 0;
    // sample() and pdf() from one point `p`, for many calls: every path of a sampler
    // point starts there. What each call would set up (a rect's spherical rectangle)
    // is set up once; the numbers are the same. The default shares nothing.
    class FromPoint {
    public:
        virtual ~FromPoint() = default;
        virtual std::optional<EmitterPoint> sample(Vec2 u) const = 0;
        virtual double pdf(const Vec3& q) const = 0;
    };
    virtual std::unique_ptr<const FromPoint> from(const Vec3& p) const;
    virtual EmitterPrimitive primitive() const = 0;
    virtual std::vector<Vec3> outline() const = 0;  // a closed polygon on the shape, for plans
    static constexpr int kOutlinePoints = 32;       // a round outline's
    virtual EmitterMesh mesh() const = 0;
    // One line for people: "0.6 x 0.6 m rect".
    virtual std::string describe() const = 0;
};

// Emitted luminance (cd/m^2) of a Lambertian emitter: flux / (pi * area).
double emitterLuminance(const Emitter& e);

// A registered shape: its name in the scene file and how its own keys are read. A
// reader reports problems through `f` and reads nothing but `f`, so the loader can
// probe it for the keys it knows.
struct EmitterShapeEntry {
    const char* name;
    std::shared_ptr<const EmitterShape> (*read)(const json::Fields& f);
};

// Every emitter shape, in the order the docs list them (emitter_registry.cpp).
const std::vector<EmitterShapeEntry>& emitterShapes();
const EmitterShapeEntry* findEmitterShape(std::string_view name);
std::vector<std::string> emitterShapeNames();

// The shapes built in code (tests, examples): `up` runs along the rect's second side.
std::shared_ptr<const EmitterShape> rectEmitter(Vec3 center, Vec3 normal, Vec3 up, Vec2 size);
std::shared_ptr<const EmitterShape> diskEmitter(Vec3 center, Vec3 normal, double radius);
std::shared_ptr<const EmitterShape> sphereEmitter(Vec3 center, double radius);

}  // namespace luxplan
