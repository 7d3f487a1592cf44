// A closed 4 x 3 x 2.5 m grey room lit by a 1 cm bulb, with a planar sampler over each
// of its six faces: every lumen is absorbed after 1 / (1 - rho) reflections on average,
// so the area-weighted mean illuminance is flux / (A (1 - rho)) whatever the estimator
// does with the paths (the roulettes' tests).
#pragma once

#include <cmath>

#include <luxplan/emitters/emitter_shape.h>
#include <luxplan/lightsamplers/light_samplers.h>
#include "support/scene_builder.h"

namespace luxplan::test {

struct ClosedGreyRoom {
    static constexpr double kArea = 2 * (4 * 3 + 4 * 2.5 + 3 * 2.5);  // m2
    static constexpr double kFaceAreas[6] = {12, 12, 10, 10, 7.5, 7.5};
    Scene scene;
    double expected = 0;  // lx: flux / (A (1 - rho))

    // Each face's band starts at `targetMin` lx.
    ClosedGreyRoom(double rho, double flux, double targetMin = 0) : expected(flux / (kArea * (1 - rho))) {
        scene = SceneBuilder()
                    .material("grey", diffuse(rho))
                    .room({0, 0, 0}, {4, 3, 2.5}, "grey", "grey", "grey")
                    .emitter("bulb", sphereEmitter({2.1, 1.4, 1.3}, 0.01), flux)
                    .sampler("floor", planarSampler({2, 1.5, 0.001}, {0, 0, 1}, {0, 1, 0}, {4, 3}, {4, 3}), targetMin, 1e9)
                    .sampler("ceiling", planarSampler({2, 1.5, 2.499}, {0, 0, -1}, {0, 1, 0}, {4, 3}, {4, 3}), targetMin, 1e9)
                    .sampler("south", planarSampler({2, 0.001, 1.25}, {0, 1, 0}, {0, 0, 1}, {4, 2.5}, {4, 3}), targetMin, 1e9)
                    .sampler("north", planarSampler({2, 2.999, 1.25}, {0, -1, 0}, {0, 0, 1}, {4, 2.5}, {4, 3}), targetMin, 1e9)
                    .sampler("west", planarSampler({0.001, 1.5, 1.25}, {1, 0, 0}, {0, 0, 1}, {3, 2.5}, {3, 3}), targetMin, 1e9)
                    .sampler("east", planarSampler({3.999, 1.5, 1.25}, {-1, 0, 0}, {0, 0, 1}, {3, 2.5}, {3, 3}), targetMin, 1e9)
                    .build();
    }

    // The six faces' area-weighted mean of a measurement, and its standard error.
    struct Mean {
        double value = 0, standardError = 0;
    };
    static Mean mean(const MeasureResult& r) {
        Mean m;
        double variance = 0;
        for (int k = 0; k < 6; ++k) {
            m.value += kFaceAreas[k] * r.samplers[size_t(k)].value / kArea;
            variance += std::pow(kFaceAreas[k] / kArea * r.samplers[size_t(k)].standardError, 2);
        }
        m.standardError = std::sqrt(variance);
        return m;
    }
};

}  // namespace luxplan::test
