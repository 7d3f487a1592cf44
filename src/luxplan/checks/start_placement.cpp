// Scene placements that pass a hard limit (a wall, a static item, a blocker, a
// footprint bound).
#include <luxplan/checks/scene_warnings.h>

#include <luxplan/constraints/geometry_cost.h>
#include <luxplan/scene/layout.h>

namespace luxplan {

std::vector<Diagnostic> startPlacement(const Scene& scene) {
    std::vector<Diagnostic> out;
    GeometryEvaluator geometry(scene);
    const GeometryResult r = geometry.evaluate(worldTransforms(scene, initialLayout(scene)), /* breakdown = */ true);
    auto warn = [&](int entity, const std::string& what) {
        out.push_back({scene.file.string(), scene.entities[size_t(entity)].jsonPath,
                       "the scene places \"" + scene.entities[size_t(entity)].path + "\" past a hard limit: " + what});
    };
    for (const PenaltyTerm& t : r.terms)
        if (t.hardOverlap() && t.rejects) warn(t.a, describe(scene, t));
    for (const FootprintTerm& f : r.footprints) warn(f.entity, describe(scene, f));
    return out;
}

}  // namespace luxplan
