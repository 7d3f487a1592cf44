#include <luxplan/checks/scene_warnings.h>

namespace luxplan {

std::vector<Diagnostic> sceneWarnings(const Scene& scene) {
    std::vector<Diagnostic> all;
    for (auto check : {enclosedEmitters, outsideTheRoom, sealedSamplers, darkDaylight, startPlacement})
        for (Diagnostic& d : check(scene)) all.push_back(std::move(d));
    return all;
}

}  // namespace luxplan
