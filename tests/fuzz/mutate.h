// Structure-aware mutations of luxplan's inputs: scenes, layouts, OBJ and glTF meshes,
// IES and EULUMDAT files. Each mutation class states what the program must do with
// what it makes (fuzz_case.h: refuse, accept, either).
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "fuzz_case.h"

namespace luxplan::fuzz {

// The inputs mutations start from, read once from the source tree.
struct Seeds {
    struct SceneSeed {
        std::string name;                          // e.g. scenes/paper/fig8-lab.json
        std::string text;                          // the scene
        std::map<std::string, std::string> files;  // files it names (photometry, meshes), by name
        std::string layout;                        // a valid layout.json for it ("" if none movable)
    };
    std::vector<SceneSeed> scenes;
    std::vector<std::pair<std::string, std::string>> objs, gltfs, glbs, ies, ldts;  // name, bytes
    std::string photometryScene;  // a scene with luminaires naming "PHOTOMETRY"
};

// Reads scenes/**.json (and what they name), the meshes and photometric files under
// scenes/ and tests/data/; each scene's layout comes from layoutFor() (fuzz_case.h).
Seeds loadSeeds(const std::filesystem::path& sourceDir);

// The case number `index` of a run seeded with `seed` (the same pair gives the same case).
Case makeCase(const Seeds& seeds, std::uint64_t seed, std::uint64_t index);

}  // namespace luxplan::fuzz
