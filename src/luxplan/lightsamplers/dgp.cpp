// DGP sampler (Wienold and Christoffersen 2006, evalglare's constants): the daylight
// glare probability at an eye, from the vertical illuminance over the hemisphere in
// front of it and the glare sources in view: every visible sun disk, every luminaire
// brighter than "source_threshold_nits", and every connected region of directions
// (sky, sunlit surfaces) brighter than it, found on a grid of "direction_cells" x
// "direction_cells" equal solid angles (glare_sources.h, docs/glare.md).
#include <stdexcept>

#include <luxplan/lightsamplers/glare_sources.h>

namespace luxplan {
namespace {

constexpr int kMinCells = 2, kMaxCells = 64;

class Dgp final : public GlareSamplerType {
public:
    Vec3 origin, direction{0, -1, 0};
    double thresholdNits = 2000;
    std::shared_ptr<const DirectionGrid> grid;  // shared by copies: its centroids cost ~n^2 * 256 maps

    const char* name() const override { return "dgp"; }
    const char* unit() const override { return "DGP"; }
    // A probability.
    ValueFormat valueFormat() const override { return {.digits = 3, .summaryDigits = 2, .unitless = true}; }
    std::string quantityHtml(bool) const override { return "DGP (daylight glare probability)"; }
    std::unique_ptr<PlacedSampler> place(const Transform& world) const override {
        return std::make_unique<PlacedGlare>(PlacedGlare::Metric::Dgp, world.applyPoint(origin),
                                             normalize(world.applyVector(direction)), thresholdNits, grid);
    }
    std::optional<Vec3> facing(const Transform& world) const override { return normalize(world.applyVector(direction)); }
    std::shared_ptr<const SamplerType> transformed(const Transform& t) const override {
        auto s = std::make_shared<Dgp>(*this);
        s->origin = t.applyPoint(origin);
        s->direction = t.applyVector(direction);
        return s;
    }
    int64_t glareSources(int64_t luminaires, int64_t sunDisks) const override { return luminaires + sunDisks; }
    std::string describe() const override {
        const int n = grid->cellsPerSide();
        return "daylight glare probability, sources above " + json::formatNumber(thresholdNits) + " cd/m2, " +
               std::to_string(n) + " x " + std::to_string(n) + " direction cells";
    }

protected:
    std::string surveyHead(double value, const GlareSurvey& g) const override {
        return "DGP " + fixedDigits(value, 3) + ", Ev " + fixedDigits(g.verticalIlluminance, 0) + " lx";
    }
};

}  // namespace

std::shared_ptr<const SamplerType> dgpSampler(Vec3 origin, Vec3 direction, double thresholdNits, int directionCells) {
    if (length(direction) < 1e-12) throw std::invalid_argument("dgp sampler: zero direction");
    if (!(thresholdNits > 0)) throw std::invalid_argument("dgp sampler: source_threshold_nits must be positive");
    if (directionCells < kMinCells || directionCells > kMaxCells)
        throw std::invalid_argument("dgp sampler: direction_cells must be in [2, 64]");
    auto s = std::make_shared<Dgp>();
    s->origin = origin;
    s->direction = normalize(direction);
    s->thresholdNits = thresholdNits;
    s->grid = std::make_shared<DirectionGrid>(directionCells);
    return s;
}

std::shared_ptr<const SamplerType> readDgpSampler(const json::Fields& f) {
    auto s = std::make_shared<Dgp>();
    s->origin = f.vec3("origin", true, json::coordinateRange()).value_or(Vec3());
    s->direction = f.direction("direction", true).value_or(Vec3(0, -1, 0));
    s->thresholdNits = f.number("source_threshold_nits", 2000.0, json::Range::positive("cd/m2"));
    const int n = f.integer("direction_cells", json::Range::closed(kMinCells, kMaxCells)).value_or(24);
    s->grid = std::make_shared<DirectionGrid>(n);
    return s;
}

}  // namespace luxplan
