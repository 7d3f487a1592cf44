// Marching squares: each square of four samples is classified by which corners lie at
// or above the level, and the crossing points on its edges are joined.
#include <luxplan/output/contours.h>

namespace luxplan {

std::vector<ContourSegment> isolines(const std::vector<double>& values, int nx, int ny, double level,
                                     const std::vector<char>& valid) {
    std::vector<ContourSegment> out;
    if (nx < 2 || ny < 2 || values.size() < size_t(nx) * size_t(ny)) return out;
    auto at = [&](int i, int j) { return values[size_t(j) * size_t(nx) + size_t(i)]; };
    auto ok = [&](int i, int j) { return valid.empty() || valid[size_t(j) * size_t(nx) + size_t(i)]; };
    for (int j = 0; j + 1 < ny; ++j)
        for (int i = 0; i + 1 < nx; ++i) {
            if (!ok(i, j) || !ok(i + 1, j) || !ok(i + 1, j + 1) || !ok(i, j + 1)) continue;
            // Corners counter-clockwise from (i, j); edges k joins corner k and k + 1.
            const Vec2 corner[4] = {{double(i), double(j)}, {i + 1.0, double(j)}, {i + 1.0, j + 1.0}, {double(i), j + 1.0}};
            const double v[4] = {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)};
            bool finite = true;
            for (double x : v) finite = finite && std::isfinite(x);
            if (!finite) continue;
            int code = 0;
            for (int k = 0; k < 4; ++k)
                if (v[k] >= level) code |= 1 << k;
            if (code == 0 || code == 15) continue;
            auto cross = [&](int k) {
                int l = (k + 1) % 4;
                double t = (level - v[k]) / (v[l] - v[k]);
                return corner[k] + (corner[l] - corner[k]) * std::clamp(t, 0.0, 1.0);
            };
            // The edges the level crosses, in order round the square.
            int edges[4], n = 0;
            for (int k = 0; k < 4; ++k)
                if (((code >> k) & 1) != ((code >> ((k + 1) % 4)) & 1)) edges[n++] = k;
            if (n == 2) {
                out.push_back({cross(edges[0]), cross(edges[1])});
                continue;
            }
            // A saddle (codes 5 and 10): four crossings. If the centre is on the side of
            // corner 0, corner 0's region connects through the centre and the
            // segments cut off corners 1 and 3; otherwise they cut off corners 0 and 2.
            const double centre = (v[0] + v[1] + v[2] + v[3]) / 4;
            const bool centreHigh = centre >= level, zeroHigh = (code & 1) != 0;
            if (centreHigh == zeroHigh) {
                out.push_back({cross(0), cross(1)});  // around corner 1
                out.push_back({cross(2), cross(3)});  // around corner 3
            } else {
                out.push_back({cross(3), cross(0)});  // around corner 0
                out.push_back({cross(1), cross(2)});  // around corner 2
            }
        }
    return out;
}

}  // namespace luxplan
