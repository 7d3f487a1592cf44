#include <luxplan/checks/scene_warnings.h>

#include <cstdio>

#include <luxplan/lightsamplers/sampler_type.h>

namespace luxplan {

std::vector<Vec3> measurementPoints(const LightSamplerSpec& sampler, const Transform& frame) {
    SamplerDrawing d = sampler.type->place(frame)->drawing();
    return d.dots.empty() ? d.outline : d.dots;
}

std::string pointText(const Vec3& p) {
    char buffer[96];
    std::snprintf(buffer, sizeof buffer, "(%.3g, %.3g, %.3g)", p.x, p.y, p.z);
    return buffer;
}

std::vector<Diagnostic> sceneWarnings(const Scene& scene) {
    std::vector<Diagnostic> all;
    for (auto check : {lowMaintenanceFactor, enclosedEmitters, outsideTheRoom, sealedSamplers, darkDaylight, startPlacement})
        for (Diagnostic& d : check(scene)) all.push_back(std::move(d));
    return all;
}

}  // namespace luxplan
