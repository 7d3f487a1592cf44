// Scene file -> scene model. Reads each section with `Fields`, which reports wrong
// types, unknown keys and bad ranges with their JSON path; names are resolved after
// all definitions are read, so every problem of a file is reported in one run.
#include <luxplan/io/scene_loader.h>

#include <fstream>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include <luxplan/daylight/datetime.h>
#include <luxplan/io/json_fields.h>
#include <luxplan/io/mesh_io.h>
#include <luxplan/scene/presets.h>
#include <luxplan/scene/room.h>

namespace luxplan::io {
namespace {

// ---- JSON parsing with duplicate-key detection and line/column for syntax errors ----

struct ParseState {
    struct Frame {
        bool isArray = false;
        size_t index = 0;
        std::string key;
        std::set<std::string> keys;
    };
    std::vector<Frame> stack;
    std::vector<std::string> duplicates;  // JSON Pointers of repeated keys

    std::string pathOfTop() const {
        std::string p;
        for (size_t i = 0; i + 1 < stack.size(); ++i)
            p = stack[i].isArray ? pointer(p, stack[i].index) : pointer(p, stack[i].key);
        return p;
    }
    void elementDone() {
        if (!stack.empty() && stack.back().isArray) ++stack.back().index;
    }
};

std::pair<size_t, size_t> lineColumn(const std::string& text, size_t byte) {
    size_t line = 1, col = 1;
    for (size_t i = 0; i < byte && i < text.size(); ++i) {
        if (text[i] == '\n') ++line, col = 1;
        else ++col;
    }
    return {line, col};
}

std::optional<Json> parseJson(const std::string& text, DiagnosticSink& sink) {
    ParseState state;
    auto callback = [&](int, Json::parse_event_t event, Json& parsed) {
        switch (event) {
            case Json::parse_event_t::object_start: state.stack.emplace_back(); break;
            case Json::parse_event_t::array_start:
                state.stack.emplace_back();
                state.stack.back().isArray = true;
                break;
            case Json::parse_event_t::key: {
                auto& top = state.stack.back();
                top.key = parsed.get<std::string>();
                if (!top.keys.insert(top.key).second) state.duplicates.push_back(pointer(state.pathOfTop(), top.key));
                break;
            }
            case Json::parse_event_t::object_end:
            case Json::parse_event_t::array_end:
                state.stack.pop_back();
                state.elementDone();
                break;
            case Json::parse_event_t::value: state.elementDone(); break;
        }
        return true;
    };
    try {
        Json root = Json::parse(text, callback, /*allow_exceptions=*/true, /*ignore_comments=*/false);
        for (const auto& d : state.duplicates) sink.error(d, "duplicate key (JSON objects need unique keys)");
        return root;
    } catch (const Json::parse_error& e) {
        auto [line, col] = lineColumn(text, e.byte > 0 ? e.byte - 1 : 0);
        std::string what = e.what();
        // nlohmann's message starts with "[json.exception.parse_error.101] parse error at line ..., column ...: ".
        auto colon = what.find(": ", what.find("parse error"));
        std::string detail = colon == std::string::npos ? what : what.substr(colon + 2);
        sink.error("", "malformed JSON at line " + std::to_string(line) + ", column " + std::to_string(col) + ": " +
                           detail);
        return std::nullopt;
    }
}

const Range kUnit = Range::closed(0, 1);
const Range kNonNegative = Range::atLeast(0);

// ---- the loader ----

class Loader {
public:
    Loader(const std::filesystem::path& file, const LoadOptions& options) : options_(options) {
        sink_.file = file.string();
        scene_.file = file;
        dir_ = file.parent_path();
    }

    Scene load() {
        std::ifstream in(scene_.file, std::ios::binary);
        if (!in) {
            sink_.error("", "cannot open the file");
            throw SceneError(sink_.diagnostics);
        }
        std::stringstream buffer;
        buffer << in.rdbuf();
        auto root = parseJson(buffer.str(), sink_);
        if (!root) throw SceneError(sink_.diagnostics);
        readRoot(*root);
        if (sink_.count()) throw SceneError(sink_.diagnostics);
        buildVoxels();
        return std::move(scene_);
    }

private:
    void readRoot(const Json& root) {
        Fields f(sink_, root, "",
                 {"luxplan", "name", "site", "daylight", "materials", "geometry", "luminaires", "entities", "samplers",
                  "constraints", "objective", "optimizer"},
                 "a scene object");
        if (!f.valid()) return;
        if (auto v = f.integer("luxplan", {}, true); v && *v != 1)
            f.error("luxplan", "unsupported format version " + std::to_string(*v) + " (this luxplan reads version 1)");
        scene_.name = f.string("name").value_or(scene_.file.stem().string());
        size_t beforeSite = sink_.count();
        if (f.has("site")) readSite(f.get("site"), f.at("site"));
        siteValid_ = sink_.count() == beforeSite;
        if (f.has("daylight")) readDaylight(f.get("daylight"), f.at("daylight"));
        if (f.has("materials")) readMaterials(f.get("materials"), f.at("materials"));
        if (auto* a = f.array("geometry"))
            for (size_t i = 0; i < a->size(); ++i) readStatic((*a)[i], pointer(f.at("geometry"), i));
        if (auto* a = f.array("luminaires"))
            for (size_t i = 0; i < a->size(); ++i) readEmitter((*a)[i], pointer(f.at("luminaires"), i), -1);
        size_t before = sink_.count();
        if (auto* a = f.array("entities"))
            for (size_t i = 0; i < a->size(); ++i) readEntity((*a)[i], pointer(f.at("entities"), i), -1);
        // Constraints naming an entity that failed to load would only repeat that error.
        entitiesIncomplete_ = sink_.count() != before;
        if (auto* a = f.array("samplers"))
            for (size_t i = 0; i < a->size(); ++i) readSampler((*a)[i], pointer(f.at("samplers"), i), -1);
        if (auto* a = f.array("constraints"))
            for (size_t i = 0; i < a->size(); ++i) readConstraint((*a)[i], pointer(f.at("constraints"), i));
        if (f.has("objective")) {
            Fields o(sink_, f.get("objective"), f.at("objective"), {"lighting_weight"});
            scene_.objective.lightingWeight = o.number("lighting_weight", 0.5, kUnit);
        }
        if (f.has("optimizer")) readOptimizer(f.get("optimizer"), f.at("optimizer"));
        checkUniqueNames();
    }

