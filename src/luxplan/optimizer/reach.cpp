#include <luxplan/optimizer/reach.h>

#include <cmath>
#include <optional>
#include <sstream>

#include <luxplan/constraints/penalty.h>
#include <luxplan/core/point_statistics.h>
#include <luxplan/lightsamplers/sampler_type.h>

namespace luxplan {
namespace {

// Two standard errors: an estimate this close to the band may have been in it.
constexpr double kReachZ = 2;

std::string amount(double v, const LightSamplerSpec& s) {
    std::ostringstream out;
    out.precision(v >= 100 ? 0 : 2);
    out << std::fixed << v << " " << s.type->unit();
    return out.str();
}

std::string withError(double v, double standardError, const LightSamplerSpec& s) {
    if (!(standardError > 0)) return amount(v, s);
    std::ostringstream out;
    out.precision(std::abs(v) >= 100 ? 1 : 2);
    out << std::fixed << v << " ± " << standardError << " " << s.type->unit();
    return out.str();
}

}  // namespace

void SamplerRange::add(const LightSamplerSpec& sampler, double value, double standardError) {
    ++layouts;
    met += value >= sampler.targetMin && value <= sampler.targetMax;
    if (value < lowest) lowest = value, lowestError = standardError;
    if (value > highest) highest = value, highestError = standardError;
}

const char* reachName(Reach reach) {
    switch (reach) {
        case Reach::Met: return "met";
        case Reach::WithinNoise: return "within_noise";
        case Reach::GoalMissed: return "goal_missed";
        case Reach::Reached: return "reached";
        case Reach::NeverMet: return "never_met";
        case Reach::OutOfReach: return "out_of_reach";
        case Reach::NotMeasured: return "not_measured";
    }
    return "?";
}

ReachVerdict reachVerdict(const LightSamplerSpec& s, const SamplerRange& range, double value, double standardError) {
    if (value >= s.targetMin && value <= s.targetMax) return {Reach::Met, ""};
    if (std::isfinite(value) && standardError > 0) {
        const bool low = value < s.targetMin;
        const double bound = low ? s.targetMin : s.targetMax;
        if (std::abs(value - bound) <= standardError)
            return {Reach::WithinNoise, "at the target's " + std::string(low ? "minimum" : "maximum") +
                                            " within its noise (" + withError(value, standardError, s) + " against " +
                                            amount(bound, s) + "): met or missed by less than one standard error; "
                                            "a measurement with more paths decides"};
    }
    const std::string over = range.layouts == 1 ? " in the one layout the search measured"
                                                 : " over the " + std::to_string(range.layouts) + " layouts the search measured";
    // Wider regions help only where there are regions: a scene may move nothing.
    const std::string widen = range.layouts == 1 ? "" : ", or widen the regions";
    if (range.layouts == 0)
        return {Reach::NotMeasured, "the search measured no layout's light (lighting weight 0, or no layout passed the "
                                    "geometric rules)"};
    const bool belowEverywhere = range.highest + kReachZ * range.highestError < s.targetMin;
    const bool aboveEverywhere = range.lowest - kReachZ * range.lowestError > s.targetMax;
    if (belowEverywhere)
        return {Reach::OutOfReach, "at most " + amount(range.highest, s) + over + ", below the target's minimum of " +
                                       amount(s.targetMin, s) +
                                       ": nowhere the search tried gets enough light; add or move light" + widen};
    if (aboveEverywhere)
        return {Reach::OutOfReach, "at least " + amount(range.lowest, s) + over + ", above the target's maximum of " +
                                       amount(s.targetMax, s) +
                                       ": everywhere the search tried gets too much light (daylight or luminaires); "
                                       "shade or dim it" + widen};
    const std::string seen = "it read " + amount(range.lowest, s) + " to " + amount(range.highest, s);
    if (range.met == range.layouts)
        return {Reach::Reached, "met in all " + std::to_string(range.layouts) +
                                    " layouts the search measured (" + seen + "), but not in the result's own measurement (" +
                                    withError(value, standardError, s) +
                                    "): the search's estimates read it inside its band; a wider optimizer.margin or more "
                                    "optimizer.paths_per_point keeps it inside"};
    if (range.met > 0)
        return {Reach::Reached, "met in " + std::to_string(range.met) + " of the " + std::to_string(range.layouts) +
                                    " layouts the search measured (" + seen + "): a trade-off, or a longer search"};
    return {Reach::NeverMet, "met in none of the " + std::to_string(range.layouts) +
                                 " layouts the search measured, though some came within their noise (" + seen + ")"};
}

ReachVerdict reachVerdict(const LightSamplerSpec& s, const SamplerRange& range, const SamplerResult& result) {
    ReachVerdict verdict = reachVerdict(s, range, result.value, result.standardError);
    if (verdict.reach != Reach::Met || s.statistics.empty()) return verdict;
    std::optional<ReachVerdict> withinNoise;
    for (const LightingTerm& t : lightingTerms(s, result)) {
        if (t.statistic == Statistic::Mean || t.penalty == 0) continue;
        const double past = t.value < t.targetMin ? t.targetMin - t.value : t.value - t.targetMax;
        std::ostringstream out;
        out.precision(3);
        if (t.standardError > 0 && past <= t.standardError) {
            out << "its value meets the target, and its " << statisticNames().name(t.statistic)
                << " goal is at its bound within noise: " << t.value << " ± " << t.standardError << " against ["
                << t.targetMin << ", " << t.targetMax << "]";
            if (!withinNoise) withinNoise = ReachVerdict{Reach::WithinNoise, out.str()};
            continue;
        }
        out << "its value meets the target, but its " << statisticNames().name(t.statistic) << " goal does not: " << t.value
            << " against [" << t.targetMin << ", " << t.targetMax << "]";
        return {Reach::GoalMissed, out.str()};
    }
    return withinNoise ? *withinNoise : verdict;
}

}  // namespace luxplan
