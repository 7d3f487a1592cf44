// Parametric furniture presets built from boxes. Every preset fills the box
// [-w/2, w/2] x [-d/2, d/2] x [0, h] of its size and faces -y (its default front):
// a chair's seat opens to -y, a monitor's screen looks to -y.
#pragma once

#include <map>
#include <string>
#include <string_view>
#include <vector>

#include <luxplan/core/math.h>
#include <luxplan/scene/mesh.h>

namespace luxplan {

struct PresetInfo {
    std::string name;
    Vec3 defaultSize;                // w (x), d (y), h (z) in metres
    std::vector<std::string> slots;  // material slots; the first is the body
    std::string description;
};

const std::vector<PresetInfo>& presetCatalog();
const PresetInfo* findPreset(std::string_view name);

// Builds a preset of the given size; `slotMaterials` gives the material of each slot
// (a slot missing from the map takes the body's material).
TriangleMesh buildPreset(const PresetInfo& preset, const Vec3& size, const std::map<std::string, uint32_t>& slotMaterials);

}  // namespace luxplan