    void readOptimizer(const Json& j, const std::string& path) {
        Fields o(sink_, j, path,
                 {"iterations", "seed", "paths_per_point", "report_paths_per_point", "hierarchy", "inner_iterations",
                  "temperature", "start"});
        OptimizerSettings& s = scene_.optimizer;
        s.iterations = o.integer("iterations", Range::atLeast(0)).value_or(10000);
        s.seed = uint64_t(o.integer("seed", Range::atLeast(0)).value_or(1));
        auto paths = o.integer("paths_per_point", Range::atLeast(1));
        s.pathsPerPoint = paths.value_or(1000);
        s.searchPathsPerPoint = paths.value_or(64);
        s.reportPathsPerPoint = o.integer("report_paths_per_point", Range::atLeast(1)).value_or(std::max(1000, s.pathsPerPoint));
        s.innerIterations = o.integer("inner_iterations", Range::closed(1, 1000)).value_or(4);
        if (auto h = o.string("hierarchy")) {
            if (*h == "flat") s.flat = true;
            else if (*h != "hierarchical") o.error("hierarchy", "unknown hierarchy \"" + *h + "\" (hierarchical or flat)");
        }
        if (auto start = o.string("start")) {
            if (*start == "scene") s.startFromScene = true;
            else if (*start != "uniform") o.error("start", "unknown start \"" + *start + "\" (uniform or scene)");
        }
        if (o.has("temperature")) {
            const Json& t = o.get("temperature");
            if (t.is_number()) {
                s.constantTemperature = true;
                s.temperatureStart = s.temperatureEnd = o.number("temperature", 0.1, Range::positive());
            } else {
                Fields tf(sink_, t, o.at("temperature"), {"start", "end"}, "a number or {\"start\", \"end\"}");
                s.temperatureStart = tf.number("start", 0.1, Range::positive());
                s.temperatureEnd = tf.number("end", 0.001, Range::positive());
            }
        }
    }

    void readSite(const Json& j, const std::string& path) {
        Fields f(sink_, j, path, {"latitude", "longitude", "north_deg"});
        scene_.site.latitudeDeg = f.number("latitude", 0.0, Range::closed(-90, 90, "deg"));
        scene_.site.longitudeDeg = f.number("longitude", 0.0, Range::closed(-180, 180, "deg"));
        scene_.site.northDeg = f.number("north_deg", 0.0, Range::closed(-360, 360, "deg"));
    }

    std::optional<DateTime> readTime(const Fields& f, const char* key) {
        auto text = f.string(key);
        if (!text) return std::nullopt;
        std::string why;
        auto t = parseIso8601(*text, &why);
        if (!t) f.error(key, why);
        return t;
    }

    // Types, units and keys here; the cross-field rules (what each sky model needs, the
    // time interval) are the daylight module's validateDaylight(), run once this passes.
    void readDaylight(const Json& j, const std::string& path) {
        size_t before = sink_.count();
        Fields f(sink_, j, path,
                 {"sky", "sun", "ground_reflectance", "from", "to", "step_minutes", "pressure_mbar", "temperature_c"});
        if (!f.valid()) return;
        DaylightParams d;
        if (!f.has("sky")) f.missing("sky");
        else {
            Fields s(sink_, f.get("sky"), f.at("sky"),
                     {"model", "turbidity", "horizontal_illuminance_lx", "luminance_nits", "type"});
            auto model = s.string("model", true);
            auto parsed = model ? parseSkyModel(*model) : std::nullopt;
            if (model && !parsed)
                s.error("model", "unknown sky model \"" + *model + "\" (preetham, cie_overcast, uniform or cie_general)");
            if (parsed) {
                d.model = *parsed;
                std::vector<const char*> own;
                switch (d.model) {
                    case SkyModelType::Preetham: own = {"turbidity"}; break;
                    case SkyModelType::CieOvercast: own = {"horizontal_illuminance_lx"}; break;
                    case SkyModelType::Uniform: own = {"luminance_nits"}; break;
                    case SkyModelType::CieGeneral: own = {"horizontal_illuminance_lx", "type", "turbidity"}; break;
                }
                for (const char* k : {"turbidity", "horizontal_illuminance_lx", "luminance_nits", "type"})
                    if (s.has(k) && std::none_of(own.begin(), own.end(), [&](const char* o) { return std::string(o) == k; }))
                        s.error(k, std::string("\"") + k + "\" does not apply to the " + *model + " sky");
            }
            d.turbidity = s.number("turbidity", 3.0);
            d.horizontalIlluminanceLx = s.number("horizontal_illuminance_lx");
            d.luminanceNits = s.number("luminance_nits");
            d.cieSkyType = s.integer("type").value_or(12);
        }
        if (f.has("sun")) {
            const Json& sun = f.get("sun");
            if (sun.is_boolean()) {
                d.sun = sun.get<bool>();
            } else if (sun.is_object()) {
                Fields o(sink_, sun, f.at("sun"), {"altitude_deg", "azimuth_deg", "normal_illuminance_lx"});
                SunOverride so;
                so.altitudeDeg = o.number("altitude_deg", {}, true).value_or(45);
                so.azimuthDeg = o.number("azimuth_deg", {}, true).value_or(180);
                so.normalIlluminanceLx = o.number("normal_illuminance_lx");
                d.sunOverride = so;
            } else {
                f.error("sun", "expected true, false or a sun object, got " + typeName(sun));
            }
        }
        d.groundReflectance = f.number("ground_reflectance", 0.2);
        d.stepMinutes = f.number("step_minutes", 15.0);
        d.pressureMbar = f.number("pressure_mbar", 1010.0);
        d.temperatureC = f.number("temperature_c", 10.0);
        d.from = readTime(f, "from");
        d.to = readTime(f, "to");
        if (sink_.count() == before && siteValid_)
            for (Diagnostic diag : validateDaylight(d, scene_.site)) {
                diag.file = sink_.file;
                sink_.diagnostics.push_back(diag);
            }
        scene_.daylight = d;
    }

