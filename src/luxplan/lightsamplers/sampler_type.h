// The interface every light sampler type implements (the paper's Section 4): how it
// is read from the scene file, placed in the world, measured by the path tracer,
// combined into one value, described, presented and drawn. Each type is one file of this
// folder (planar.cpp, directional.cpp, volume.cpp, cylindrical.cpp, ugr.cpp, dgp.cpp) and
// one line of sampler_registry.cpp; docs/architecture.md walks through adding one.
#pragma once

#include <algorithm>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include <luxplan/core/estimator.h>
#include <luxplan/core/format.h>
#include <luxplan/core/math.h>
#include <luxplan/json/fields.h>
#include <luxplan/scene/sampler_result.h>

namespace luxplan {

class PathTracer;
class PathSamples;
class Sensor;
struct RayStats;
struct PathParams;

// A value and its standard error. An error estimated from the spread of a few values
// (folds) has that many less one degrees of freedom; 0 means many (from the paths).
struct Estimate {
    double value = 0;
    double standardError = 0;
    int degreesOfFreedom = 0;
};

// What one path adds to a sampler's items: to the item it was traced for and, for a
// type whose paths reach other items too (sharesPaths()), to those. At most
// kCapacity distinct items per path (a directional path's own stratum and its eye's
// light samples: directional.cpp); adding to an item already there sums. Small,
// since the path cache keeps one per path and its checks stream through them.
class PathContributions {
public:
    static constexpr int kCapacity = 4;
    explicit PathContributions(int item) : item_(item) {}
    void add(double value) { add(item_, value); }  // to the path's own item
    void add(int item, double value) {
        for (int k = 0; k < count_; ++k)
            if (items_[k] == item) {
                values_[k] += value;
                return;
            }
        if (count_ == kCapacity) throw std::logic_error("PathContributions: more than kCapacity items in one path");
        items_[count_] = item, values_[count_] = value, ++count_;
    }
    int size() const { return count_; }
    int itemAt(int k) const { return items_[k]; }
    double valueAt(int k) const { return values_[k]; }
    bool finite() const {
        for (int k = 0; k < count_; ++k)
            if (!std::isfinite(values_[k])) return false;
        return true;
    }
    // The same items and values, bit for bit (a NaN equals the same NaN).
    bool sameAs(const PathContributions& o) const {
        if (count_ != o.count_) return false;
        for (int k = 0; k < count_; ++k)
            if (items_[k] != o.items_[k] || std::bit_cast<uint64_t>(values_[k]) != std::bit_cast<uint64_t>(o.values_[k]))
                return false;
        return true;
    }
    double sum() const {
        double s = 0;
        for (int k = 0; k < count_; ++k) s += values_[k];
        return s;
    }

private:
    int item_;
    int count_ = 0;
    // Entries [0, count_) only: not zeroed, since a path is traced for each (most add one).
    std::array<int, kCapacity> items_;
    std::array<double, kCapacity> values_;
};

// The estimates of a sampler's items, from all paths or from some folds: a path
// goes to fold (path index mod kFolds), so folds are independent and a type can
// choose among its items with some folds and measure the choice with another (the
// directional sampler's brightest stratum). Paths traced for different items are
// strata of one stratified estimate: an item's value is the mean over sources of each
// source's mean, and its variance sums the variances within each source's paths, not
// across them.
class ItemEstimates {
public:
    static constexpr int kFolds = 8;
    static constexpr unsigned kAllFolds = (1u << kFolds) - 1;

