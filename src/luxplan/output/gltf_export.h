// The scene under one layout as a binary glTF 2.0 file (.glb) for Blender and other
// viewers: room, static geometry, furniture, emitters as emissive meshes and as
// KHR_lights_punctual lights, one PBR material per scene material.
#pragma once

#include <filesystem>

#include <luxplan/scene/layout.h>

namespace luxplan {

// Linear RGB of a black body at `kelvin` (clamped to [1667, 25000] K), scaled so that
// its largest component is 1: the colour that `cct_k` gives lights in images.
Vec3 blackBodyRgb(double kelvin);

// Writes `file` (glTF is y-up: luxplan's (x, y, z) becomes (x, z, -y)). Nodes, named
// after what they show: one per visible static item (world frame), one per entity with
// parts (its mesh in its own frame, the node placing it by worldTransforms) and one
// per emitter (an emissive rect, disk or sphere carrying a point light for a sphere, a
// spot light along the normal for a rect or disk, intensity in candela). Invisible
// blockers are left out. Each scene camera is a perspective camera node of its name.
// Throws IoError when the file cannot be written.
void writeGlb(const std::filesystem::path& file, const Scene& scene, const Layout& layout);

}  // namespace luxplan