    void readMaterials(const Json& j, const std::string& path) {
        if (!j.is_object()) {
            sink_.error(path, "expected an object of named materials, got " + typeName(j));
            return;
        }
        for (const auto& [name, value] : j.items()) {
            std::string p = pointer(path, name);
            Fields f(sink_, value, p, {"type", "reflectance", "roughness", "base", "transmittance"});
            if (!f.valid()) continue;
            Material m;
            m.name = name;
            auto type = f.string("type", true);
            auto notFor = [&](std::initializer_list<const char*> keys) {
                for (const char* k : keys)
                    if (f.has(k)) f.error(k, std::string("\"") + k + "\" does not apply to a " + *type + " material");
            };
            if (type == "diffuse") {
                m.type = MaterialType::Diffuse;
                m.reflectance = f.color("reflectance", true).value_or(Vec3(0.5, 0.5, 0.5));
                notFor({"roughness", "base", "transmittance"});
            } else if (type == "glossy") {
                m.type = MaterialType::Glossy;
                m.reflectance = f.color("reflectance").value_or(Vec3(0.04, 0.04, 0.04));
                m.roughness = f.number("roughness", 0.1, Range{0, 1, true, false});
                m.base = f.color("base").value_or(Vec3(0, 0, 0));
                notFor({"transmittance"});
            } else if (type == "glass") {
                m.type = MaterialType::Glass;
                m.transmittance = f.number("transmittance", 0.88, kUnit);
                notFor({"reflectance", "roughness", "base"});
            } else if (type == "mirror") {
                m.type = MaterialType::Mirror;
                m.reflectance = f.color("reflectance").value_or(Vec3(0.9, 0.9, 0.9));
                notFor({"roughness", "base", "transmittance"});
            } else if (type) {
                f.error("type", "unknown material type \"" + *type + "\" (diffuse, glossy, glass or mirror)");
            }
            scene_.materialIndex[name] = uint32_t(scene_.materials.size());
            scene_.materials.push_back(m);
        }
    }

    std::optional<uint32_t> materialRef(const Fields& f, const char* key, bool required) {
        auto name = f.string(key, required);
        if (!name) return std::nullopt;
        auto it = scene_.materialIndex.find(*name);
        if (it == scene_.materialIndex.end()) {
            f.error(key, "unknown material \"" + *name + "\"");
            return std::nullopt;
        }
        return it->second;
    }

    // {"translate": [x,y,z], "rotate_deg": a, "scale": s | [sx,sy,sz]}
    Transform readTransform(const Fields& parent, const char* key) {
        if (!parent.has(key)) return Transform();
        Fields f(sink_, parent.get(key), parent.at(key), {"translate", "rotate_deg", "scale"});
        Vec3 scale(1, 1, 1);
        if (f.has("scale")) {
            if (f.get("scale").is_number()) {
                double s = f.number("scale", 1.0, Range::positive());
                scale = Vec3(s, s, s);
            } else {
                scale = f.vec3("scale", false, Range::positive()).value_or(scale);
            }
        }
        return Transform::placement(f.vec3("translate").value_or(Vec3()), f.number("rotate_deg", 0.0)) *
               Transform::scale(scale);
    }

    TriangleMesh readMeshFile(const Fields& f, const char* key, uint32_t material) {
        auto rel = f.string(key, true);
        if (!rel) return {};
        std::filesystem::path file = std::filesystem::path(*rel).is_absolute() ? std::filesystem::path(*rel) : dir_ / *rel;
        try {
            return loadMeshFile(file, material);
        } catch (const IoError& e) {
            f.error(key, "cannot read mesh \"" + file.string() + "\": " + e.what());
        }
        return {};
    }

    std::optional<Bounds3> readMinMax(const Fields& f, const char* what) {
        auto lo = f.vec3("min", true), hi = f.vec3("max", true);
        if (!lo || !hi) return std::nullopt;
        for (int a = 0; a < 3; ++a)
            if ((*hi)[a] <= (*lo)[a]) {
                f.error("max", std::string(what) + " is empty or inverted: max " + "xyz"[a] + " " +
                                   formatNumber((*hi)[a]) + " <= min " + formatNumber((*lo)[a]));
                return std::nullopt;
            }
        return Bounds3(*lo, *hi);
    }

