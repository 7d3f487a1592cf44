// Statistics of a sampler's measured points as EN 12464-1 states its lighting
// requirements: the mean (Em), the minimum (Emin), the maximum (Emax) and the
// uniformity U0 = Emin / Em, each with a standard error from the points' own.
// Formulas and sources: docs/light-transport.md#statistics-over-the-points.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include <luxplan/core/names.h>

namespace luxplan {

// What a lighting goal is on: a sampler's value (Mean), a statistic over its points, or
// (AnnualInRange, no statistic of the points) the share of a year's hours whose value
// lies in its target (LightSamplerSpec::annual).
enum class Statistic { Mean, Min, Max, U0, AnnualInRange };

// The names measure --json and the scene file use.
inline const EnumNames<Statistic>& statisticNames() {
    static const EnumNames<Statistic> names{{{Statistic::Mean, "mean"},
                                             {Statistic::Min, "min"},
                                             {Statistic::Max, "max"},
                                             {Statistic::U0, "u0"},
                                             {Statistic::AnnualInRange, "annual_in_range"}}};
    return names;
}

struct StatisticEstimate {
    double value = 0;
    double standardError = 0;
};

struct PointStatistics {
    StatisticEstimate mean, min, max, u0;
    const StatisticEstimate& of(Statistic s) const {
        switch (s) {
            case Statistic::Mean: return mean;
            case Statistic::Min: return min;
            case Statistic::Max: return max;
            case Statistic::U0: return u0;
            case Statistic::AnnualInRange: break;  // no statistic of the points
        }
        return mean;
    }
};

// `values[i]` and `errors[i]`: point i's estimate and standard error, points
// estimated independently of each other (planar and volume samplers). The mean sums
// in point order, as PlacedSampler::combine does, so it equals the sampler's value.
// min and max carry the error of the point that attains them (an approximation: the
// min of noisy points is biased low by up to a few of their errors when several points
// are near the minimum). U0's error is the delta method's, with the covariance of the
// min point and the mean (its variance over n). An unlit set (mean <= 0) has U0 = 0.
// No points: all zero. NaN values (covered points) are left out.
inline PointStatistics pointStatistics(const std::vector<double>& values, const std::vector<double>& errors) {
    PointStatistics s;
    auto error = [&](size_t i) { return i < errors.size() ? errors[i] : 0.0; };
    // A NaN is a point covered by furniture (SamplerResult::covered): not on the task.
    size_t n = 0, lo = 0, hi = 0;
    double sum = 0, variance = 0;
    for (size_t i = 0; i < values.size(); ++i) {
        if (std::isnan(values[i])) continue;
        if (n == 0) lo = hi = i;
        ++n;
        sum += values[i], variance += error(i) * error(i);
        if (values[i] < values[lo]) lo = i;
        if (values[i] > values[hi]) hi = i;
    }
    if (n == 0) return s;
    s.mean = {sum / double(n), std::sqrt(variance) / double(n)};
    s.min = {values[lo], error(lo)};
    s.max = {values[hi], error(hi)};
    if (s.mean.value > 0) {
        const double m = s.mean.value, u = s.min.value / m, sMin = s.min.standardError, sMean = s.mean.standardError;
        // Var(min/m) ~ (sMin^2 - 2 u Cov(min, m) + u^2 sMean^2) / m^2, Cov(min, m) = sMin^2 / n.
        const double v = (sMin * sMin * (1 - 2 * u / double(n)) + u * u * sMean * sMean) / (m * m);
        s.u0 = {u, std::sqrt(std::max(0.0, v))};
    }
    return s;
}

}  // namespace luxplan
