#include <luxplan/io/layout_io.h>

#include <cmath>
#include <sstream>

#include <nlohmann/json.hpp>

#include <luxplan/core/atomic_file.h>
#include <luxplan/json/fields.h>
#include <luxplan/json/parse.h>

namespace luxplan::io {

using namespace json;

std::string layoutToJson(const Scene& scene, const Layout& layout) {
    Json entities = Json::object();
    for (size_t i = 0; i < scene.entities.size(); ++i) {
        if (!scene.entities[i].movable()) continue;
        // x and y to 0.1 mm, the rotation to 0.01 degree, each inside its region
        // (roundedPlacement): what the file says is what a reader measures.
        const Placement p = roundedPlacement(scene.entities[i], layout.placements[i]);
        Json& entry = entities[scene.entities[i].path];
        entry = {{"position", {p.position.x, p.position.y, p.position.z}}, {"rotation", p.rotationDeg}};
        // Outside every region (a flat run's layout in the scene's hierarchy): no index.
        if (p.region >= 0) entry["region"] = p.region;
    }
    return Json{{"entities", entities}}.dump(2) + "\n";
}

void writeLayout(const std::filesystem::path& file, const Scene& scene, const Layout& layout) {
    writeFileAtomically(file, layoutToJson(scene, layout));
}

namespace {

// The entities of a parsed layout; problems go to `sink`.
Layout readEntities(DiagnosticSink& sink, const Json& root, const Scene& scene) {
    Layout layout = initialLayout(scene);
    Fields top(sink, root, "", "a layout object");
    if (top.valid() && !top.has("entities")) top.missing("entities");
    if (top.has("entities")) {
        const Json& entities = top.get("entities");
        if (!entities.is_object()) sink.error("/entities", "expected an object keyed by entity path, got " + typeName(entities));
        else
            for (const auto& [name, value] : entities.items()) {
                std::string path = pointer("/entities", name);
                int index = scene.findEntity(name);
                if (index < 0) {
                    sink.error(path, "unknown entity \"" + name + "\" in scene " + scene.file.string());
                    continue;
                }
                const Entity& e = scene.entities[index];
                Fields f(sink, value, path);
                if (!f.valid()) continue;
                if (!e.movable()) {
                    sink.error(path, "entity \"" + name + "\" is fixed (it has no placement regions)");
                    continue;
                }
                Placement& p = layout.placements[index];
                if (f.has("position")) {
                    const Json& pos = f.get("position");
                    auto n = readNumbers(sink, pos, f.at("position"), pos.is_array() && pos.size() == 2 ? 2 : 3,
                                         coordinateRange());
                    if (n) p.position = Vec3((*n)[0], (*n)[1], n->size() == 3 ? (*n)[2] : e.position.z);
                    // An entity moves on the plane of its scene position's z.
                    if (n && !(std::abs(p.position.z - e.position.z) <= 1e-9 * (1 + std::abs(e.position.z)))) {
                        sink.error(pointer(f.at("position"), 2), "z " + formatNumber(p.position.z) + " is not the plane entity \"" + name +
                                                                     "\" moves on (z = " + formatNumber(e.position.z) +
                                                                     ", its position's in the scene)");
                        p.position.z = e.position.z;
                    }
                }
                p.rotationDeg = f.number("rotation", p.rotationDeg, json::rotationRange());
                auto region = f.integer("region", Range::closed(0, double(e.regions.size()) - 1));
                if (region) {
                    p.region = *region;
                    if (!regionContains(e.regions[*region], {p.position.x, p.position.y}, p.rotationDeg, kRegionTolerance))
                        f.error("region", "position (" + formatNumber(p.position.x) + ", " + formatNumber(p.position.y) +
                                              ") with rotation " + formatNumber(p.rotationDeg) + " lies outside region " +
                                              std::to_string(*region));
                } else if (!f.has("region")) {
                    p.region = findRegion(e.regions, {p.position.x, p.position.y}, p.rotationDeg);
                }
                f.finish();
            }
    }
    top.finish();
    return layout;
}

}  // namespace

Layout readLayout(const std::filesystem::path& file, const Scene& scene) {
    DiagnosticSink sink;
    sink.file = file.string();
    auto text = readInputFile(sink, file, limits::kMaxJsonFileBytes);
    if (!text) throw SceneError(sink.diagnostics);
    return readLayoutText(*text, file.string(), scene);
}

Layout readLayoutText(const std::string& text, const std::string& name, const Scene& scene) {
    DiagnosticSink sink;
    sink.file = name;
    auto parsed = parseJson(text, sink);
    if (!parsed) throw SceneError(sink.diagnostics);
    const Json& root = *parsed;
    Layout layout;
    try {
        layout = readEntities(sink, root, scene);
    } catch (const std::exception& e) {
        // A library's exception still names the file.
        sink.error("", std::string("cannot read the layout: ") + e.what());
    }
    if (sink.count()) throw SceneError(sink.diagnostics);
    return layout;
}

}  // namespace luxplan::io
