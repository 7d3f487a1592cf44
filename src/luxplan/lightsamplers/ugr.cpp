// UGR sampler (CIE 117-1995): the unified glare rating of the luminaires an eye sees
// in front of it and above its horizontal plane, UGR = 8 log10(0.25 / L_b * sum L_i^2
// omega_i / P_i^2), L_b = E_ind / pi with E_ind the vertical illuminance at the eye
// from everything but those luminaires' direct light (glare_sources.h, docs/glare.md).
#include <stdexcept>

#include <luxplan/lightsamplers/glare_sources.h>

namespace luxplan {
namespace {

class Ugr final : public GlareSamplerType {
public:
    Vec3 origin, direction{0, -1, 0};

    const char* name() const override { return "ugr"; }
    const char* unit() const override { return "UGR"; }
    // CIE 117's scale starts at 10: below it, "<10".
    ValueFormat valueFormat() const override { return {.digits = 1, .summaryDigits = 1, .floor = 10, .unitless = true}; }
    std::string quantityHtml(bool) const override { return "UGR (unified glare rating)"; }
    std::unique_ptr<PlacedSampler> place(const Transform& world) const override {
        return std::make_unique<PlacedGlare>(PlacedGlare::Metric::Ugr, world.applyPoint(origin),
                                             normalize(world.applyVector(direction)), 0.0);
    }
    std::optional<Vec3> facing(const Transform& world) const override { return normalize(world.applyVector(direction)); }
    std::shared_ptr<const SamplerType> transformed(const Transform& t) const override {
        auto s = std::make_shared<Ugr>(*this);
        s->origin = t.applyPoint(origin);
        s->direction = t.applyVector(direction);
        return s;
    }
    std::string describe() const override { return "unified glare rating of the luminaires in view (CIE 117)"; }
    int64_t glareSources(int64_t luminaires, int64_t) const override { return luminaires; }

protected:
    std::string surveyHead(double value, const GlareSurvey& g) const override {
        return "UGR " + valueFormat().text(value, 1) + ", Lb " + fixedDigits(g.backgroundLuminance, 1) + " cd/m2";
    }
};

}  // namespace

std::shared_ptr<const SamplerType> ugrSampler(Vec3 origin, Vec3 direction) {
    if (length(direction) < 1e-12) throw std::invalid_argument("ugr sampler: zero direction");
    auto s = std::make_shared<Ugr>();
    s->origin = origin;
    s->direction = normalize(direction);
    return s;
}

std::shared_ptr<const SamplerType> readUgrSampler(const json::Fields& f) {
    auto s = std::make_shared<Ugr>();
    s->origin = f.vec3("origin", true, json::coordinateRange()).value_or(Vec3());
    s->direction = f.direction("direction", true).value_or(Vec3(0, -1, 0));
    return s;
}

}  // namespace luxplan
