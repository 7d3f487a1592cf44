// A scene's year as daylight coefficients measure it: its annual hours (annualHours)
// and each hour's sky from its daylight (skyLuminanceAt), and what `measure` and the
// search do with it: the annual goals' shares of hours in range.
#pragma once

#include <vector>

#include <luxplan/annual/daylight_coefficients.h>
#include <luxplan/scene/sampler_result.h>

namespace luxplan {

// The coefficients' basis for the scene's daylight. Throws std::runtime_error naming
// what is missing: no daylight, or no occupied hour with the sun up in its period.
DaylightCoefficients sceneYear(const Scene& scene);

// The year's hours at the samplers `which`, where `rt`'s layout puts them: a tracer
// under the year's basis sky on `rt` (DaylightCoefficients::measure).
AnnualSeries measureYearAt(const DaylightCoefficients& year, const EmbreeScene& rt, const std::vector<size_t>& which,
                           int paths, uint64_t seed, const std::function<void(size_t, size_t)>& progress = {});

// The samplers with an annual goal (LightSamplerSpec::annual), in scene order.
std::vector<size_t> annualGoalSamplers(const Scene& scene);

// Sets each measured sampler's SamplerResult::annualInRange and annualHours from the
// series (matched by name): the share of hours whose value lies in its target.
void setAnnualInRange(const Scene& scene, const AnnualSeries& series, std::vector<SamplerResult>& results);

}  // namespace luxplan
