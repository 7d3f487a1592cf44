// A light sampler's measurement as measure --json and report.json give it besides its
// value: the terms of Eq. 3 it adds (its value's and its statistics goals'), the
// statistics of its points (EN 12464-1's Em, Emin, Emax, U0) and its grid; and the
// same as one line of text for measure's table. docs/outputs.md lists the keys.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include <luxplan/constraints/penalty.h>

namespace luxplan {

// {"grid": [nx, ny] (planar), "stats": {"mean", "min", "max", "u0"} and
// "stats_std_error" (planar, volume), "terms": [{"statistic", "value", "std_error",
// "target", "tolerance", "penalty"}]}; an open target end is null.
nlohmann::ordered_json samplerStatisticsJson(const LightSamplerSpec& sampler, const SamplerResult& result);

// "Em 512.3 lx, Emin 301.2, Emax 700.1, U0 0.59, 9 x 7 grid" (a luminance's L for
// cd/m2); "" for a type without point statistics.
std::string describeStatistics(const LightSamplerSpec& sampler, const SamplerResult& result);

}  // namespace luxplan
