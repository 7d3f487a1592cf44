// A maintenance factor below what any EN 12464-1 maintenance schedule gives.
#include <luxplan/checks/scene_warnings.h>

#include <luxplan/json/fields.h>

namespace luxplan {

std::vector<Diagnostic> lowMaintenanceFactor(const Scene& scene) {
    if (!(scene.maintenanceFactor < kLowestUsualMaintenanceFactor)) return {};
    return {{scene.file.string(), "/maintenance_factor",
             "maintenance factor " + json::formatNumber(scene.maintenanceFactor) +
                 " leaves the luminaires less than half their light as new, darker than EN 12464-1's maintenance "
                 "schedules leave a room (about 0.5 to 0.9; 0.8 for a clean room): was the share lost (1 - factor) meant?"}};
}

}  // namespace luxplan
