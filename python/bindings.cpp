// The compiled part of the Python module luxplan (luxplan/__init__.py wraps it): scenes
// loaded as the CLI loads them, measure's JSON and optimize's report.json and layout.json
// as the CLI writes them, as text that json.loads reads into the same numbers. The GIL
// is released while the engine runs.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cmath>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <tbb/global_control.h>

#include <luxplan/api/measure.h>
#include <luxplan/api/optimize.h>
#include <luxplan/optimizer/progress_line.h>
#include <luxplan/api/scene.h>
#include <luxplan/io/layout_io.h>

namespace py = pybind11;
using namespace pybind11::literals;

namespace luxplan::python {
namespace {

// The engine's worker threads during one call (0: every core), as the CLI's --threads.
std::optional<tbb::global_control> threadLimit(int threads) {
    if (threads <= 0) return std::nullopt;
    return std::optional<tbb::global_control>(std::in_place, tbb::global_control::max_allowed_parallelism, size_t(threads));
}

class PyScene {
public:
    PyScene(const std::string& path, const std::vector<std::string>& settings) : path_(path) {
        py::gil_scoped_release released;
        scene_ = std::make_shared<const Scene>(api::namingScene(path, [&] { return api::loadScene(path, settings); }));
        warnings_ = api::sceneWarnings(*scene_);
    }
    const std::string& path() const { return path_; }
    const std::vector<std::string>& warnings() const { return warnings_; }
    std::string initialLayout() const { return io::layoutToJson(*scene_, luxplan::initialLayout(*scene_)); }

    // measure's JSON text and the warnings it said, one line each.
    py::tuple measure(const std::optional<std::string>& layoutFile, const std::optional<std::string>& layoutText, int paths,
                      std::optional<uint64_t> seed, int threads, const std::string& at, bool annual) const {
        api::MeasureRequest request;
        request.layoutFile = layoutFile.value_or("");
        request.layoutText = layoutText;
        request.paths = paths;
        request.seed = seed;
        request.at = at;
        request.annual = annual;
        std::vector<std::string> said;
        api::MeasureHooks hooks;
        hooks.warning = [&said](const std::string& line) { said.push_back(line); };
        std::string text;
        {
            py::gil_scoped_release released;
            const auto limit = threadLimit(threads);
            text = api::namingScene(path_, [&] { return api::measureJson(api::measure(*scene_, request, hooks)).dump(2); });
        }
        return py::make_tuple(text, said);
    }

