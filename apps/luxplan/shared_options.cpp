#include "shared_options.h"

#include <iostream>
#include <stdexcept>

#include "commands.h"
#include "option_checks.h"
#include <luxplan/api/scene.h>
#include <luxplan/io/scene_loader.h>

namespace luxplan::cli {
namespace {

bool helpAll = false;

// A settings problem without its "--set " (CLI11 says "--set: " before it).
std::string withoutPrefix(const std::string& problem) {
    const std::string prefix = "--set ";
    return problem.rfind(prefix, 0) == 0 ? problem.substr(prefix.size()) : problem;
}

const char* const kAdvanced = "Advanced options";

// The default --help leaves the advanced options' group out (a hidden option's group,
// "", would also take its name out of its error messages).
class DesignerHelp : public CLI::Formatter {
public:
    std::string make_group(std::string group, bool positional, std::vector<const CLI::Option*> opts) const override {
        if (group == kAdvanced && !helpAll) return "";
        return CLI::Formatter::make_group(std::move(group), positional, std::move(opts));
    }
};

}  // namespace

void setHelpAll(bool all) { helpAll = all; }

std::string advancedGroup() { return kAdvanced; }

void addSharedOptions(CLI::App* cmd, SharedArgs& args, int& threads, const std::string& pathsHelp, unsigned which) {
    cmd->add_option("scene", args.scene, "Scene JSON file")->required();
    if (which & kLayoutOption) cmd->add_option("--layout", args.layout, "layout.json to use instead of the scene's placement");
    cmd->add_option("--paths", args.paths, pathsHelp)->check(wholeNumber(1));
    addSeedOption(cmd, args.seed);
    cmd->add_option("--threads", threads, "Worker threads (default: all cores)")->check(wholeNumber(0));
    cmd->add_option("--set", args.settings,
                    "A setting of the scene's \"optimizer\" object, over the file's (repeatable; --help-all or `luxplan "
                    "settings` lists every key)")
        ->allow_extra_args(false)
        ->type_name("KEY=VALUE")
        ->check(CLI::Validator(
            [](std::string& text) -> std::string {
                try {
                    const std::vector<std::string> problems = io::settingProblems({io::parseSetting(text)});
                    return problems.empty() ? "" : withoutPrefix(problems.front());
                } catch (const std::invalid_argument& e) {
                    return e.what();
                }
            },
            ""));
    if (which & kQuietOption) cmd->add_flag("-q,--quiet", args.quiet, "No progress line");
    cmd->formatter(std::make_shared<DesignerHelp>());
    cmd->footer(helpAll ? "\n" + io::settingsTableText()
                        : "\n--help-all: the advanced options too, and every --set key with its default and meaning");
}

Scene loadSceneWithSettings(const SharedArgs& args) {
    try {
        return api::loadScene(args.scene, args.settings);
    } catch (const api::UsageError& e) {
        throw CLI::ValidationError(e.option(), e.problem());
    }
}

void registerSettingsCommand(CLI::App& app) {
    auto* cmd = app.add_subcommand("settings", "List every setting: the scene file's \"optimizer\" keys, which --set KEY=VALUE sets");
    cmd->callback([] { std::cout << io::settingsTableText(); });
}

}  // namespace luxplan::cli
