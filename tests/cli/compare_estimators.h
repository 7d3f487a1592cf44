// Two `measure --json` outputs of one scene by two unbiased estimators: the planar
// samplers agree within their errors (the other types' values hold a selection).
#pragma once

#include <cmath>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace luxplan::test {

// The summed variance of `a`'s planar samplers over `b`'s (ADD_FAILUREs where a value
// differs by more than 4 errors, or the sampler lists do not match).
inline double planarVarianceRatio(const nlohmann::json& a, const nlohmann::json& b) {
    if (a["samplers"].size() != b["samplers"].size()) {
        ADD_FAILURE() << "different samplers";
        return NAN;
    }
    double varianceA = 0, varianceB = 0;
    for (size_t k = 0; k < a["samplers"].size(); ++k) {
        const auto &x = a["samplers"][k], &y = b["samplers"][k];
        if (x["type"] != "planar") continue;
        const double ex = x["std_error"], ey = y["std_error"];
        EXPECT_NEAR(double(x["value"]), double(y["value"]), 4 * std::hypot(ex, ey)) << x["name"];
        varianceA += ex * ex, varianceB += ey * ey;
    }
    return varianceA / varianceB;
}

}  // namespace luxplan::test
