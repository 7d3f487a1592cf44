// The cost of one layout as the optimizer measured it.
#pragma once

#include <string>

#include <luxplan/optimizer/lighting.h>

namespace luxplan {

// The cost of one layout.
struct Evaluation {
    double cost = 0;      // C = w L + (1 - w) G; for a rejected layout (1 - w) G (no lighting)
    double lighting = 0;  // L (0 when not evaluated)
    double geometry = 0;  // G
    bool rejected = false;
    bool lightingEvaluated = false;
    double violation = 0;  // GeometryResult::violation
    double costError = 0;  // the standard error of `cost`: w times that of L (G is exact)
    std::string rejectedBy;
    LightingBreakdown samplers;
};

}  // namespace luxplan
