// Loads and validates a scene file (docs/scene-format.md, version 1) into the scene model.
#pragma once

#include <filesystem>
#include <vector>

#include <luxplan/io/settings_table.h>
#include <luxplan/scene/scene.h>

namespace luxplan::io {

struct LoadOptions {
    double voxelSize = 0.02;  // target voxel edge (m) for the overlap volumes
    // `--set KEY=VALUE`: read as keys of the "optimizer" object, over the file's own;
    // their problems are named "--set KEY=VALUE" instead of a JSON path.
    std::vector<SettingOverride> settings;
};

// Reads, validates and builds the scene. Every problem found is reported at once:
// throws SceneError whose diagnostics read FILE: /json/path: message.
Scene loadScene(const std::filesystem::path& file, const LoadOptions& options = {});

}  // namespace luxplan::io
