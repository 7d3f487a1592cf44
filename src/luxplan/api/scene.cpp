#include <luxplan/api/scene.h>

#include <luxplan/checks/scene_warnings.h>
#include <luxplan/io/scene_loader.h>
#include <luxplan/io/settings_table.h>

namespace luxplan::api {
namespace {

// A settings problem without its "--set " (the option is said before it).
std::string withoutPrefix(const std::string& problem) {
    const std::string prefix = "--set ";
    return problem.rfind(prefix, 0) == 0 ? problem.substr(prefix.size()) : problem;
}

}  // namespace

Scene loadScene(const std::string& path, const std::vector<std::string>& settings) {
    io::LoadOptions options;
    for (const std::string& text : settings) {
        try {
            options.settings.push_back(io::parseSetting(text));
        } catch (const std::invalid_argument& e) {
            throw UsageError("--set " + text, e.what());
        }
    }
    // Each was checked alone when parsed; here the keys that exclude each other.
    const std::vector<std::string> problems = io::settingProblems(options.settings);
    if (!problems.empty()) throw UsageError("--set", withoutPrefix(problems.front()));
    Scene scene = io::loadScene(path, options);
    for (const io::SettingOverride& s : options.settings) scene.settingsSet.push_back(s.key);
    return scene;
}

std::vector<std::string> sceneWarnings(const Scene& scene) {
    std::vector<std::string> lines;
    for (Diagnostic w : luxplan::sceneWarnings(scene)) {
        w.message = "warning: " + w.message;
        lines.push_back(w.str());
    }
    return lines;
}

}  // namespace luxplan::api
