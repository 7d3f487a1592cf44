// Loading a scene as the commands load it, and naming the scene file in every
// refusal: what the CLI and the Python module share.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include <luxplan/core/error.h>
#include <luxplan/scene/scene.h>

namespace luxplan::api {

// A usage problem of an option (a --set value): the CLI reports it as a usage error
// (exit 2, "OPTION: PROBLEM"), Python as a ValueError.
class UsageError : public std::runtime_error {
public:
    UsageError(std::string option, std::string problem)
        : std::runtime_error(option + ": " + problem), option_(std::move(option)), problem_(std::move(problem)) {}
    const std::string& option() const { return option_; }
    const std::string& problem() const { return problem_; }

private:
    std::string option_, problem_;
};

// The scene file with its "optimizer" settings overridden by `settings`, each
// "KEY=VALUE" as --set takes it. Throws UsageError for a setting, SceneError or IoError
// for the file.
Scene loadScene(const std::string& path, const std::vector<std::string>& settings = {});

// What validate, measure and optimize say of a valid scene that may not be what was
// meant (checks/scene_warnings.h): FILE: /json/path: warning: ..., a line each.
std::vector<std::string> sceneWarnings(const Scene& scene);

// Runs `fn` on the scene file `scene`: an exception that names no file (a library's,
// or a problem found after loading) becomes SceneError SCENE: /: message, so that every
// refusal names its file. SceneError, IoError, UsageError and what `passes` says of
// (the CLI's own errors) pass unchanged.
template <class Fn, class Passes>
decltype(auto) namingScene(const std::string& scene, Fn&& fn, Passes&& passes) {
    try {
        return fn();
    } catch (const SceneError&) {
        throw;
    } catch (const IoError&) {
        throw;
    } catch (const UsageError&) {
        throw;
    } catch (const std::exception& e) {
        if (passes(e)) throw;
        throw SceneError({{scene, "", e.what()}});
    }
}
template <class Fn>
decltype(auto) namingScene(const std::string& scene, Fn&& fn) {
    return namingScene(scene, std::forward<Fn>(fn), [](const std::exception&) { return false; });
}

}  // namespace luxplan::api
