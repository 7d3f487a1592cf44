// The small scene that the robustness tests and the fuzzer start from, as scene-file
// text: a 6 x 4 x 3 m room, one 3200 lm ceiling panel, a movable desk box and a planar
// sampler on it.
#pragma once

#include <string>

namespace luxplan::test {

// `extraGeometry`: JSON objects appended to "geometry" (each with a leading comma);
// `optimizerPaths` > 0 adds "optimizer": {"paths_per_point": N}.
inline std::string smallRoomScene(const std::string& extraGeometry = "", int optimizerPaths = 4) {
    std::string s = R"({"luxplan": 1,
  "materials": {"wall": {"type": "diffuse", "reflectance": 0.6}},
  "geometry": [{"name": "room", "room": {"min": [0,0,0], "max": [6,4,3]},
                "materials": {"floor": "wall", "walls": "wall", "ceiling": "wall"}})";
    s += extraGeometry;
    s += R"(],
  "luminaires": [{"name": "panel", "shape": "rect", "center": [3,2,2.99], "normal": [0,0,-1], "size": [0.6,0.6], "flux_lm": 3200}],
  "entities": [{"name": "desk", "position": [2, 2],
                "placement": {"regions": [{"min": [1,1], "max": [5,3], "rotations": [0, 90]}]},
                "parts": [{"box": {"size": [1.2,0.6,0.75]}, "material": "wall"}]}],
  "samplers": [{"name": "top", "type": "planar", "center": [3,2,0.8], "size": [1,1], "target": [300,500]}])";
    if (optimizerPaths > 0) {
        s += ",\n  \"optimizer\": {\"paths_per_point\": ";
        s += std::to_string(optimizerPaths);
        s += "}";
    }
    s += "}";
    return s;
}

}  // namespace luxplan::test