    void readStatic(const Json& j, const std::string& path) {
        Fields f(sink_, j, path, {"name", "room", "box", "mesh", "transform", "material", "materials", "openings", "invisible"});
        if (!f.valid()) return;
        StaticItem item;
        item.jsonPath = path;
        item.name = f.string("name", true).value_or("");
        item.invisible = f.boolean("invisible").value_or(false);
        int shapes = int(f.has("room")) + int(f.has("box")) + int(f.has("mesh"));
        if (shapes != 1) {
            sink_.error(path, shapes == 0 ? "needs one shape: \"room\", \"box\" or \"mesh\""
                                          : "has more than one shape (\"room\", \"box\", \"mesh\")");
            return;
        }
        if (f.has("room")) {
            item.kind = StaticKind::Room;
            for (const char* k : {"material", "transform"})
                if (f.has(k)) f.error(k, std::string("\"") + k + "\" does not apply to a room (use \"materials\")");
            readRoom(f, item);
        } else {
            for (const char* k : {"materials", "openings"})
                if (f.has(k)) f.error(k, std::string("\"") + k + "\" applies only to a room");
            auto mat = materialRef(f, "material", !item.invisible);
            uint32_t m = mat.value_or(0);
            if (f.has("box")) {
                item.kind = StaticKind::Box;
                if (f.has("transform")) f.error("transform", "\"transform\" applies only to a mesh");
                Fields b(sink_, f.get("box"), f.at("box"), {"min", "max"});
                if (auto box = readMinMax(b, "box")) addBox(item.mesh, *box, m);
            } else {
                item.kind = StaticKind::Mesh;
                Transform t = readTransform(f, "transform");
                item.mesh.append(readMeshFile(f, "mesh", m), t);
            }
        }
        scene_.geometry.push_back(std::move(item));
    }

    void readRoom(const Fields& f, StaticItem& item) {
        Fields r(sink_, f.get("room"), f.at("room"), {"min", "max"});
        auto box = readMinMax(r, "room");
        RoomShell room;
        if (box) room.box = *box;
        if (!f.has("materials")) f.missing("materials");
        else {
            Fields m(sink_, f.get("materials"), f.at("materials"), {"floor", "walls", "ceiling"});
            room.floorMaterial = materialRef(m, "floor", true).value_or(0);
            room.wallMaterial = materialRef(m, "walls", true).value_or(0);
            room.ceilingMaterial = materialRef(m, "ceiling", true).value_or(0);
        }
        if (auto* openings = f.array("openings"))
            for (size_t i = 0; i < openings->size(); ++i) {
                std::string p = pointer(f.at("openings"), i);
                if (auto o = readOpening((*openings)[i], p, room, box.has_value())) {
                    room.openings.push_back(*o);
                    checkOpeningOverlap(room, p);
                }
            }
        item.room = room;
        if (box) item.mesh = buildRoomShell(room);
    }

    std::optional<Opening> readOpening(const Json& j, const std::string& path, const RoomShell& room, bool haveBox) {
        Fields f(sink_, j, path, {"wall", "offset", "width", "sill", "height", "center", "size", "material"});
        if (!f.valid()) return std::nullopt;
        Opening o;
        auto wall = f.string("wall", true);
        if (!wall) return std::nullopt;
        static const std::map<std::string, Wall> walls = {{"north", Wall::North}, {"south", Wall::South},
                                                          {"east", Wall::East},   {"west", Wall::West},
                                                          {"ceiling", Wall::Ceiling}};
        auto it = walls.find(*wall);
        if (it == walls.end()) {
            f.error("wall", "unknown wall \"" + *wall + "\" (north, south, east, west or ceiling)");
            return std::nullopt;
        }
        o.wall = it->second;
        if (f.has("material")) o.material = materialRef(f, "material", true);
        size_t before = sink_.count();
        if (o.wall == Wall::Ceiling) {
            for (const char* k : {"offset", "width", "sill", "height"})
                if (f.has(k)) f.error(k, std::string("\"") + k + "\" does not apply to a ceiling opening (use center and size)");
            o.center = f.vec2("center", true).value_or(Vec2());
            o.size = f.vec2("size", true, Range::positive("m")).value_or(Vec2(1, 1));
        } else {
            for (const char* k : {"center", "size"})
                if (f.has(k)) f.error(k, std::string("\"") + k + "\" applies only to a ceiling opening");
            o.offset = f.number("offset", kNonNegative, true).value_or(0);
            o.width = f.number("width", Range::positive("m"), true).value_or(1);
            o.sill = f.number("sill", 0.0, kNonNegative);
            o.height = f.number("height", Range::positive("m"), true).value_or(1);
        }
        if (sink_.count() != before || !haveBox) return std::nullopt;
        WallFrame wf = wallFrame(room.box, o.wall);
        auto rect = openingRect(room.box, o);
        const double eps = 1e-9;
        if (rect[0] < -eps || rect[2] > wf.length + eps || rect[1] < -eps || rect[3] > wf.height + eps) {
            sink_.error(path, "opening [" + formatNumber(rect[0]) + ", " + formatNumber(rect[2]) + "] x [" +
                                  formatNumber(rect[1]) + ", " + formatNumber(rect[3]) + "] does not fit in the " + *wall +
                                  (o.wall == Wall::Ceiling ? "" : " wall") + " (" + formatNumber(wf.length) + " x " +
                                  formatNumber(wf.height) + " m)");
            return std::nullopt;
        }
        return o;
    }

    void checkOpeningOverlap(const RoomShell& room, const std::string& path) {
        const Opening& o = room.openings.back();
        auto a = openingRect(room.box, o);
        for (size_t i = 0; i + 1 < room.openings.size(); ++i) {
            if (room.openings[i].wall != o.wall) continue;
            auto b = openingRect(room.box, room.openings[i]);
            if (a[0] < b[2] && b[0] < a[2] && a[1] < b[3] && b[1] < a[3])
                sink_.error(path, "overlaps opening " + std::to_string(i) + " on the same wall");
        }
    }

