#include <luxplan/core/format.h>

#include <cmath>
#include <cstdio>

namespace luxplan {

std::string fixedDigits(double v, int digits) {
    char buffer[400];  // 1e308 with its digits
    std::snprintf(buffer, sizeof buffer, "%.*f", digits, v);
    return buffer;
}

std::string significantDigits(double v, int digits) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*g", digits, v);
    return buffer;
}

std::string compactNumber(double v) {
    const double a = std::abs(v);
    if (a == 0) return "0";
    if (a >= 10000) return significantDigits(v / 1000, 3) + "k";
    if (a >= 100 || std::abs(v - std::round(v)) < 1e-9 * a) return fixedDigits(v, 0);
    return significantDigits(v, 3);
}

}  // namespace luxplan
