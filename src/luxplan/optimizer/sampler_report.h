// One measured light sampler as every output shows it: measure's table and JSON,
// report.json, report.html and the plan all read its row. The row holds the terms
// of Eq. 3 it adds (its value's and its statistics goals'), the statistics of its
// points (EN 12464-1's Em, Emin, Emax, U0) and gives its value, error and target in
// its type's format (SamplerType::valueFormat), its details as JSON and as text.
// docs/outputs.md lists the JSON keys.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <luxplan/constraints/penalty.h>
#include <luxplan/core/point_statistics.h>
#include <luxplan/lightsamplers/sampler_type.h>

namespace luxplan {

class SamplerRow {
public:
    // Throws as lightingTerms does (a non-finite value, goals without points).
    SamplerRow(const LightSamplerSpec& sampler, const SamplerResult& result);

    const LightSamplerSpec& sampler() const { return sampler_; }
    const SamplerResult& result() const { return result_; }
    const ValueFormat& format() const { return format_; }
    // Its value's term first, then one per statistics goal.
    const std::vector<LightingTerm>& terms() const { return terms_; }
    double penalty() const { return terms_.front().penalty; }
    bool met() const { return allMet(terms_); }
    // Over its points, for a type with point statistics.
    const std::optional<PointStatistics>& statistics() const { return statistics_; }

    // Its value with `decimals` decimals, "<10" below its type's floor; with the type's
    // digits by default.
    std::string valueText(int decimals) const { return format_.text(result_.value, decimals); }
    std::string valueText() const { return valueText(format_.digits); }
    // Its standard error with the type's digits; "n/a" from fewer than 2 paths per point.
    std::string errorText() const;
    // Its target as measure shows it: "[300, 500]", "[0, inf]".
    std::string targetText() const;

    // {"grid": [nx, ny] (planar), "stats": {"mean", "min", "max", "u0"} and
    // "stats_std_error" (planar, volume), "terms": [{"statistic", "value", "std_error",
    // "target", "tolerance", "penalty"}], then the type's details (SamplerType::addDetails:
    // a glare eye's "glare")}; an open target end is null.
    nlohmann::ordered_json detailsJson() const;
    // One line: the type's details ("UGR 13.2, Lb 31.0 cd/m2, 1 source; ..."), else
    // "Em 512.3 lx, Emin 301.2, Emax 700.1, U0 0.59, 9 x 7 grid" (a luminance's L for
    // cd/m2); "" for a type with neither.
    std::string detailsText() const;

private:
    const LightSamplerSpec& sampler_;
    const SamplerResult& result_;
    ValueFormat format_;
    std::vector<LightingTerm> terms_;
    std::optional<PointStatistics> statistics_;
};

// A target band as measure shows it: "[300, 500]", "[0, inf]" (shortest %g form).
std::string targetBandText(double lo, double hi);

}  // namespace luxplan