    void readEmitter(const Json& j, const std::string& path, int entity) {
        Fields f(sink_, j, path, {"name", "shape", "center", "normal", "size", "up", "radius", "flux_lm", "cct_k"});
        if (!f.valid()) return;
        Emitter e;
        e.jsonPath = path;
        e.entity = entity;
        e.name = f.string("name", true).value_or("");
        auto shape = f.string("shape", true);
        if (shape == "rect") e.shape = EmitterShape::Rect;
        else if (shape == "disk") e.shape = EmitterShape::Disk;
        else if (shape == "sphere") e.shape = EmitterShape::Sphere;
        else if (shape) f.error("shape", "unknown emitter shape \"" + *shape + "\" (rect, disk or sphere)");
        e.center = f.vec3("center", true).value_or(Vec3());
        e.fluxLm = f.number("flux_lm", kNonNegative, true).value_or(0);
        e.cctK = f.number("cct_k", 4000.0, Range::closed(1000, 40000, "K"));
        if (e.shape == EmitterShape::Sphere) {
            for (const char* k : {"normal", "size", "up"})
                if (f.has(k)) f.error(k, std::string("\"") + k + "\" does not apply to a sphere (it emits all round)");
        } else {
            e.normal = f.direction("normal").value_or(Vec3(0, 0, -1));
        }
        if (e.shape == EmitterShape::Rect) {
            e.size = f.vec2("size", true, Range::positive("m")).value_or(Vec2(1, 1));
            if (f.has("radius")) f.error("radius", "\"radius\" does not apply to a rect (use size)");
            Vec3 up = f.direction("up").value_or(std::abs(e.normal.y) > 0.999 ? Vec3(1, 0, 0) : Vec3(0, 1, 0));
            if (length(cross(up, e.normal)) < 1e-6) {
                f.error(f.has("up") ? "up" : "normal", "\"up\" is parallel to \"normal\"");
            } else {
                e.up = normalize(up - e.normal * dot(up, e.normal));  // orthogonalize
            }
        } else if (shape) {
            e.radius = f.number("radius", Range::positive("m"), true).value_or(0.1);
            if (f.has("size")) f.error("size", "\"size\" does not apply to a " + *shape + " (use radius)");
            if (f.has("up") && e.shape == EmitterShape::Disk) f.error("up", "\"up\" does not apply to a disk");
        }
        int index = int(scene_.emitters.size());
        scene_.emitters.push_back(e);
        if (entity >= 0) scene_.entities[entity].emitters.push_back(index);
    }

    std::optional<Region> readRegion(const Json& j, const std::string& path, double initialRotation) {
        Fields f(sink_, j, path, {"min", "max", "rotations", "rotation_range"});
        if (!f.valid()) return std::nullopt;
        Region r;
        auto lo = f.vec2("min", true), hi = f.vec2("max", true);
        if (lo && hi) {
            r.lo = *lo, r.hi = *hi;
            for (int a = 0; a < 2; ++a)
                if ((*hi)[a] < (*lo)[a])
                    f.error("max", std::string("region is inverted: max ") + "xy"[a] + " " + formatNumber((*hi)[a]) +
                                       " < min " + formatNumber((*lo)[a]));
        }
        if (f.has("rotations") && f.has("rotation_range")) {
            sink_.error(path, "give either \"rotations\" or \"rotation_range\", not both");
        } else if (auto* rots = f.array("rotations")) {
            if (rots->empty()) f.error("rotations", "the set of rotations is empty");
            for (size_t i = 0; i < rots->size(); ++i) {
                if (!(*rots)[i].is_number()) {
                    sink_.error(pointer(f.at("rotations"), i), "expected a number, got " + typeName((*rots)[i]));
                    continue;
                }
                r.rotationsDeg.push_back((*rots)[i].get<double>());
            }
        } else if (f.has("rotation_range")) {
            if (auto range = f.vec2("rotation_range")) {
                if (range->y < range->x)
                    f.error("rotation_range", "rotation range is inverted: " + formatNumber(range->y) + " < " +
                                                  formatNumber(range->x));
                r.continuousRotation = true;
                r.rotationMinDeg = range->x, r.rotationMaxDeg = range->y;
            }
        } else {
            r.rotationsDeg = {initialRotation};  // no rotation given: the entity keeps its initial one
        }
        return r;
    }

