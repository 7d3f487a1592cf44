// The lighting term of the optimizer office (support/shared_scenes.h: optimizerOffice())
// as a function of the desk's place: E = 600 - 100 x lx against the target [300, 500],
// so the optimizer tests know L without tracing a path.
#pragma once

#include <luxplan/constraints/geometry_cost.h>
#include <luxplan/constraints/penalty.h>
#include <luxplan/optimizer/lighting.h>

namespace luxplan::test {

// Counts its calls, and those for layouts the geometric test rejects.
class DeskLight : public LightingEvaluator {
public:
    explicit DeskLight(const Scene& scene) : scene_(scene) {}
    double evaluate(const Layout&, const std::vector<Transform>& world, LightingBreakdown* out) override {
        ++calls;
        if (GeometryEvaluator(scene_).evaluate(world).rejected) ++rejectedCalls;
        double e = 600 - 100 * world[size_t(scene_.findEntity("workstation.desk"))].t.x;
        if (out) out->samplers = {{e, 0, {e, e}, {0, 0}}};
        return lightingCost(scene_, {e});
    }
    int calls = 0, rejectedCalls = 0;

private:
    const Scene& scene_;
};

}  // namespace luxplan::test
