// A SceneLab (support/scene_lab.h) built from JSON text through the scene loader,
// for the tests that link luxplan_io (output).
#pragma once

#include <luxplan/io/scene_loader.h>
#include "support/scene_lab.h"
#include "support/temp_files.h"

namespace luxplan::test {

struct LabDir {
    TempDir dir;
};

struct Lab : LabDir, SceneLab {
    explicit Lab(const std::string& json, const PathTracerOptions& options = {})
        : SceneLab(io::loadScene(dir.write("scene.json", json)), options) {}
    explicit Lab(Scene scene, const PathTracerOptions& options = {}) : SceneLab(std::move(scene), options) {}
};

}  // namespace luxplan::test
