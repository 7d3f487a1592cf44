// The compiled part of the Python module luxplan (luxplan/__init__.py wraps it): scenes
// loaded as the CLI loads them, and measure's JSON as the CLI prints it, as text that
// json.loads reads into the same numbers. The GIL is released while the engine runs.
#include <optional>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <tbb/global_control.h>

#include <luxplan/api/measure.h>
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
             "annual"_a);
}
