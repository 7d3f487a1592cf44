// The illuminance a uniform Lambertian rectangle gives a point on a parallel plane:
// the classic configuration factor, for the analytic tests.
#pragma once

#include <cmath>

namespace luxplan::test {

// At a point at height h below one corner of an a x b rectangle of luminance L:
// E = L/2 [X/sqrt(1+X^2) atan(Y/sqrt(1+X^2)) + Y/sqrt(1+Y^2) atan(X/sqrt(1+Y^2))],
// X = a/h, Y = b/h.
inline double cornerIlluminance(double L, double a, double b, double h) {
    const double X = a / h, Y = b / h;
    return L / 2 *
           (X / std::sqrt(1 + X * X) * std::atan(Y / std::sqrt(1 + X * X)) +
            Y / std::sqrt(1 + Y * Y) * std::atan(X / std::sqrt(1 + Y * Y)));
}
// Any point whose projection falls inside the rectangle [x0,x1] x [y0,y1]: four corners.
// With L = 1, the rectangle's projected solid angle.
inline double rectIlluminance(double L, double x0, double x1, double y0, double y1, double px, double py, double h) {
    return cornerIlluminance(L, px - x0, py - y0, h) + cornerIlluminance(L, x1 - px, py - y0, h) +
           cornerIlluminance(L, px - x0, y1 - py, h) + cornerIlluminance(L, x1 - px, y1 - py, h);
}

}  // namespace luxplan::test
