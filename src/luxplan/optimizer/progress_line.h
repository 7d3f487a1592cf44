// The optimizer's progress in words, for a person watching the run: where it is,
// what the cost is made of, how often each kind of move is taken, and how long is
// left. `optimize` prints it; tests read it.
#pragma once

#include <string>

#include <luxplan/optimizer/optimizer.h>

namespace luxplan {

// "iteration 1400 of 3000 | cost 0.0161, best 0.0149 | accepted: translate 52%,
// rotate 74% | 37s, about 42s left". Before any layout keeps every rule within its
// rejection limit the cost is the rules' alone, and the line says so ("arranging").
std::string progressLine(const Progress& p);

// The one-off line when the search first holds such a layout: the
// cost then starts to include the light, so it may rise.
std::string lightingStartsLine(const Progress& p);

// 42s, 3m05s, 1h02m.
std::string durationText(double seconds);

// A measurement of more paths than this (points x paths per point) runs for minutes:
// measure and optimize warn before it, and measure reports its progress.
inline constexpr double kLargeMeasurementPaths = 2e7;

// "warning: measuring 1000000 points (100 samplers) x 1000 paths per point = 1e+09
// paths, more than 2e+07: it may run for minutes (fewer paths or points take less)",
// `what` ("measuring", "the search measures each layout at") leading; "" when the
// paths are at most kLargeMeasurementPaths.
std::string largeMeasurementWarning(const std::string& what, long long points, int samplers, long long pathsPerPoint);

// "measuring: 37% of 1e+09 paths (1m02s, about 1m45s left)"; `atMost`: an adaptive
// measurement, whose samplers may stop early ("of at most 1e+09 paths").
std::string measureProgressLine(unsigned long long done, unsigned long long total, double seconds, bool atMost = false);

}  // namespace luxplan
