// `luxplan validate SCENE`: exit 0, or print every problem as FILE: /json/path: message.
#include "commands.h"

namespace luxplan::cli {

void registerValidateCommand(CLI::App& app) {
    auto* cmd = app.add_subcommand("validate", "Check a scene file against the format; print every error");
    auto scene = std::make_shared<std::string>();
    cmd->add_option("scene", *scene, "Scene JSON file")->required();
}

void registerInfoCommand(CLI::App& app) {
    auto* cmd = app.add_subcommand("info", "Validate a scene and print a summary of it");
    auto scene = std::make_shared<std::string>();
    cmd->add_option("scene", *scene, "Scene JSON file")->required();
}

}  // namespace luxplan::cli
