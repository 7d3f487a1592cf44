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

}  // namespace luxplan