    void readEntity(const Json& j, const std::string& path, int parent) {
        Fields f(sink_, j, path,
                 {"name", "children", "parts", "position", "rotation", "placement", "fixed", "fronts", "samplers", "emitters"});
        if (!f.valid()) return;
        int index = int(scene_.entities.size());
        scene_.entities.emplace_back();
        {
            Entity& e = scene_.entities.back();
            e.jsonPath = path;
            e.parent = parent;
            e.name = f.string("name", true).value_or("#" + std::to_string(index));
            if (e.name.find('.') != std::string::npos)
                f.error("name", "entity names must not contain '.' (it separates levels in dotted paths)");
            e.path = parent >= 0 ? scene_.entities[parent].path + "." + e.name : e.name;
            if (f.has("position")) {
                const Json& p = f.get("position");
                auto n = readNumbers(sink_, p, f.at("position"), p.is_array() && p.size() == 3 ? 3 : 2);
                if (n) e.position = Vec3((*n)[0], (*n)[1], n->size() == 3 ? (*n)[2] : 0.0);
            }
            e.rotationDeg = f.number("rotation", 0.0);
        }
        if (parent >= 0) scene_.entities[parent].children.push_back(index);

        bool fixed = f.boolean("fixed").value_or(false);
        if (f.has("placement") && !fixed) {
            Fields p(sink_, f.get("placement"), f.at("placement"), {"regions"});
            if (auto* regions = p.array("regions", true)) {
                if (regions->empty()) p.error("regions", "placement has no regions");
                for (size_t i = 0; i < regions->size(); ++i)
                    if (auto r = readRegion((*regions)[i], pointer(p.at("regions"), i), scene_.entities[index].rotationDeg))
                        scene_.entities[index].regions.push_back(*r);
            }
        }
        if (auto* fronts = f.array("fronts")) {
            std::vector<Vec2> list;
            if (fronts->empty()) f.error("fronts", "needs at least one front direction");
            for (size_t i = 0; i < fronts->size(); ++i) {
                auto n = readNumbers(sink_, (*fronts)[i], pointer(f.at("fronts"), i), 2);
                if (!n) continue;
                Vec2 v((*n)[0], (*n)[1]);
                if (length(v) < 1e-12) sink_.error(pointer(f.at("fronts"), i), "front direction must not be zero");
                else list.push_back(v * (1.0 / length(v)));
            }
            if (!list.empty()) scene_.entities[index].fronts = list;
        }
        if (auto* parts = f.array("parts"))
            for (size_t i = 0; i < parts->size(); ++i) readPart((*parts)[i], pointer(f.at("parts"), i), index);
        if (auto* emitters = f.array("emitters"))
            for (size_t i = 0; i < emitters->size(); ++i) readEmitter((*emitters)[i], pointer(f.at("emitters"), i), index);
        if (auto* samplers = f.array("samplers"))
            for (size_t i = 0; i < samplers->size(); ++i) readSampler((*samplers)[i], pointer(f.at("samplers"), i), index);
        if (auto* children = f.array("children"))
            for (size_t i = 0; i < children->size(); ++i) readEntity((*children)[i], pointer(f.at("children"), i), index);
    }

    void readPart(const Json& j, const std::string& path, int entity) {
        Fields f(sink_, j, path, {"box", "mesh", "preset", "transform", "size", "center", "material", "materials"});
        if (!f.valid()) return;
        int shapes = int(f.has("box")) + int(f.has("mesh")) + int(f.has("preset"));
        if (shapes != 1) {
            sink_.error(path, shapes == 0 ? "needs one of \"box\", \"mesh\" or \"preset\""
                                          : "has more than one of \"box\", \"mesh\", \"preset\"");
            return;
        }
        PartInfo info;
        TriangleMesh mesh;
        if (f.has("box")) {
            for (const char* k : {"transform", "size", "center", "materials"})
                if (f.has(k)) f.error(k, std::string("\"") + k + "\" does not apply to a box part (put size and center in \"box\")");
            info.kind = "box";
            info.material = materialRef(f, "material", true).value_or(0);
            Fields b(sink_, f.get("box"), f.at("box"), {"size", "center"});
            auto size = b.vec3("size", true, Range::positive("m"));
            if (size) {
                Vec3 c = b.vec3("center").value_or(Vec3(0, 0, size->z / 2));
                addBox(mesh, Bounds3(c - *size * 0.5, c + *size * 0.5), info.material);
            }
        } else if (f.has("mesh")) {
            for (const char* k : {"size", "center", "materials"})
                if (f.has(k)) f.error(k, std::string("\"") + k + "\" does not apply to a mesh part (use \"transform\")");
            info.kind = "mesh";
            info.material = materialRef(f, "material", true).value_or(0);
            Transform t = readTransform(f, "transform");
            mesh.append(readMeshFile(f, "mesh", info.material), t);
        } else {
            if (f.has("transform")) f.error("transform", "\"transform\" does not apply to a preset (use size, center)");
            auto name = f.string("preset", true);
            const PresetInfo* preset = name ? findPreset(*name) : nullptr;
            if (name && !preset) {
                std::string known;
                for (const auto& p : presetCatalog()) known += (known.empty() ? "" : ", ") + p.name;
                f.error("preset", "unknown preset \"" + *name + "\" (" + known + ")");
                return;
            }
            if (!preset) return;
            info.kind = preset->name;
            std::map<std::string, uint32_t> slots;
            auto body = materialRef(f, "material", !f.has("materials"));
            if (body) slots[preset->slots.front()] = *body;
            if (f.has("materials")) {
                Fields m(sink_, f.get("materials"), f.at("materials"), preset->slots, "an object of material slots");
                for (const auto& slot : preset->slots)
                    if (auto mat = materialRef(m, slot.c_str(), false)) slots[slot] = *mat;
                if (!slots.count(preset->slots.front()))
                    m.error(preset->slots.front().c_str(), "missing the body material (give \"material\" or \"materials\"." +
                                                               preset->slots.front() + ")");
            }
            info.material = slots.count(preset->slots.front()) ? slots[preset->slots.front()] : 0;
            Vec3 size = f.vec3("size", false, Range::positive("m")).value_or(preset->defaultSize);
            Vec3 center = f.vec3("center").value_or(Vec3(0, 0, size.z / 2));
            mesh.append(buildPreset(*preset, size, slots), Transform::translate(center - Vec3(0, 0, size.z / 2)));
        }
        info.bounds = mesh.bounds();
        Entity& e = scene_.entities[entity];
        e.parts.push_back(info);
        e.mesh.append(mesh);
    }

