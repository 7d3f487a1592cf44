#include <luxplan/optimizer/sampler_report.h>

#include <cmath>
#include <string_view>

#include <luxplan/core/format.h>
#include <luxplan/json/fields.h>

namespace luxplan {

using Json = nlohmann::ordered_json;

SamplerRow::SamplerRow(const LightSamplerSpec& sampler, const SamplerResult& result)
    : sampler_(sampler), result_(result), format_(sampler.type->valueFormat()), terms_(lightingTerms(sampler, result)) {
    if (sampler.type->hasPointStatistics()) statistics_ = pointStatistics(result.points, result.pointErrors);
}

std::string SamplerRow::errorText() const {
    return result_.pathsPerPoint < 2 ? "n/a" : fixedDigits(result_.standardError, format_.digits);
}

std::string SamplerRow::targetText() const { return targetBandText(sampler_.targetMin, sampler_.targetMax); }

std::string targetBandText(double lo, double hi) {
    return "[" + significantDigits(lo, 6) + ", " + (std::isfinite(hi) ? significantDigits(hi, 6) : "inf") + "]";
}

Json SamplerRow::detailsJson() const {
    Json j = Json::object();
    if (auto grid = sampler_.type->pointGrid()) j["grid"] = {(*grid)[0], (*grid)[1]};
    if (statistics_) {
        Json values = Json::object(), errors = Json::object();
        for (Statistic s : {Statistic::Mean, Statistic::Min, Statistic::Max, Statistic::U0}) {
            values[statisticNames().name(s)] = statistics_->of(s).value;
            errors[statisticNames().name(s)] = statistics_->of(s).standardError;
        }
        j["stats"] = values;
        j["stats_std_error"] = errors;
    }
    Json terms = Json::array();
    for (const LightingTerm& t : terms_)
        terms.push_back({{"statistic", statisticNames().name(t.statistic)},
                         {"value", t.value},
                         {"std_error", t.standardError},
                         {"target", {json::numberOrNull(t.targetMin), json::numberOrNull(t.targetMax)}},
                         {"tolerance", t.tolerance},
                         {"penalty", t.penalty}});
    j["terms"] = terms;
    sampler_.type->addDetails(result_, j);
    return j;
}

std::string SamplerRow::detailsText() const {
    if (std::string details = sampler_.type->detailsText(result_); !details.empty()) return details;
    if (!statistics_) return "";
    const PointStatistics& s = *statistics_;
    const std::string unit = sampler_.type->unit();
    const std::string q = unit == "lx" ? "E" : "L";
    std::string d = q + "m " + fixedDigits(s.mean.value, 1) + " " + unit + ", " + q + "min " + fixedDigits(s.min.value, 1) +
                    ", " + q + "max " + fixedDigits(s.max.value, 1) + ", U0 " + fixedDigits(s.u0.value, 2);
    if (auto grid = sampler_.type->pointGrid()) d += ", " + std::to_string((*grid)[0]) + " x " + std::to_string((*grid)[1]) + " grid";
    return d;
}

}  // namespace luxplan
