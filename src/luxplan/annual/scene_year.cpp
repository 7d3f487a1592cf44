#include <luxplan/annual/scene_year.h>

#include <stdexcept>

#include <luxplan/annual/annual_metrics.h>
#include <luxplan/daylight/perez_sky.h>
#include <luxplan/rt/embree_scene.h>

namespace luxplan {

DaylightCoefficients sceneYear(const Scene& scene) {
    if (!scene.daylight) throw std::runtime_error("the scene has no \"daylight\": an annual measurement needs its hours");
    const DaylightParams& d = *scene.daylight;
    std::vector<DaylightInstant> hours = annualHours(d, scene.site);
    if (hours.empty())
        throw std::runtime_error("no occupied hour with the sun above the horizon in the daylight's period "
                                 "(its \"from\"/\"to\" and \"occupied\")");
    DaylightCoefficientOptions options;
    options.groundReflectance = d.groundReflectance;
    return DaylightCoefficients(
        hours,
        [&d, &hours](size_t h) -> HourSky {
            const DaylightInstant& i = hours[h];
            if (d.model == SkyModelType::Perez) {
                // The relative distribution, normalised on the patches themselves.
                const PerezSkyCondition condition = perezConditionOf(d, i);
                if (!condition.lit) return HourSky([](const Vec3&) { return 0.0; });
                const PerezAllWeatherSky sky(condition, i.sunDirection, false);
                return HourSky([sky](const Vec3& w) { return sky.relativeLuminance(w); }, condition.diffuseHorizontalLx);
            }
            return skyLuminanceAt(d, i);
        },
        options);
}

AnnualSeries measureYearAt(const DaylightCoefficients& year, const EmbreeScene& rt, const std::vector<size_t>& which,
                           int paths, uint64_t seed, const std::function<void(size_t, size_t)>& progress) {
    const PathTracer basis(rt, &year.basis(), DaylightCoefficients::tracing());
    return year.measure(basis, which, paths, seed, progress);
}

std::vector<size_t> annualGoalSamplers(const Scene& scene) {
    std::vector<size_t> out;
    for (size_t k = 0; k < scene.samplers.size(); ++k)
        if (scene.samplers[k].annual) out.push_back(k);
    return out;
}

void setAnnualInRange(const Scene& scene, const AnnualSeries& series, std::vector<SamplerResult>& results) {
    for (const AnnualSampler& a : series.samplers)
        for (size_t k = 0; k < scene.samplers.size() && k < results.size(); ++k)
            if (scene.samplers[k].name == a.name) {
                results[k].annualInRange = annualMetrics(a, series).inRange;
                results[k].annualHours = int(series.hours.size());
            }
}

}  // namespace luxplan
