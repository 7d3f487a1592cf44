#include <luxplan/optimizer/progress_line.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <luxplan/core/format.h>

namespace luxplan {
namespace {

// Enough digits to see a cost change near zero, few when it is large.
std::string cost(double c) {
    if (!std::isfinite(c)) return "-";
    return fixedDigits(c, std::abs(c) >= 10 ? 1 : std::abs(c) >= 1 ? 3 : 4);
}

std::string temperatureText(double t) {
    char buf[32];
    std::snprintf(buf, sizeof buf, t >= 0.01 ? "%.3f" : "%.1e", t);
    return buf;
}

}  // namespace

std::string durationText(double seconds) {
    char buf[32];
    long s = std::lround(std::max(0.0, seconds));
    if (s >= 3600) std::snprintf(buf, sizeof buf, "%ldh%02ldm", s / 3600, s / 60 % 60);
    else if (s >= 60) std::snprintf(buf, sizeof buf, "%ldm%02lds", s / 60, s % 60);
    else std::snprintf(buf, sizeof buf, "%lds", s);
    return buf;
}

namespace {

std::string progressPathCount(double paths) { return significantDigits(paths, 3); }

}  // namespace

std::string largeMeasurementWarning(const std::string& what, long long points, int samplers, long long pathsPerPoint) {
    const double paths = double(points) * double(pathsPerPoint);
    if (!(paths > kLargeMeasurementPaths)) return "";
    return "warning: " + what + " " + std::to_string(points) + " points (" + std::to_string(samplers) +
           (samplers == 1 ? " sampler" : " samplers") + ") x " + std::to_string(pathsPerPoint) + " paths per point = " +
           progressPathCount(paths) + " paths, more than " + progressPathCount(kLargeMeasurementPaths) +
           ": it may run for minutes (fewer paths per point or coarser grids take less)";
}

std::string measureProgressLine(unsigned long long done, unsigned long long total, double seconds, bool atMost) {
    const double share = total > 0 ? std::min(1.0, double(done) / double(total)) : 1.0;
    std::string line = "measuring: " + fixedDigits(std::floor(100 * share), 0) + "% of " + (atMost ? "at most " : "") +
                       progressPathCount(double(total)) + " paths (" + durationText(seconds);
    if (done > 0 && share < 1) line += ", about " + durationText(seconds * (1 - share) / share) + " left";
    return line + ")";
}

std::string progressLine(const Progress& p) {
    std::string line = "iteration " + std::to_string(p.iteration) + " of " + std::to_string(p.iterations) + " | ";
    if (!p.feasible) {
        line += "arranging: no layout keeps every rule within its limit yet (rules' cost " + cost(p.current) + ", light not measured)";
    } else {
        line += "cost " + cost(p.current) + ", best " + cost(p.best);
        if (p.lightingMeasured) line += " (light and rules)";
    }
    std::string moves;
    for (MoveType t : kMoveTypes) {
        if (p.proposed[int(t)] == 0) continue;  // a move the scene does not allow
        moves += (moves.empty() ? "" : ", ") + std::string(moveName(t)) + " " + fixedDigits(100 * p.acceptance[int(t)], 0) + "%";
    }
    if (!moves.empty()) line += " | accepted: " + moves;
    if (p.polishing) line += " | polishing the best (zero temperature), " + fixedDigits(100 * p.recentAcceptance, 0) + "% kept lately";
    else line += " | temperature " + temperatureText(p.temperature) + ", " + fixedDigits(100 * p.recentAcceptance, 0) + "% accepted lately";
    line += " | " + durationText(p.seconds);
    if (p.iteration < p.iterations) line += ", about " + durationText(p.etaSeconds) + " left";
    return line;
}

std::string lightingStartsLine(const Progress& p) {
    std::string line = "by iteration " + std::to_string(p.iteration) + ": a layout keeps every rule within its limit";
    if (p.lightingMeasured) line += "; from here the cost includes the light, so it may rise";
    return line;
}

}  // namespace luxplan
