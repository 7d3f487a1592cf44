// layout.json (docs/scene-format.md, "layout.json"): {"entities": {"dotted.path": {"position": [x,y,z],
// "rotation": deg, "region": k}}} for every movable entity, in its parent's frame.
#pragma once

#include <filesystem>
#include <string>

#include <luxplan/scene/layout.h>

namespace luxplan::io {

// Positions are written to 0.1 mm and rotations to 0.01 degree (roundedPlacement,
// scene/layout.h); z as it is. A layout to be measured as its file will be read
// back is rounded first (roundedLayout): the optimizer's result is.
std::string layoutToJson(const Scene& scene, const Layout& layout);
void writeLayout(const std::filesystem::path& file, const Scene& scene, const Layout& layout);

// Reads a layout for `scene`: entities it names take its placement, the others keep
// the scene's. Throws SceneError (all problems, FILE: /json/path: message).
Layout readLayout(const std::filesystem::path& file, const Scene& scene);
// The same from a layout file's text, its problems named by `name` as by a file.
Layout readLayoutText(const std::string& text, const std::string& name, const Scene& scene);

}  // namespace luxplan::io