    // The search, and its files in `out` if given: (report.json's text, layout.json's
    // text, the warnings it said). `progress` (or None) is called with a dict every
    // progress step; Ctrl-C stops the search with its best layout so far. The engine runs
    // on a thread of its own while this one, without the GIL, waits for it and looks for
    // signals every 0.1 s (Python runs signal handlers on the main thread only).
    py::tuple optimize(const std::optional<std::string>& out, int iterations, std::optional<uint64_t> seed, int threads,
                       int paths, int suggestions, const std::optional<std::string>& startFile,
                       const std::optional<std::string>& startText, bool pictures, bool pdf, py::object progress) const {
        api::OptimizeRequest request;
        request.iterations = iterations;
        request.seed = seed;
        request.paths = paths;
        request.suggestions = suggestions;
        request.startFile = startFile.value_or("");
        request.startText = startText;
        std::atomic<bool> cancel{false};
        std::mutex lock;
        std::condition_variable finished;
        bool done = false;
        std::vector<std::string> said;
        std::exception_ptr failure;
        py::object raisedType, raisedValue;  // what the progress callback raised (under the GIL)
        std::string report, layout;

        api::OptimizeHooks hooks;
        hooks.warning = hooks.note = [&](const std::string& line) {
            const std::lock_guard<std::mutex> guard(lock);
            said.push_back(line);
        };
        hooks.cancel = &cancel;
        if (!progress.is_none())
            hooks.progress = [&](const Progress& p) {
                py::gil_scoped_acquire gil;
                try {
                    progress(py::dict("iteration"_a = p.iteration, "iterations"_a = p.iterations, "current"_a = p.current,
                                      "best"_a = std::isfinite(p.best) ? py::object(py::float_(p.best)) : py::object(py::none()),
                                      "temperature"_a = p.temperature, "feasible"_a = p.feasible, "seconds"_a = p.seconds,
                                      "eta_seconds"_a = p.etaSeconds, "line"_a = progressLine(p)));
                } catch (py::error_already_set& e) {
                    if (!raisedType) raisedType = e.type(), raisedValue = e.value();
                    cancel = true;
                }
            };
        std::thread engine([&] {
            try {
                const auto limit = threadLimit(threads);
                api::namingScene(path_, [&] {
                    if (out) api::checkOutputFolder(*out);
                    const std::unique_ptr<api::OptimizeRun> run = api::optimize(*scene_, request, hooks);
                    report = api::reportText(*run);
                    layout = api::layoutText(*run);
                    if (out) api::writeOutputs(*run, *out);
                    if (out && pictures && !cancel) api::writePictures(*run, *out, 0, pdf, &cancel);
                });
            } catch (...) {
                failure = std::current_exception();
            }
            const std::lock_guard<std::mutex> guard(lock);
            done = true;
            finished.notify_all();
        });
        {
            py::gil_scoped_release released;
            std::unique_lock<std::mutex> waiting(lock);
            while (!finished.wait_for(waiting, std::chrono::milliseconds(100), [&] { return done; })) {
                waiting.unlock();
                {
                    py::gil_scoped_acquire gil;
                    if (PyErr_CheckSignals() != 0) {
                        // KeyboardInterrupt (or a handler's own exception): the search stops with
                        // its best so far, which is returned; the exception is not raised.
                        PyErr_Clear();
                        cancel = true;
                    }
                }
                waiting.lock();
            }
        }
        engine.join();
        if (raisedType) {
            PyErr_SetObject(raisedType.ptr(), raisedValue.ptr());
            throw py::error_already_set();
        }
        if (failure) std::rethrow_exception(failure);
        return py::make_tuple(report, layout, said);
    }

private:
    std::string path_;
    std::shared_ptr<const Scene> scene_;
    std::vector<std::string> warnings_;
};

}  // namespace
}  // namespace luxplan::python

PYBIND11_MODULE(_core, m) {
    using namespace luxplan;
    m.doc() = "luxplan's engine (the package luxplan wraps it)";
    // Exceptions as Python classes of the module: SceneError (a ValueError whose
    // `diagnostics` list each problem's file, JSON path and message), IoError (an
    // OSError: a file that cannot be read, or a mesh, photometric or weather file's
    // problem at FILE:LINE) and UsageError (a ValueError: a setting).
    static py::exception<SceneError> sceneError(m, "SceneError", PyExc_ValueError);
    static py::exception<IoError> ioError(m, "IoError", PyExc_OSError);
    static py::exception<api::UsageError> usageError(m, "UsageError", PyExc_ValueError);
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const SceneError& e) {
            py::list diagnostics;
            for (const Diagnostic& d : e.diagnostics())
                diagnostics.append(py::dict("file"_a = d.file, "path"_a = d.jsonPath.empty() ? "/" : d.jsonPath,
                                            "message"_a = d.message));
            py::object error = py::handle(sceneError.ptr())(e.what());  // an instance, to carry its diagnostics
            error.attr("diagnostics") = diagnostics;
            PyErr_SetObject(sceneError.ptr(), error.ptr());
        } catch (const IoError& e) {
            ioError(e.what());
        } catch (const api::UsageError& e) {
            usageError(e.what());
        }
    });

    py::class_<python::PyScene>(m, "Scene")
        .def(py::init<const std::string&, const std::vector<std::string>&>(), "path"_a, "settings"_a = std::vector<std::string>{})
        .def_property_readonly("path", &python::PyScene::path)
        .def_property_readonly("warnings", &python::PyScene::warnings)
        .def("initial_layout", &python::PyScene::initialLayout)
        .def("measure", &python::PyScene::measure, "layout_file"_a, "layout_text"_a, "paths"_a, "seed"_a, "threads"_a, "at"_a,
             "annual"_a)
        .def("optimize", &python::PyScene::optimize, "out"_a, "iterations"_a, "seed"_a, "threads"_a, "paths"_a,
             "suggestions"_a, "start_file"_a, "start_text"_a, "pictures"_a, "pdf"_a, "progress"_a);
}
