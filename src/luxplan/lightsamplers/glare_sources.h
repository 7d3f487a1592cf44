// Glare metrics shared by the "ugr" and "dgp" samplers (docs/glare.md): the Guth
// position index as evalglare codes it, UGR (CIE 117-1995) and DGP (Wienold and
// Christoffersen 2006, evalglare's constants), and the placed sampler both use: the
// vertical illuminance at the eye and a direct view of each source (luminaire, sun
// disk), each source's visible solid angle omega, mean luminance L and direction.
#pragma once

#include <memory>
#include <vector>

#include <luxplan/lightsamplers/sampler_result.h>
#include <luxplan/lightsamplers/sampler_type.h>

namespace luxplan {

// P from tau (the angle between the vertical plane through the line of sight and the
// plane holding the line of sight and the source; 0 straight above) and sigma (the
// angle between the line of sight and the source), in degrees; capped at 16.
double guthIndex(double tauDeg, double sigmaDeg);
// P of the unit direction `w` seen along unit `forward` with world up +z: Guth above
// the line of sight, Iwata's formula (evalglare's) below it; 16 behind the eye.
double guthIndexOf(const Vec3& forward, const Vec3& w);

// 8 log10(0.25 / Lb * sum L^2 omega / P^2), 0 with no source (and never below 0).
double unifiedGlareRating(double backgroundLuminance, const std::vector<GlareSource>& sources);
// 5.87e-5 Ev + 0.159 + 0.092 log10(1 + sum L^2 omega / (P^2 Ev^1.87)), times the
// low-light factor below 1000 lx, clamped to [0, 1].
double daylightGlareProbability(double verticalIlluminance, const std::vector<GlareSource>& sources);

// The placed "ugr" or "dgp" sampler. Items: 0 the vertical illuminance at the eye,
// then per source slot (emitters first, then sun disks, up to kSlots) its visible
// solid angle, L omega, direct vertical illuminance and omega-weighted direction.
class PlacedGlare final : public PlacedSampler {
public:
    static constexpr int kSlots = 32, kQuantities = 6;
    enum class Metric { Ugr, Dgp };
    PlacedGlare(Metric metric, Vec3 eye, Vec3 forward, double thresholdNits)
        : metric_(metric), eye_(eye), forward_(forward), threshold_(thresholdNits) {}

    int items() const override { return 1 + kSlots * kQuantities; }
    void sample(const PathTracer& tracer, int item, PathSamples& samples, RayStats& stats, PathContributions& out) const override;
    // The metric from all folds; its error by the jackknife over the folds.
    Estimate combine(const ItemEstimates& items) const override;
    SamplerDrawing drawing() const override;
    // The survey from item means (points of a SamplerResult, in item order).
    GlareSurvey survey(const std::vector<double>& itemMeans) const;

private:
    Metric metric_;
    Vec3 eye_, forward_;
    double threshold_;
};

// Constructed in C++ (tests): a normalized direction, which must not be zero.
std::shared_ptr<const SamplerType> ugrSampler(Vec3 origin, Vec3 direction);
std::shared_ptr<const SamplerType> dgpSampler(Vec3 origin, Vec3 direction, double sourceThresholdNits = 2000);
// The survey behind a measured glare sampler's value (null type: not a glare sampler).
std::optional<GlareSurvey> glareSurvey(const SamplerType& type, const Transform& worldFromFrame,
                                       const std::vector<double>& itemMeans);

}  // namespace luxplan