    void readSampler(const Json& j, const std::string& path, int entity) {
        Fields f(sink_, j, path,
                 {"name", "type", "target", "tolerance", "weight", "center", "normal", "size", "up", "grid", "origin",
                  "direction", "fov_deg", "strata", "axes", "points"});
        if (!f.valid()) return;
        LightSamplerSpec s;
        s.jsonPath = path;
        s.entity = entity;
        s.name = f.string("name", true).value_or("");
        auto type = f.string("type", true);
        std::vector<const char*> own;
        if (type == "planar") {
            s.type = LightSamplerType::Planar;
            own = {"center", "normal", "size", "up", "grid"};
            s.center = f.vec3("center", true).value_or(Vec3());
            s.normal = f.direction("normal").value_or(Vec3(0, 0, 1));
            s.up = f.direction("up").value_or(Vec3(0, 1, 0));
            if (length(cross(s.up, s.normal)) < 1e-6)
                f.error(f.has("up") ? "up" : "normal", "\"up\" is parallel to \"normal\"");
            s.size = f.vec2("size", true).value_or(Vec2(1, 1));
            if (f.has("size") && (s.size.x <= 0 || s.size.y <= 0))
                f.error("size", "sampler has zero area: size " + formatNumber(s.size.x) + " x " + formatNumber(s.size.y));
            if (f.has("grid")) {
                auto g = readNumbers(sink_, f.get("grid"), f.at("grid"), 2, Range::closed(1, 1024));
                if (g) {
                    if ((*g)[0] != std::floor((*g)[0]) || (*g)[1] != std::floor((*g)[1]))
                        f.error("grid", "grid counts must be whole numbers");
                    s.grid = {int((*g)[0]), int((*g)[1])};
                }
            }
        } else if (type == "directional") {
            s.type = LightSamplerType::Directional;
            own = {"origin", "direction", "fov_deg", "strata", "up"};
            s.origin = f.vec3("origin", true).value_or(Vec3());
            s.direction = f.direction("direction", true).value_or(Vec3(0, -1, 0));
            s.fovDeg = f.number("fov_deg", 60.0, Range{0, 180, true, true, "deg"});
            s.strata = f.integer("strata", Range::closed(1, 256)).value_or(8);
            Vec3 fallbackUp = std::abs(s.direction.z) > 0.999 ? Vec3(0, 1, 0) : Vec3(0, 0, 1);
            s.up = f.direction("up").value_or(fallbackUp);
            if (length(cross(s.up, s.direction)) < 1e-6) f.error("up", "\"up\" is parallel to \"direction\"");
        } else if (type == "volume") {
            s.type = LightSamplerType::Volume;
            own = {"center", "axes", "points"};
            s.center = f.vec3("center", true).value_or(Vec3());
            if (auto* axes = f.array("axes", true)) {
                if (axes->size() != 3) f.error("axes", "expected three side vectors, got " + std::to_string(axes->size()));
                else {
                    bool ok = true;
                    for (size_t i = 0; i < 3; ++i) {
                        auto n = readNumbers(sink_, (*axes)[i], pointer(f.at("axes"), i), 3);
                        if (n) s.axes[i] = Vec3((*n)[0], (*n)[1], (*n)[2]);
                        else ok = false;
                    }
                    if (ok && std::abs(dot(cross(s.axes[0], s.axes[1]), s.axes[2])) < 1e-12)
                        f.error("axes", "the box has zero volume (side vectors are degenerate)");
                }
            }
            s.points = f.integer("points", Range::closed(1, 1000000)).value_or(200);
        } else if (type) {
            f.error("type", "unknown sampler type \"" + *type + "\" (planar, directional or volume)");
        }
        if (type)
            for (const char* k : {"center", "normal", "size", "up", "grid", "origin", "direction", "fov_deg", "strata", "axes", "points"})
                if (f.has(k) && std::find_if(own.begin(), own.end(), [&](const char* o) { return std::string(o) == k; }) == own.end() &&
                    !own.empty())
                    f.error(k, std::string("\"") + k + "\" does not apply to a " + *type + " sampler");
        readTarget(f, s);
        s.weight = f.number("weight", 1.0, kNonNegative);
        int index = int(scene_.samplers.size());
        scene_.samplers.push_back(s);
        if (entity >= 0) scene_.entities[entity].samplers.push_back(index);
    }

    void readTarget(const Fields& f, LightSamplerSpec& s) {
        const char* unit = s.unit();
        if (!f.has("target")) f.missing("target");
        else {
            const Json& t = f.get("target");
            if (!t.is_array() || t.size() != 2) {
                f.error("target", "expected [min, max], got " + typeName(t));
            } else {
                bool ok = true;
                auto bound = [&](size_t i, double fallback) {
                    if (t[i].is_null()) return fallback;
                    if (!t[i].is_number()) {
                        sink_.error(pointer(f.at("target"), i), "expected a number or null, got " + typeName(t[i]));
                        ok = false;
                        return fallback;
                    }
                    return t[i].get<double>();
                };
                s.targetMin = bound(0, 0.0);
                s.targetMax = bound(1, kInf);
                if (ok && s.targetMax < s.targetMin)
                    f.error("target", "target range is reversed: max " + formatNumber(s.targetMax) + " < min " +
                                          formatNumber(s.targetMin) + " " + unit);
                else if (ok && s.targetMax < 0)
                    f.error("target", "impossible target: max " + formatNumber(s.targetMax) + " " + unit +
                                          " is below 0 and no light level can meet it");
                else if (ok && s.targetMin < 0)
                    f.error("target", "target min " + formatNumber(s.targetMin) + " " + unit + " is negative");
            }
        }
        // Default tolerance (the paper's L_rej): the width of the range, or half the
        // finite bound when the range is open or a single value.
        double width = s.targetMax - s.targetMin;
        double fallback = std::isfinite(width) && width > 0 ? width : 0.5 * (std::isfinite(s.targetMax) ? s.targetMax : s.targetMin);
        if (!(fallback > 0)) fallback = 1;
        s.tolerance = f.number("tolerance", fallback, Range::positive(unit));
    }

