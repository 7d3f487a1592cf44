// Planar sampler: illuminance (lx) at the centres of the cells of a grid on a
// rectangle, e.g. a desk's work plane; its value is the mean over the points. The
// grid is given, or EN 12464-1's for the area, which may be trimmed by a band at the
// room's walls (docs/scene-format.md#samplers-lighting-intentions).
#include <cmath>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include <luxplan/lightsamplers/sampler_type.h>
#include <luxplan/pathtracer/path_tracer.h>

namespace luxplan {
namespace {

// "" or why an EN 12464-1 grid has too many points (core/limits.h).
std::string gridLimitProblem(std::array<int, 2> grid) {
    if (grid[0] <= 1024 && grid[1] <= 1024 && int64_t(grid[0]) * grid[1] <= limits::kMaxSamplerPoints) return "";
    return "the EN 12464-1 grid of " + std::to_string(grid[0]) + " x " + std::to_string(grid[1]) +
           " points exceeds the limit of 1024 per side and " + std::to_string(limits::kMaxSamplerPoints) + " in all";
}

class PlacedPlanar final : public PlacedSampler {
public:
    PlacedPlanar(std::vector<Vec3> points, Vec3 normal, std::vector<Vec3> corners)
        : points_(std::move(points)), normal_(normal), corners_(std::move(corners)) {}
    int items() const override { return int(points_.size()); }
    void sample(const PathTracer& tracer, int item, PathSamples& samples, RayStats& stats, const PathParams& params,
                PathContributions& out) const override {
        out.add(tracer.sample(CosineSensor(points_[size_t(item)], normal_), samples, stats, params));
    }
    std::unique_ptr<Sensor> sensorOf(int item) const override {
        return std::make_unique<CosineSensor>(points_[size_t(item)], normal_);
    }
    std::vector<Vec3> coverageProbes(Vec3& normal) const override {
        normal = normal_;
        return points_;
    }
    SamplerDrawing drawing() const override {
        SamplerDrawing d;
        d.outline = corners_;
        d.lineWidth = 2.5;
        d.dots = points_;
        return d;
    }

private:
    std::vector<Vec3> points_;  // row-major over the grid, the first side fastest
    Vec3 normal_;
    std::vector<Vec3> corners_;
};

class Planar final : public SamplerType {
public:
    Vec3 center, normal{0, 0, 1}, up{0, 1, 0};
    Vec2 size{1, 1};
    std::array<int, 2> grid{4, 4};
    bool en12464 = false;           // the grid follows EN 12464-1's rule for `size`
    std::optional<double> wallBand;  // m; trims `size` at the room's walls (fitted(), idempotent)

    const char* name() const override { return "planar"; }
    const char* unit() const override { return "lx"; }
    ResultGroup resultGroup() const override { return ResultGroup::TaskArea; }
    std::string quantityHtml(bool maintained) const override {
        return maintained ? "E<sub>m</sub> (maintained mean)" : "E<sub>m</sub> (mean)";
    }

    std::unique_ptr<PlacedSampler> place(const Transform& world) const override {
        Vec3 n = normalize(normal);
        Vec3 v = normalize(up - n * dot(up, n));
        Vec3 w = normalize(cross(v, n));
        std::vector<Vec3> points, corners;
        for (int j = 0; j < grid[1]; ++j)
            for (int i = 0; i < grid[0]; ++i) {
                double a = ((i + 0.5) / grid[0] - 0.5) * size.x, b = ((j + 0.5) / grid[1] - 0.5) * size.y;
                points.push_back(world.applyPoint(center + w * a + v * b));
            }
        for (int i = 0; i < 4; ++i) {
            double a = (i == 0 || i == 3) ? -0.5 : 0.5, b = i < 2 ? -0.5 : 0.5;
            corners.push_back(world.applyPoint(center + w * (a * size.x) + v * (b * size.y)));
        }
        return std::make_unique<PlacedPlanar>(std::move(points), normalize(world.applyVector(n)), std::move(corners));
    }

    std::optional<Vec3> facing(const Transform& world) const override { return normalize(world.applyVector(normal)); }