    // `sources`: how many items' paths reach each item (1 unless the sampler shares
    // paths, then all of them).
    ItemEstimates(int items, int sources);
    int items() const { return items_; }
    // What the paths traced for item `source` added to `item` in fold `fold`.
    MeanEstimator& cell(int item, int source, int fold) { return cells_[index(item, source, fold)]; }
    // Item `item` estimated from all folds, or from every fold but `heldOut`.
    Estimate of(int item) const;
    Estimate ofAllBut(int item, int heldOut) const { return stratified(item, heldOut); }
    // ... or from fold `fold` alone.
    Estimate ofFold(int item, int fold) const;
    // How many paths of fold `fold` reach `item`.
    uint64_t pathsInFold(int item, int fold) const;
    // After the cells of (item, source) are filled anew: what was computed from them is
    // computed again, on first use (the same numbers as a fresh object's).
    void changed(int item, int source);

private:
    size_t index(int item, int source, int fold) const { return (size_t(item) * sources_ + source) * kFolds + fold; }
    Estimate stratified(int item, int heldOut) const;
    int items_, sources_;
    std::vector<MeanEstimator> cells_;
    // Per (item, source), all folds merged: set up on first use, after the cells are
    // filled, so that a held-out fold costs one subtraction, not seven merges.
    mutable std::vector<MeanEstimator> totals_;
    // of() per item, computed on first use (after the cells are filled, as totals_): a
    // look asks for each several times.
    mutable std::vector<Estimate> all_;
    mutable std::vector<char> allSet_;
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

// What an item needs at a look of adaptive measurement (PlacedSampler::stillNeeded).
enum ItemNeed : char {
    kNoMorePaths = 0,  // it can no longer change the value
    kMorePaths = 1,
    // None while the value is unsettled, but before the value settles at or below its
    // band's top the item's paths catch up with the others': its estimate from fewer
    // paths may read low (heavy-tailed light that its paths have not met yet).
    kPaused = 2,
};

// One sampler where the layout puts it, ready to be traced (world frame).
class PlacedSampler {
public:
    virtual ~PlacedSampler() = default;
    // The scene's luminaires and sun disks, told once before items() is asked (by
    // placeSampler): a glare eye surveys each as a source of its own.
    virtual void setSources(int /*luminaires*/, int /*sunDisks*/) {}
    // How many estimates it is made of: its points, or its strata.
    virtual int items() const = 0;
    // Traces one path for `item` with `params` (its roulette floor and recorders:
    // PathParams) and adds what it contributes, in the type's unit.
    virtual void sample(const PathTracer& tracer, int item, PathSamples& samples, RayStats& stats, const PathParams& params,
                        PathContributions& out) const = 0;
    // Whether a path traced for one item may add to others. If so, every item's
    // estimate is the mean over all the sampler's paths (each path then adds its
    // contribution times items(), so that an item's own paths keep their weight).
    // Otherwise an item's estimate is the mean over its own paths, and sample()
    // adds to that item only.
    virtual bool sharesPaths() const { return false; }
    // Whether the type compares its folds (chooses with some, measures with another):
    // with low-discrepancy sampling, each fold's paths then come from a sequence of
    // their own, so that folds stay independent. Otherwise all of an item's paths are
    // one sequence, which stratifies better.
    virtual bool independentFolds() const { return false; }
    // The sampler's value from its items' estimates. Default: the mean of the items,
    // whose error is the root sum of squares over their count.
    virtual Estimate combine(const ItemEstimates& items) const;
    // The standard error to report for `value` (combine()'s), MeasureOptions::choiceError.
    // Default: its own. A type whose value chooses among its items adds how that choice
    // varies where the value's own error cannot see it.
    virtual double reportedError(const ItemEstimates& /*items*/, const Estimate& value) const { return value.standardError; }
    // In adaptive measurement, at a look that left the value unsettled: what each
    // item needs (ItemNeed), z being the confidence multiplier and [targetMin,
    // targetMax] the sampler's band. Default: more for every item (a mean needs them all).
    virtual std::vector<char> stillNeeded(const ItemEstimates& items, double z, double targetMin, double targetMax) const;
    // In adaptive measurement: how high the value may be, at z errors, where its own
    // interval can fall short of that (a stop needs both below a bound). Default: no
    // more than the value's interval says.
    virtual double upperEnd(const ItemEstimates& /*items*/, double /*z*/) const { return -kInf; }
    // ... and how low it may be, at z errors, where its items alone bound it from below
    // more tightly than its own interval does (a stop above a bound needs either).
    // Default: no more than the value's interval says.
    virtual double lowerEnd(const ItemEstimates& /*items*/, double /*z*/) const { return -kInf; }
    virtual SamplerDrawing drawing() const = 0;
    // The sensor item `item`'s paths start from, where each item is one sensor whose
    // paths' mean is its estimate (no shared paths, no cells): daylight coefficients
    // (annual/daylight_coefficients.h) split those paths' light by where it came from.
    // Null for the other types.
    virtual std::unique_ptr<Sensor> sensorOf(int item) const;
    // What its value is made of, from its items' means (the points of a SamplerResult,
    // in item order), where the type reports it: a glare eye's survey of its sources.
    virtual std::optional<GlareSurvey> survey(const std::vector<double>& /*itemMeans*/) const { return std::nullopt; }
    // The points a layout's furniture covers (planar samplers: findCoveredPoints), one
    // flag per item; none are traced and the default combine() leaves them out.
    virtual std::vector<Vec3> coverageProbes(Vec3& normal) const {
        (void)normal;
        return {};
    }
    void setCovered(std::vector<char> covered) { covered_ = std::move(covered); }
    bool covered(int item) const { return size_t(item) < covered_.size() && covered_[size_t(item)]; }
    bool anyCovered() const { return std::find(covered_.begin(), covered_.end(), char(1)) != covered_.end(); }

private:
    std::vector<char> covered_;
};

// How a type's values read for people: measure's table, the reports, the plan.
struct ValueFormat {
    int digits = 1;         // decimals in measure's table and the detail lines
    int summaryDigits = 0;  // decimals in report.html's results (lx and cd/m2 to the unit)
    // Below it a value reads "<floor" (UGR: CIE 117's scale starts at 10); JSON keeps the number.
    double floor = -kInf;
    bool unitless = false;  // its unit names the quantity (UGR, DGP): no unit after a number
    // `v` with `decimals` decimals, or "<floor".
    std::string text(double v, int decimals) const {
        if (!(v < floor)) return fixedDigits(v, decimals);
        std::string below(1, '<');  // appended piecewise: GCC 12 warns falsely (-Wrestrict) on "<" + string
        return below.append(formatNumber(floor));
    }
};

// Where report.html's results list a sampler: a task area (its Em, Emin and U0), a
// viewpoint's glare, or among the others.
enum class ResultGroup { TaskArea, Glare, Other };

// Where a sampler is in the scene: the inner boxes of the scene's rooms (world
// frame) and whether an entity carries it.
struct SamplerSite {
    std::vector<Bounds3> rooms;
    bool carried = false;
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
    // Whether its value is the mean of its points, so that their min, max and
    // uniformity U0 (EN 12464-1, core/point_statistics.h) describe it and may carry
    // goals (the sampler's "statistics"): planar and volume.
    virtual bool hasPointStatistics() const { return false; }
    // The direction it looks in when its frame is at `worldFromFrame`, where it has one
    // (a planar sampler's normal, a directional one's view axis, a glare eye's line of
    // sight), for the scene checks.
    virtual std::optional<Vec3> facing(const Transform& /*worldFromFrame*/) const { return std::nullopt; }
    // Whether it gathers light from every direction (cylindrical, volume), so that on
    // the room's shell half of what it sees lies outside, whichever way it is turned.
    virtual bool looksAllRound() const { return false; }
    // How many glare sources its eye surveys one by one in a scene of `luminaires` and
    // `sunDisks` (ugr: the luminaires; dgp: the sun disks too), for the limit on them
    // (limits::kMaxGlareSources); 0 for a kind that surveys none.
    virtual int64_t glareSources(int64_t /*luminaires*/, int64_t /*sunDisks*/) const { return 0; }
    // What tracing its paths needs: true where they survey sources each on a scale of
    // its own (a glare eye), so that no roulette floor from their spread fits their
    // light samples (lightSampleFloors) and they go to the survey tracer where the
    // caller gives one (measureSamplers' glareTracer: the search's, with the sunlit patches).
    virtual bool surveysSources() const { return false; }
    // How its values read (digits, a floor, a unit of its own).
    virtual ValueFormat valueFormat() const { return {}; }
    // report.html's results: which group lists it, and what its value is called there
    // (HTML; `maintained`: a maintenance factor below 1 scales the luminaires' light).
    virtual ResultGroup resultGroup() const { return ResultGroup::Other; }
    virtual std::string quantityHtml(bool /*maintained*/) const { return name(); }
    // Its measurement's details beyond the value and the point statistics: as report.json's
    // and measure --json's keys, added to `out`, and as one line of text (measure's
    // table; "" for none). A glare eye's sources.
    virtual void addDetails(const SamplerResult& /*result*/, nlohmann::ordered_json& /*out*/) const {}
    virtual std::string detailsText(const SamplerResult& /*result*/) const { return ""; }
    // Its points as an nx x ny grid (planar), for reports; none otherwise.
    virtual std::optional<std::array<int, 2>> pointGrid() const { return std::nullopt; }
    // The sampler fitted to where the loader found it, which its reader cannot see
    // (the planar type's "wall_band" trims its area at the walls of its room), with
    // problems reported through `f`, the sampler's object; null: nothing to fit.
    virtual std::shared_ptr<const SamplerType> fitted(const SamplerSite& /*site*/, const json::Fields& /*f*/) const {
        return nullptr;
    }
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
// EN 12464-1's calculation grid on a w x h area (the planar type's "grid":
// "en12464"): cells of at most p = 0.2 * 5^log10(d) m, d the longer side, p at most
// 10 m; n = ceil(side / p) cells per side, a point at each centre. 5 x 4 m: p = 0.616
// m, 9 x 7 points.
double en12464Spacing(double longerSide);
std::array<int, 2> en12464Grid(Vec2 size);
std::shared_ptr<const SamplerType> directionalSampler(Vec3 origin, Vec3 direction, Vec3 up, double fovDeg, int strata);
std::shared_ptr<const SamplerType> volumeSampler(Vec3 center, std::array<Vec3, 3> axes, int points);
std::shared_ptr<const SamplerType> cylindricalSampler(Vec3 center);

// Every sampler type, in the order the docs list them (sampler_registry.cpp).
const std::vector<SamplerTypeEntry>& samplerTypes();
const SamplerTypeEntry* findSamplerType(std::string_view name);
std::vector<std::string> samplerTypeNames();

}  // namespace luxplan
