// The à-trous passes of denoise.h.
#include <luxplan/output/denoise.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace luxplan {

void denoiseLuminance(std::vector<double>& luminance, std::vector<double> variance, const GuideBuffer& guide,
                      const Vec3& cameraPosition, const DenoiseOptions& options) {
    const int w = guide.width, h = guide.height;
    const size_t n = size_t(w) * size_t(h);
    if (luminance.size() != n || variance.size() != n || guide.position.size() != n || guide.normal.size() != n ||
        guide.surface.size() != n)
        throw std::invalid_argument("denoiseLuminance: image, variance and guide sizes differ");
    constexpr double kKernel[5] = {1.0 / 16, 1.0 / 4, 3.0 / 8, 1.0 / 4, 1.0 / 16};
    std::vector<double> distance(n);
    for (size_t i = 0; i < n; ++i) distance[i] = length(guide.position[i] - cameraPosition);

    std::vector<double> nextL(n), nextVar(n), blurred(n);
    for (int pass = 0, step = 1; pass < options.passes; ++pass, step *= 2) {
        // The luminance weight uses a 3 x 3 blur of the variance, steadier than one pixel's.
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                double sum = 0, count = 0;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        int qx = x + dx, qy = y + dy;
                        if (qx < 0 || qy < 0 || qx >= w || qy >= h) continue;
                        sum += variance[size_t(qy) * w + qx], count += 1;
                    }
                blurred[size_t(y) * w + x] = sum / count;
            }
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const size_t p = size_t(y) * w + x;
                nextL[p] = luminance[p], nextVar[p] = variance[p];
                if (guide.surface[p] < 0) continue;
                const Vec3& np = guide.normal[p];
                const Vec3& pp = guide.position[p];
                const double planeScale = options.planeTolerance * std::max(distance[p], 1e-3) * step;
                const double lumScale = options.luminanceSigma * std::sqrt(std::max(0.0, blurred[p])) + 1e-12;
                double sumW = 0, sumL = 0, sumVar = 0;
                for (int dy = -2; dy <= 2; ++dy)
                    for (int dx = -2; dx <= 2; ++dx) {
                        int qx = x + dx * step, qy = y + dy * step;
                        if (qx < 0 || qy < 0 || qx >= w || qy >= h) continue;
                        const size_t q = size_t(qy) * w + qx;
                        if (guide.surface[q] != guide.surface[p]) continue;
                        double wn = std::pow(std::max(0.0, dot(np, guide.normal[q])), options.normalPower);
                        double wp = std::exp(-std::abs(dot(np, guide.position[q] - pp)) / planeScale);
                        double wl = std::exp(-std::abs(luminance[q] - luminance[p]) / lumScale);
                        double weight = kKernel[dx + 2] * kKernel[dy + 2] * wn * wp * wl;
                        sumW += weight, sumL += weight * luminance[q], sumVar += weight * weight * variance[q];
                    }
                if (sumW > 0) nextL[p] = sumL / sumW, nextVar[p] = sumVar / (sumW * sumW);
            }
        luminance.swap(nextL);
        variance.swap(nextVar);
    }
}

}  // namespace luxplan
