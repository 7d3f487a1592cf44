// luxplan: furniture layout optimization guided by illumination goals.
#include <iostream>

#include "commands.h"
#include <luxplan/core/error.h>

int main(int argc, char** argv) {
    CLI::App app{"luxplan: arrange furniture so that design rules and lighting goals hold"};
    app.require_subcommand(1);
    app.set_version_flag("--version", "luxplan 0.1.0");
    luxplan::cli::registerValidateCommand(app);
    luxplan::cli::registerInfoCommand(app);
    luxplan::cli::registerMeasureCommand(app);
    luxplan::cli::registerOptimizeCommand(app);
    luxplan::cli::registerSunCommand(app);
    luxplan::cli::registerRenderCommand(app);
    luxplan::cli::registerReportCommand(app);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    } catch (const luxplan::SceneError& e) {
        std::cerr << e.what() << "\n";
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "luxplan: error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