    int entityRef(const Fields& f, const char* key, bool allowRoom) {
        auto name = f.string(key, true);
        if (!name) return -1;
        if (*name == "room") {
            if (allowRoom) return kRoomEntity;
            f.error(key, "\"room\" is only valid as \"b\" of an alignment constraint");
            return -1;
        }
        int e = scene_.findEntity(*name);
        if (e < 0) {
            // A bare name may name a nested entity when it is unique.
            for (size_t i = 0; i < scene_.entities.size(); ++i)
                if (scene_.entities[i].name == *name) {
                    if (e >= 0) {
                        f.error(key, "\"" + *name + "\" is ambiguous: use its dotted path (e.g. \"" + scene_.entities[i].path + "\")");
                        return -1;
                    }
                    e = int(i);
                }
        }
        if (e < 0 && !entitiesIncomplete_) f.error(key, "unknown entity \"" + *name + "\"");
        return e;
    }

    void readConstraint(const Json& j, const std::string& path) {
        Fields f(sink_, j, path, {"type", "a", "b", "tolerance_deg", "min", "max", "tolerance", "weight"});
        if (!f.valid()) return;
        ConstraintSpec c;
        c.jsonPath = path;
        auto type = f.string("type", true);
        if (!type) return;
        c.weight = f.number("weight", 1.0, kNonNegative);
        auto only = [&](std::initializer_list<const char*> keys) {
            for (const char* k : {"a", "b", "tolerance_deg", "min", "max", "tolerance"})
                if (f.has(k) && std::find_if(keys.begin(), keys.end(), [&](const char* o) { return std::string(o) == k; }) == keys.end())
                    f.error(k, std::string("\"") + k + "\" does not apply to a " + *type + " constraint");
        };
        auto angle = [&] { c.toleranceDeg = f.number("tolerance_deg", 10.0, Range{0, 180, true, false, "deg"}); };
        auto distances = [&] {
            auto lo = f.number("min", kNonNegative, true);
            // "max": null leaves the range open above.
            auto hi = f.has("max") && f.get("max").is_null() ? std::optional<double>(kInf) : f.number("max", kNonNegative, true);
            if (lo && hi && *hi < *lo)
                f.error("max", "distance range is reversed: max " + formatNumber(*hi) + " < min " + formatNumber(*lo) + " m");
            c.minDistance = lo.value_or(0), c.maxDistance = hi.value_or(kInf);
            c.distanceTolerance = f.number("tolerance", Range::positive("m"));
        };
        if (*type == "overlap") {
            c.type = ConstraintType::Overlap;
            only({"tolerance"});
            scene_.overlapTolerance = f.number("tolerance", 0.05, Range{0, 1, true, false});
            scene_.constraints.push_back(c);
            return;
        }
        if (*type == "alignment") {
            c.type = ConstraintType::Alignment;
            only({"a", "b", "tolerance_deg"});
            angle();
        } else if (*type == "distance") {
            c.type = ConstraintType::Distance;
            only({"a", "b", "min", "max", "tolerance"});
            distances();
        } else if (*type == "focus") {
            c.type = ConstraintType::Focus;
            only({"a", "b", "tolerance_deg"});
            angle();
        } else if (*type == "conversation") {
            c.type = ConstraintType::Conversation;
            only({"a", "b", "min", "max", "tolerance_deg", "tolerance"});
            angle();
            distances();
        } else {
            f.error("type", "unknown constraint type \"" + *type +
                                "\" (alignment, distance, focus, conversation or overlap)");
            return;
        }
        c.a = entityRef(f, "a", false);
        c.b = entityRef(f, "b", c.type == ConstraintType::Alignment);
        if (c.a >= 0 && c.a == c.b) f.error("b", "a constraint needs two different entities");
        scene_.constraints.push_back(c);
    }

    void checkUniqueNames() {
        std::map<std::string, std::string> seen;
        auto unique = [&](const std::string& kind, const std::string& name, const std::string& path) {
            if (name.empty()) return;
            auto [it, fresh] = seen.emplace(kind + "\n" + name, path);
            if (!fresh) sink_.error(pointer(path, "name"), "duplicate " + kind + " name \"" + name + "\" (also at " + it->second + ")");
        };
        for (const auto& g : scene_.geometry) unique("geometry", g.name, g.jsonPath);
        for (const auto& e : scene_.emitters) unique("emitter", e.name, e.jsonPath);
        for (const auto& e : scene_.entities) unique("entity", e.path, e.jsonPath);
        for (const auto& s : scene_.samplers) unique("sampler", s.name, s.jsonPath);
    }

    void buildVoxels() {
        for (auto& e : scene_.entities)
            if (e.hasGeometry()) e.voxels = voxelizeSolid(e.mesh, options_.voxelSize);
        for (auto& g : scene_.geometry)
            if (g.kind != StaticKind::Room) g.voxels = voxelizeSolid(g.mesh, options_.voxelSize);
    }

    LoadOptions options_;
    bool entitiesIncomplete_ = false;
    bool siteValid_ = true;
    DiagnosticSink sink_;
    Scene scene_;
    std::filesystem::path dir_;
};

}  // namespace

Scene loadScene(const std::filesystem::path& file, const LoadOptions& options) {
    return Loader(file, options).load();
}

}  // namespace luxplan::io
