// layout.json (SCENE-FORMAT.md): {"entities": {"dotted.path": {"position": [x,y,z],
// "rotation": deg, "region": k}}} for every movable entity, in its parent's frame.
#pragma once

#include <filesystem>
#include <string>

#include <luxplan/scene/layout.h>

namespace luxplan::io {

std::string layoutToJson(const Scene& scene, const Layout& layout);
void writeLayout(const std::filesystem::path& file, const Scene& scene, const Layout& layout);

// Reads a layout for `scene`: entities it names take its placement, the others keep
// the scene's. Throws SceneError (all problems, FILE: /json/path: message).
Layout readLayout(const std::filesystem::path& file, const Scene& scene);

}  // namespace luxplan::io
