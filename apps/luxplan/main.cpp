// luxplan: furniture layout optimization guided by illumination goals.
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include <tbb/global_control.h>

#include "commands.h"
#include "shared_options.h"
#include <luxplan/core/error.h>

int main(int argc, char** argv) {
    // --help-all: --help with the advanced options shown and every --set key listed.
    std::vector<char*> args(argv, argv + argc);
    static char help[] = "--help";
    for (char*& a : args)
        if (std::string(a) == "--help-all") {
            luxplan::cli::setHelpAll(true);
            a = help;
        }
    CLI::App app{"luxplan: arrange furniture so that design rules and lighting goals hold"};
    app.require_subcommand(1);
    app.set_version_flag("--version", "luxplan 0.1.0");
    luxplan::cli::registerValidateCommand(app);
    luxplan::cli::registerInfoCommand(app);
    int threads = 0;  // the subcommand's --threads; 0: all cores
    luxplan::cli::registerMeasureCommand(app, threads);
    luxplan::cli::registerOptimizeCommand(app, threads);
    luxplan::cli::registerSunCommand(app);
    luxplan::cli::registerRenderCommand(app, threads);
    luxplan::cli::registerReportCommand(app, threads);
    luxplan::cli::registerSettingsCommand(app);
    // The one place that sets the thread count: CLI11 runs this after storing the options
    // and before the subcommand's callback, and every parallel loop (core/parallel.h) runs
    // on TBB's default arena, which the control limits for as long as it lives.
    std::optional<tbb::global_control> parallelism;
    app.parse_complete_callback([&] {
        if (threads > 0) parallelism.emplace(tbb::global_control::max_allowed_parallelism, size_t(threads));
    });
    try {
        app.parse(int(args.size()), args.data());
    } catch (const CLI::RuntimeError& e) {
        return e.get_exit_code();  // a run stopped by a signal: 128 + the signal
    } catch (const CLI::ParseError& e) {
        // --help and --version exit 0; a mistake on the command line, 2 (1: the input).
        return app.exit(e) == 0 ? 0 : 2;
    } catch (const luxplan::SceneError& e) {
        std::cerr << e.what() << "\n";
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "luxplan: error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
