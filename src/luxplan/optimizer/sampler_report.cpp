#include <luxplan/optimizer/sampler_report.h>

#include <cmath>
#include <cstdio>
#include <string_view>

#include <luxplan/json/fields.h>
#include <luxplan/lightsamplers/sampler_type.h>

namespace luxplan {
namespace {

using Json = nlohmann::ordered_json;


std::string fixed(double v, int decimals) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", decimals, v);
    return text;
}

}  // namespace

Json samplerStatisticsJson(const LightSamplerSpec& sampler, const SamplerResult& result) {
    Json j = Json::object();
    if (auto grid = sampler.type->pointGrid()) j["grid"] = {(*grid)[0], (*grid)[1]};
    if (sampler.type->hasPointStatistics()) {
        const PointStatistics stats = pointStatistics(result.points, result.pointErrors);
        Json values = Json::object(), errors = Json::object();
        for (Statistic s : {Statistic::Mean, Statistic::Min, Statistic::Max, Statistic::U0}) {
            values[statisticNames().name(s)] = stats.of(s).value;
            errors[statisticNames().name(s)] = stats.of(s).standardError;
        }
        j["stats"] = values;
        j["stats_std_error"] = errors;
    }
    Json terms = Json::array();
    for (const LightingTerm& t : lightingTerms(sampler, result))
        terms.push_back({{"statistic", statisticNames().name(t.statistic)},
                         {"value", t.value},
                         {"std_error", t.standardError},
                         {"target", {json::numberOrNull(t.targetMin), json::numberOrNull(t.targetMax)}},
                         {"tolerance", t.tolerance},
                         {"penalty", t.penalty}});
    j["terms"] = terms;
    if (result.glare) {
        const GlareSurvey& g = *result.glare;
        Json sources = Json::array();
        for (const GlareSource& s : g.sources)
            sources.push_back({{"kind", glareSourceKindName(s.kind)},
                               {s.kind == GlareSource::Kind::Region ? "region" : "slot", s.index},
                               {"direction", {s.direction.x, s.direction.y, s.direction.z}},
                               {"luminance", s.luminance},
                               {"solid_angle", s.solidAngle},
                               {"position_index", s.positionIndex}});
        j["glare"] = {{"vertical_illuminance", g.verticalIlluminance},
                      {"direct_illuminance", g.directIlluminance},
                      {"background_luminance", g.backgroundLuminance},
                      {"sources", sources}};
    }
    return j;
}

std::string describeStatistics(const LightSamplerSpec& sampler, const SamplerResult& result) {
    if (result.glare) {
        const GlareSurvey& g = *result.glare;
        const bool ugr = std::string_view(sampler.type->name()) == "ugr";
        std::string d = ugr ? "UGR " + (result.value < 10 ? std::string("<10") : fixed(result.value, 1)) + ", Lb " +
                                  fixed(g.backgroundLuminance, 1) + " cd/m2"
                            : "DGP " + fixed(result.value, 3) + ", Ev " + fixed(g.verticalIlluminance, 0) + " lx";
        d += ", " + std::to_string(g.sources.size()) + (g.sources.size() == 1 ? " source" : " sources");
        for (const GlareSource& s : g.sources)
            d += std::string("; ") + glareSourceKindName(s.kind) + " [" + fixed(s.direction.x, 2) + " " + fixed(s.direction.y, 2) + " " + fixed(s.direction.z, 2) + "] L " +
                 fixed(s.luminance, 0) + " cd/m2, omega " + fixed(s.solidAngle * 1e3, 3) + " msr, P " + fixed(s.positionIndex, 2);
        return d;
    }
    if (!sampler.type->hasPointStatistics()) return "";
    const PointStatistics s = pointStatistics(result.points, result.pointErrors);
    const std::string q = std::string_view(sampler.type->unit()) == "lx" ? "E" : "L";
    std::string d = q + "m " + fixed(s.mean.value, 1) + " " + sampler.type->unit() + ", " + q + "min " + fixed(s.min.value, 1) +
                    ", " + q + "max " + fixed(s.max.value, 1) + ", U0 " + fixed(s.u0.value, 2);
    if (auto grid = sampler.type->pointGrid()) d += ", " + std::to_string((*grid)[0]) + " x " + std::to_string((*grid)[1]) + " grid";
    return d;
}

}  // namespace luxplan
