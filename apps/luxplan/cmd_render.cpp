// `luxplan render SCENE [--layout L] -o OUTDIR`: render.png, plan.png and scene.glb
// for a layout (with --glb-only, scene.glb alone, no light transport); `luxplan report SCENE [--layout L] -o OUTDIR`: every picture and
// report.html for a layout, measured but not optimized. Both read the settings seed,
// report_paths_per_point, sun_patches and exterior_sun (--set, io/settings_table.h).
#include <cmath>
#include <iostream>

#include "commands.h"
#include "daylight_progress.h"
#include "option_checks.h"
#include "shared_options.h"
#include "picture_progress.h"
#include <luxplan/constraints/penalty.h>
#include <luxplan/core/limits.h>
#include <luxplan/core/names.h>
#include <luxplan/daylight/daylight.h>
#include <luxplan/io/layout_io.h>
#include <luxplan/io/scene_loader.h>
#include <luxplan/output/outputs.h>

namespace luxplan::cli {
namespace {

struct PictureArgs : SharedArgs {
    std::string out;
    int width = 0, height = 0, spp = 0;
    double cell = 0;
    int cellPaths = 0;
    bool raw = false;
    bool noPdf = false;  // report: no report.pdf
    std::string camera;                // a scene camera's name
    std::vector<double> eye, target;  // or a view from the command line
    double fov = 0;
    bool glbOnly = false;              // render: scene.glb alone
};

void addPictureOptions(CLI::App* cmd, PictureArgs& args, int& threads) {
    OutputOptions defaults;
    addSharedOptions(cmd, args, threads, "Paths per sampler point (default: the report's, optimizer.report_paths_per_point)",
                     kLayoutOption);
    const std::string advanced = advancedGroup();
    cmd->add_option("--width", args.width, "Render width in pixels (default " + std::to_string(defaults.renderWidth) + ")")
        ->check(wholeNumber(1))
        ->group(advanced);
    cmd->add_option("--height", args.height, "Render height in pixels (default " + std::to_string(defaults.renderHeight) + ")")
        ->check(wholeNumber(1))
        ->group(advanced);
    cmd->add_option("--spp", args.spp, "Render samples per pixel (default " + std::to_string(defaults.renderSamplesPerPixel) + ")")
        ->check(wholeNumber(1))
        ->group(advanced);
    cmd->add_flag("--raw", args.raw, "render.png without the denoising filter (the path tracer's pixel means)")->group(advanced);
    cmd->add_option("--cell", args.cell, "Work-plane grid cell in metres (default 0.25)")->check(positiveNumber())->group(advanced);
    cmd->add_option("--cell-paths", args.cellPaths, "Illuminance samples per work-plane cell (default " +
                                                        std::to_string(defaults.cellPaths) + ")")
        ->check(wholeNumber(1))
        ->group(advanced);
    auto* camera = cmd->add_option("--camera", args.camera, "render.png from the scene's camera of that name (\"cameras\")")
                       ->check(CLI::Validator([](std::string& name) { return name.empty() ? "expected a camera's name, got \"\"" : ""; },
                                              "NAME"));
    auto* eye = cmd->add_option("--eye", args.eye, "render.png from this point: X,Y,Z in metres (with --target)")
                    ->delimiter(',')->expected(3);
    auto* target = cmd->add_option("--target", args.target, "... looking at this point: X,Y,Z in metres")->delimiter(',')->expected(3);
    cmd->add_option("--fov", args.fov, "Vertical field of view in degrees, (0, 180) (default: the camera's, or 60)")
        ->check(CLI::Range(1e-3, 179.999));
    eye->needs(target);
    target->needs(eye);
    camera->excludes(eye)->excludes(target);
}

// The view render.png is drawn from: a scene camera, a command-line one, or none
// (the default corner view).
std::optional<Camera> chosenCamera(const PictureArgs& args, const Scene& scene) {
    if (!args.camera.empty()) {
        std::vector<std::string> names;
        for (const SceneCamera& c : scene.cameras) {
            if (c.name == args.camera) return lookingAt(c.eye, c.target, args.fov > 0 ? args.fov : c.fovDeg);
            names.push_back(c.name);
        }
        throw std::runtime_error("--camera: unknown camera \"" + args.camera + "\"" + didYouMean(args.camera, names) +
                                 (names.empty() ? " (the scene has no \"cameras\")" : " (" + listNames(names) + ")"));
    }
    if (args.eye.empty()) return std::nullopt;
    const Vec3 eye(args.eye[0], args.eye[1], args.eye[2]), target(args.target[0], args.target[1], args.target[2]);
    for (double v : {eye.x, eye.y, eye.z, target.x, target.y, target.z})
        if (!std::isfinite(v) || std::abs(v) > limits::kMaxCoordinate)
            throw std::runtime_error("--eye/--target: coordinates must be finite and within " +
                                     std::to_string(int(limits::kMaxCoordinate)) + " m");
    if (length(target - eye) < 1e-6) throw std::runtime_error("--target is the same point as --eye: the camera looks nowhere");
    return lookingAt(eye, target, args.fov > 0 ? args.fov : 60);
}

OutputOptions outputOptions(const PictureArgs& args, const Scene& scene) {
    OutputOptions o;
    if (args.width > 0) o.renderWidth = args.width;
    if (args.height > 0) o.renderHeight = args.height;
    if (args.spp > 0) o.renderSamplesPerPixel = args.spp;
    o.renderDenoise = !args.raw;
    o.samplerPaths = args.paths > 0 ? args.paths : scene.optimizer.reportPathsPerPoint;  // as the report and measure
    if (args.cell > 0) o.cellSize = args.cell;
    if (args.cellPaths > 0) o.cellPaths = args.cellPaths;
    o.seed = args.seed.value_or(scene.optimizer.seed);
    o.camera = chosenCamera(args, scene);
    o.pdf = !args.noPdf;
    o.tracing.sunPatches = scene.optimizer.samplesSunPatches(SunPatchUse::On, false);
    o.tracing.exteriorSun = scene.optimizer.exteriorSun;
    return o;
}

void runPictures(const PictureArgs& args, bool report) {
    Scene scene = loadSceneWithSettings(args);
    Layout initial = initialLayout(scene);
    Layout layout = args.layout.empty() ? initial : io::readLayout(args.layout, scene);
    std::optional<DaylightEnvironment> daylight;
    if (scene.daylight) daylight = bakeDaylight(*scene.daylight, scene.site);

    OutputOptions options = outputOptions(args, scene);
    options.initialLabel = "scene placement";
    options.finalLabel = args.layout.empty() ? "scene placement" : std::filesystem::path(args.layout).filename().string();
    if (report) {
        // As layout.json holds it (0.1 mm, 0.01 degree), so that the file measures what
        // the report says.
        initial = roundedLayout(scene, initial);
        layout = roundedLayout(scene, layout);
        std::filesystem::create_directories(args.out);
        io::writeLayout(std::filesystem::path(args.out) / "layout.json", scene, layout);
    } else {
        options.comparison = options.convergence = options.html = false;
    }
    if (args.glbOnly) options.plan = options.render = options.luminanceView = false;
    RunOutputs outputs;
    {
        std::cout.flush();
        PictureProgress progress(options);
        outputs = writeRunOutputs(args.out, scene, initial, layout, nullptr, daylight ? &*daylight : nullptr, options);
    }
    std::cout << (report ? "report" : "render") << ": wrote";
    if (report) std::cout << " " << args.out << "/layout.json";
    for (const auto& f : outputs.files) std::cout << " " << f.string();
    std::cout << " in " << outputs.seconds << " s\n";
    int met = 0;
    for (size_t k = 0; k < outputs.samplers.size() && k < scene.samplers.size(); ++k)
        met += allMet(lightingTerms(scene.samplers[k], outputs.samplers[k]));
    if (!outputs.samplers.empty())
        std::cout << "  samplers: " << met << " of " << outputs.samplers.size() << " meet their targets\n";
}

}  // namespace

void registerRenderCommand(CLI::App& app, int& threads) {
    auto args = std::make_shared<PictureArgs>();
    auto* cmd = app.add_subcommand("render", "Render a layout: render.png, plan.png and scene.glb");
    addPictureOptions(cmd, *args, threads);
    cmd->add_option("-o,--out", args->out, "Output folder")->required();
    cmd->add_flag("--glb-only", args->glbOnly, "Write scene.glb alone: no pictures, no light transport");
    cmd->callback([args] { namingScene(args->scene, [&] { runPictures(*args, false); }); });
}

void registerReportCommand(CLI::App& app, int& threads) {
    auto args = std::make_shared<PictureArgs>();
    auto* cmd = app.add_subcommand("report", "Measure a layout and write every picture, scene.glb, report.html and report.pdf");
    addPictureOptions(cmd, *args, threads);
    cmd->add_flag("--no-pdf", args->noPdf, "Skip report.pdf (report.html printed by headless Chromium)");
    cmd->add_option("-o,--out", args->out, "Output folder")->required();
    cmd->callback([args] { namingScene(args->scene, [&] { runPictures(*args, true); }); });
}

}  // namespace luxplan::cli
