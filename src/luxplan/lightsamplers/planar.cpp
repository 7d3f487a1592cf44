// Planar sampler: illuminance (lx) at the centres of the cells of a grid on a
// rectangle, e.g. a desk's work plane; its value is the mean over the points.
#include <cmath>
#include <stdexcept>

#include <luxplan/lightsamplers/sampler_type.h>
#include <luxplan/pathtracer/path_tracer.h>

namespace luxplan {
namespace {

class PlacedPlanar final : public PlacedSampler {
public:
    PlacedPlanar(std::vector<Vec3> points, Vec3 normal, std::vector<Vec3> corners)
        : points_(std::move(points)), normal_(normal), corners_(std::move(corners)) {}
    int items() const override { return int(points_.size()); }
    void sample(const PathTracer& tracer, int item, PathSamples& samples, RayStats& stats, PathContributions& out) const override {
        out.add(tracer.sample(CosineSensor(points_[size_t(item)], normal_), samples, stats));
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

    const char* name() const override { return "planar"; }
    const char* unit() const override { return "lx"; }

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

    std::shared_ptr<const SamplerType> transformed(const Transform& t) const override {
        auto s = std::make_shared<Planar>(*this);
        s->center = t.applyPoint(center);
        s->normal = t.applyVector(normal);
        s->up = t.applyVector(up);
        return s;
    }

    std::string describe() const override {
        return std::to_string(grid[0]) + " x " + std::to_string(grid[1]) + " points on " + json::formatNumber(size.x) +
               " x " + json::formatNumber(size.y) + " m";
    }
};

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

std::shared_ptr<const SamplerType> readPlanarSampler(const json::Fields& f) {
    auto s = std::make_shared<Planar>();
    s->center = f.vec3("center", true, json::coordinateRange()).value_or(Vec3());
    s->normal = f.direction("normal").value_or(Vec3(0, 0, 1));
    s->up = f.direction("up").value_or(Vec3(0, 1, 0));
    if (length(cross(s->up, s->normal)) < 1e-6) f.error(f.has("up") ? "up" : "normal", "\"up\" is parallel to \"normal\"");
    s->size = f.vec2("size", true, json::signedLengthRange()).value_or(Vec2(1, 1));
    if (f.has("size") && (s->size.x <= 0 || s->size.y <= 0))
        f.error("size", "sampler has zero area: size " + json::formatNumber(s->size.x) + " x " + json::formatNumber(s->size.y));
    if (auto g = f.numbers("grid", 2, json::Range::closed(1, 1024))) {
        if ((*g)[0] != std::floor((*g)[0]) || (*g)[1] != std::floor((*g)[1])) f.error("grid", "grid counts must be whole numbers");
        else if (const double n = (*g)[0] * (*g)[1]; n > double(limits::kMaxSamplerPoints))
            f.error("grid", json::formatNumber(n) + " points exceeds the limit of " + std::to_string(limits::kMaxSamplerPoints));
        s->grid = {int((*g)[0]), int((*g)[1])};
    }
    return s;
}

}  // namespace luxplan