    std::shared_ptr<const SamplerType> transformed(const Transform& t) const override {
        auto s = std::make_shared<Planar>(*this);
        s->center = t.applyPoint(center);
        s->normal = t.applyVector(normal);
        s->up = t.applyVector(up);
        return s;
    }

    std::string describe() const override {
        std::string d = std::to_string(grid[0]) + " x " + std::to_string(grid[1]) + " points";
        if (en12464) d += " (EN 12464-1 grid)";
        d += " on " + json::formatNumber(size.x) + " x " + json::formatNumber(size.y) + " m";
        if (wallBand) d += " (a " + json::formatNumber(*wallBand) + " m band at the walls left out)";
        return d;
    }

    bool hasPointStatistics() const override { return true; }
    std::optional<std::array<int, 2>> pointGrid() const override { return grid; }

    std::shared_ptr<const SamplerType> fitted(const SamplerSite& site, const json::Fields& f) const override {
        return wallBand ? trimAtWalls(site, f) : nullptr;
    }

private:
    std::shared_ptr<const SamplerType> trimAtWalls(const SamplerSite& site, const json::Fields& f) const;
};

// The area minus the band within `wallBand` of the walls of the room that holds the
// centre: only a world-fixed, horizontal sampler with sides along the walls can be
// trimmed to a rectangle that stays put.
std::shared_ptr<const SamplerType> Planar::trimAtWalls(const SamplerSite& site, const json::Fields& f) const {
    const double band = *wallBand;
    if (site.carried) {
        f.error("wall_band", "a wall band needs a world-fixed sampler: one carried by an entity moves with it");
        return nullptr;
    }
    const Vec3 n = normalize(normal), v = normalize(up - n * dot(up, n)), w = normalize(cross(v, n));
    auto axial = [](Vec3 d) { return std::abs(std::abs(d.x) + std::abs(d.y) + std::abs(d.z) - 1) < 1e-9; };
    if (std::abs(std::abs(n.z) - 1) > 1e-9 || !axial(v)) {
        f.error("wall_band", "a wall band needs a horizontal sampler (normal [0, 0, 1] or [0, 0, -1]) whose sides run "
                             "along the walls (up along x or y)");
        return nullptr;
    }
    const Bounds3* room = nullptr;
    for (const Bounds3& r : site.rooms)
        if (r.contains(center)) room = &r;
    if (!room) {
        f.error("wall_band", "no room holds the sampler's centre [" + json::formatNumber(center.x) + ", " +
                                 json::formatNumber(center.y) + ", " + json::formatNumber(center.z) +
                                 "]: a wall band is measured from the walls of its room");
        return nullptr;
    }
    // The side along x is size.x when w runs along x, else size.y.
    const bool wAlongX = std::abs(w.x) > 0.5;
    const Vec2 half = wAlongX ? Vec2(size.x / 2, size.y / 2) : Vec2(size.y / 2, size.x / 2);
    const double x0 = std::max(center.x - half.x, room->lo.x + band), x1 = std::min(center.x + half.x, room->hi.x - band);
    const double y0 = std::max(center.y - half.y, room->lo.y + band), y1 = std::min(center.y + half.y, room->hi.y - band);
    if (!(x1 - x0 > 1e-9) || !(y1 - y0 > 1e-9)) {
        f.error("wall_band", "a wall band of " + json::formatNumber(band) + " m leaves nothing of the sampler in the room " +
                                 json::formatNumber(room->lo.x) + ".." + json::formatNumber(room->hi.x) + " x " +
                                 json::formatNumber(room->lo.y) + ".." + json::formatNumber(room->hi.y) + " m");
        return nullptr;
    }
    auto s = std::make_shared<Planar>(*this);
    s->center = Vec3((x0 + x1) / 2, (y0 + y1) / 2, center.z);
    s->size = wAlongX ? Vec2(x1 - x0, y1 - y0) : Vec2(y1 - y0, x1 - x0);
    if (en12464) {
        s->grid = en12464Grid(s->size);
        if (std::string problem = gridLimitProblem(s->grid); !problem.empty()) {
            f.error("grid", problem);
            return nullptr;
        }
    }
    return s;
}

}  // namespace

std::shared_ptr<const SamplerType> planarSampler(Vec3 center, Vec3 normal, Vec3 up, Vec2 size, std::array<int, 2> grid) {
    if (length(normal) < 1e-12 || length(up) < 1e-12) throw std::invalid_argument("planar sampler: zero direction");
    auto s = std::make_shared<Planar>();
    s->center = center;
    s->normal = normalize(normal);
    s->up = normalize(up);
    if (length(cross(s->up, s->normal)) < 1e-6) throw std::invalid_argument("planar sampler: \"up\" is parallel to \"normal\"");
    if (size.x <= 0 || size.y <= 0) throw std::invalid_argument("planar sampler has zero area");
    if (grid[0] < 1 || grid[1] < 1 || grid[0] > 1024 || grid[1] > 1024)
        throw std::invalid_argument("planar sampler: grid counts must lie in [1, 1024]");
    if (int64_t(grid[0]) * grid[1] > limits::kMaxSamplerPoints)
        throw std::invalid_argument("planar sampler: " + std::to_string(int64_t(grid[0]) * grid[1]) +
                                    " points exceeds the limit of " + std::to_string(limits::kMaxSamplerPoints));
    s->size = size;
    s->grid = grid;
    return s;
}

double en12464Spacing(double longerSide) { return std::min(10.0, 0.2 * std::pow(5.0, std::log10(longerSide))); }

std::array<int, 2> en12464Grid(Vec2 size) {
    const double p = en12464Spacing(std::max(size.x, size.y));
    // A side that is a whole number of cells in exact arithmetic must not gain one
    // from rounding (10 m: p = 1, 10 points).
    auto count = [p](double side) { return int(std::max(1.0, std::ceil(side / p * (1 - 1e-12)))); };
    return {count(size.x), count(size.y)};
}

std::shared_ptr<const SamplerType> readPlanarSampler(const json::Fields& f) {
    auto s = std::make_shared<Planar>();
    s->center = f.vec3("center", true, json::coordinateRange()).value_or(Vec3());
    s->normal = f.direction("normal").value_or(Vec3(0, 0, 1));
    s->up = f.direction("up").value_or(Vec3(0, 1, 0));
    if (length(cross(s->up, s->normal)) < 1e-6) f.error(f.has("up") ? "up" : "normal", "\"up\" is parallel to \"normal\"");
    s->size = f.vec2("size", true, json::signedLengthRange()).value_or(Vec2(1, 1));
    if (f.has("size") && (s->size.x <= 0 || s->size.y <= 0))
        f.error("size", "sampler has zero area: size " + json::formatNumber(s->size.x) + " x " + json::formatNumber(s->size.y));
    if (f.has("grid") && f.get("grid").is_string()) {
        if (f.get("grid").get<std::string>() != "en12464")
            f.error("grid", "unknown grid \"" + f.get("grid").get<std::string>() +
                                "\": expected [nx, ny] or \"en12464\" (EN 12464-1's grid for the area)");
        s->en12464 = true;
    } else if (auto g = f.numbers("grid", 2, json::Range::closed(1, 1024))) {
        if ((*g)[0] != std::floor((*g)[0]) || (*g)[1] != std::floor((*g)[1])) f.error("grid", "grid counts must be whole numbers");
        else if (const double n = (*g)[0] * (*g)[1]; n > double(limits::kMaxSamplerPoints))
            f.error("grid", json::formatNumber(n) + " points exceeds the limit of " + std::to_string(limits::kMaxSamplerPoints));
        s->grid = {int((*g)[0]), int((*g)[1])};
    }
    s->wallBand = f.number("wall_band", json::Range::positive("m").limitedTo(limits::kMaxLength));
    // A trimmed area gets its grid in fitted(); its limits are checked there.
    if (s->en12464 && s->size.x > 0 && s->size.y > 0) {
        s->grid = en12464Grid(s->size);
        if (std::string problem = gridLimitProblem(s->grid); !s->wallBand && !problem.empty()) f.error("grid", problem);
    }
    return s;
}

}  // namespace luxplan
