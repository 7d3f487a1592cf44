// What the loader refuses in a scene text, as "json/path: message" lines (each
// diagnostic checked to name the file and to print as "FILE: path: message"), for
// the io tests of error messages.
#pragma once

#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <luxplan/core/error.h>
#include <luxplan/io/scene_loader.h>
#include "support/temp_files.h"

namespace luxplan::test {

inline std::vector<std::string> loadProblems(const std::string& text, TempDir& dir, const std::string& name = "scene.json") {
    auto file = dir.write(name, text);
    try {
        io::loadScene(file);
    } catch (const SceneError& e) {
        std::vector<std::string> out;
        for (const auto& d : e.diagnostics()) {
            const std::string path = d.jsonPath.empty() ? "/" : d.jsonPath;
            EXPECT_EQ(d.file, file.string());
            EXPECT_EQ(d.str(), file.string() + ": " + path + ": " + d.message);
            out.push_back(path + ": " + d.message);
        }
        return out;
    }
    return {};
}

// The same for a scene given as JSON.
inline std::vector<std::string> problems(const nlohmann::json& scene) {
    TempDir dir;
    return loadProblems(scene.dump(2), dir);
}

// The one problem the loader finds in `scene`; the test fails unless there is exactly one.
inline std::string onlyProblem(const nlohmann::json& scene) {
    const auto p = problems(scene);
    EXPECT_EQ(p.size(), 1u) << (p.empty() ? "no problems" : p.front() + (p.size() > 1 ? " | " + p[1] : ""));
    return p.empty() ? "" : p.front();
}

}  // namespace luxplan::test
