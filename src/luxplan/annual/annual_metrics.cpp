// Annual metrics: counts over hours and points, with the thresholds' inclusivity of
// LM-83 and UDI (annual_metrics.h says which).
#include <luxplan/annual/annual_metrics.h>

#include <cmath>
#include <cstdio>
#include <limits>

#include <nlohmann/json.hpp>

#include <luxplan/core/format.h>

namespace luxplan {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

bool inBand(double v, double lo, double hi) { return std::isfinite(v) && v >= lo && v <= hi; }

nlohmann::json annualNumber(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

nlohmann::json annualNumbers(const std::vector<double>& values) {
    nlohmann::json out = nlohmann::json::array();
    for (double v : values) out.push_back(annualNumber(v));
    return out;
}

}  // namespace

AnnualMetrics annualMetrics(const AnnualSampler& s, size_t hourCount) {
    AnnualMetrics m;
    const size_t n = std::min(hourCount, s.values.size());
    m.hours = int(n);
    double sum = 0;
    int inRange = 0;
    for (size_t h = 0; h < n; ++h) {
        sum += s.values[h];
        inRange += inBand(s.values[h], s.targetMin, s.targetMax);
    }
    m.mean = n > 0 ? sum / double(n) : kNaN;
    m.inRange = n > 0 ? double(inRange) / double(n) : kNaN;

    m.planar = s.planar;
    if (!s.planar) {
        m.sda = m.ase = kNaN;
        m.udi = {kNaN, kNaN, kNaN};
        return m;
    }
    // Direct-sun values for ASE: one row per point, as `points`.
    const bool hasSun = s.directSun.size() == s.points.size();
    int sdaPass = 0, aseFail = 0;
    long long below = 0, useful = 0, above = 0, pointHours = 0;
    m.pointsInRange.assign(s.points.size(), kNaN);
    for (size_t p = 0; p < s.points.size(); ++p) {
        const std::vector<double>& row = s.points[p];
        if (row.empty()) continue;  // covered by furniture: no analysis point
        ++m.points;
        const size_t hours = std::min(n, row.size());
        int lit = 0, pointInRange = 0;
        for (size_t h = 0; h < hours; ++h) {
            const double v = row[h];
            lit += v >= kSdaIlluminance;
            pointInRange += inBand(v, s.targetMin, s.targetMax);
            if (!std::isfinite(v)) continue;
            below += v < kUdiLow;
            above += v > kUdiHigh;
            useful += v >= kUdiLow && v <= kUdiHigh;
            ++pointHours;
        }
        // "At least 50%" of the hours, compared in whole hours: lit / n >= 0.5.
        sdaPass += n > 0 && double(lit) >= kSdaTimeShare * double(n);
        m.pointsInRange[p] = n > 0 ? double(pointInRange) / double(n) : kNaN;
        if (hasSun) {
            int sunny = 0;
            for (size_t h = 0; h < std::min(n, s.directSun[p].size()); ++h) sunny += s.directSun[p][h] > kAseIlluminance;
            aseFail += sunny > kAseHours;
        }
    }
    const bool any = m.points > 0 && n > 0;
    m.sda = any ? double(sdaPass) / m.points : kNaN;
    m.ase = any && hasSun ? double(aseFail) / m.points : kNaN;
    if (pointHours > 0)
        m.udi = {double(below) / double(pointHours), double(useful) / double(pointHours), double(above) / double(pointHours)};
    else
        m.udi = {kNaN, kNaN, kNaN};
    return m;
}

void addAnnualJson(nlohmann::json& measureJson, const AnnualSeries& series) {
    nlohmann::json hours = nlohmann::json::array();
    for (const DateTime& t : series.hours) hours.push_back(t.str());
    measureJson["hours"] = std::move(hours);
    if (!measureJson.contains("samplers") || !measureJson["samplers"].is_array())
        measureJson["samplers"] = nlohmann::json::array();
    nlohmann::json& samplers = measureJson["samplers"];
    for (const AnnualSampler& s : series.samplers) {
        const AnnualMetrics m = annualMetrics(s, series);
        nlohmann::json annual = {{"hours", m.hours},
                                 {"mean", annualNumber(m.mean)},
                                 {"in_range", annualNumber(m.inRange)},
                                 {"values", annualNumbers(std::vector<double>(s.values.begin(), s.values.begin() + m.hours))}};
        nlohmann::json* object = nullptr;
        for (nlohmann::json& o : samplers)
            if (o.is_object() && o.contains("name") && o["name"] == s.name) {
                object = &o;
                break;
            }
        if (!object) {
            samplers.push_back({{"name", s.name}, {"type", s.type}});
            object = &samplers.back();
        }
        if (m.planar) {
            const nlohmann::json udi = {annualNumber(m.udi[0]), annualNumber(m.udi[1]), annualNumber(m.udi[2])};
            annual["sda"] = annualNumber(m.sda);
            annual["ase"] = annualNumber(m.ase);
            annual["udi"] = udi;
            annual["points_in_range"] = annualNumbers(m.pointsInRange);
            // Each point's hourly values (null for a covered point), as Radiance's and
            // Honeybee's annual results give them.
            nlohmann::json points = nlohmann::json::array();
            for (const std::vector<double>& p : s.points)
                points.push_back(p.empty() ? nlohmann::json(nullptr) : annualNumbers(p));
            annual["point_values"] = points;
            // The contract's "planar samplers add sda, ase, udi" read both ways: inside
            // "annual" and beside it.
            (*object)["sda"] = annual["sda"];
            (*object)["ase"] = annual["ase"];
            (*object)["udi"] = udi;
        }
        (*object)["annual"] = std::move(annual);
    }
}

std::string annualText(const AnnualSeries& series) {
    // A share as a percentage with one decimal, "-" where there is none.
    auto percent = [](double share) { return std::isfinite(share) ? fixedDigits(100 * share, 1) : std::string("-"); };
    auto number = [](double v) { return std::isfinite(v) ? fixedDigits(v, 1) : std::string("-"); };
    std::string out;
    char line[256];
    std::snprintf(line, sizeof line, "%-24s%8s%12s%12s%9s%9s%12s%12s%12s\n", "sampler", "hours", "mean", "in range %", "sDA %",
                  "ASE %", "UDI <100 %", "100-3000 %", ">3000 %");
    out += line;
    for (const AnnualSampler& s : series.samplers) {
        const AnnualMetrics m = annualMetrics(s, series);
        std::snprintf(line, sizeof line, "%-24s%8d%12s%12s", s.name.c_str(), m.hours, number(m.mean).c_str(),
                      percent(m.inRange).c_str());
        out += line;
        if (m.planar) {
            std::snprintf(line, sizeof line, "%9s%9s%12s%12s%12s", percent(m.sda).c_str(), percent(m.ase).c_str(),
                          percent(m.udi[0]).c_str(), percent(m.udi[1]).c_str(), percent(m.udi[2]).c_str());
            out += line;
        }
        out += "\n";
    }
    out += std::to_string(series.hours.size()) + " hours";
    if (!series.hours.empty()) out += " from " + series.hours.front().str() + " to " + series.hours.back().str();
    out += "\nmean in the sampler's unit (lx for planar samplers); sDA300/50% and ASE1000,250h of IES LM-83-12 over "
           "the uncovered points; UDI: shares of point-hours below 100, in 100-3000, above 3000 lx\n";
    return out;
}

}  // namespace luxplan
