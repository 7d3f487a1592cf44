// Scene file -> scene model. Reads each section with `Fields`, which reports wrong
// types, unknown keys and bad ranges with their JSON path; names are resolved after
// all definitions are read, so every problem of a file is reported in one run.
#include <luxplan/io/scene_loader.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include <luxplan/constraints/constraint_type.h>
#include <luxplan/daylight/datetime.h>
#include <luxplan/daylight/daylight.h>
#include <luxplan/daylight/weather.h>
#include <luxplan/emitters/emitter_shape.h>
#include <luxplan/emitters/photometric_emitter.h>
#include <luxplan/json/fields.h>
#include <luxplan/json/parse.h>
#include <luxplan/core/limits.h>
#include <luxplan/core/parallel.h>
#include <luxplan/lightsamplers/sampler_type.h>
#include <luxplan/io/mesh_io.h>
#include <luxplan/io/photometry_io.h>
#include <luxplan/scene/presets.h>
#include <luxplan/scene/room.h>

namespace luxplan::io {
namespace {

using json::DiagnosticSink;
using json::Fields;
using json::Json;
using json::Range;
using json::formatNumber;
using json::pointer;
using json::typeName;

const Range kUnit = Range::closed(0, 1);
const Range kNonNegative = Range::atLeast(0);
const Range kCoordinate = json::coordinateRange();
const Range kLength = json::lengthRange();
const Range kOffset = json::offsetRange();
const Range kScale = Range::positive().limitedTo(limits::kMaxScale);
const Range kWeight = json::weightRange();

// "a rect emitter", "an alignment constraint".
std::string article(const std::string& noun) {
    return (std::string("aeiou").find(noun.empty() ? 'x' : noun[0]) != std::string::npos ? "an " : "a ") + noun;
}

// ---- the loader ----
//
// Objects whose keys depend on a kind ("shape", "type", "model") read their common
// keys, then the kind's own with one function per kind; finish() then reports what
// no function read. A family's keys are what its kinds' functions ask for on an empty
// object (json::probeKeys), so a key read by one kind is reported on another as not
// applying to it.

class Loader {
public:
    Loader(const std::filesystem::path& file, const LoadOptions& options) : options_(options) {
        sink_.file = file.string();
        scene_.file = file;
        dir_ = file.parent_path();
    }

    Scene load() {
        auto text = json::readInputFile(sink_, scene_.file, limits::kMaxJsonFileBytes);
        if (!text) throw SceneError(sink_.diagnostics);
        auto root = json::parseJson(*text, sink_);
        if (!root) throw SceneError(sink_.diagnostics);
        try {
            readRoot(*root);
            if (!sink_.count()) checkScene();
            if (!sink_.count()) buildVoxels();
        } catch (const SceneError&) {
            throw;
        } catch (const std::exception& e) {
            // A library's exception (or one of ours) still names the file.
            sink_.error("", std::string("cannot load the scene: ") + e.what());
        }
        if (sink_.count()) throw SceneError(distinct(sink_.diagnostics));
        return std::move(scene_);
    }

private:
    // The same problem at the same place once: a template used by six entities
    // reports its own mistakes once.
    static std::vector<Diagnostic> distinct(const std::vector<Diagnostic>& all) {
        std::vector<Diagnostic> kept;
        for (const Diagnostic& d : all)
            if (std::none_of(kept.begin(), kept.end(), [&](const Diagnostic& k) { return k.str() == d.str(); })) kept.push_back(d);
        return kept;
    }

    // The keys every kind of a family reads, for finish().
    template <class Kind, class ReadKind>
    std::vector<std::string> familyKeys(const std::vector<Kind>& kinds, ReadKind readKind) {
        std::vector<std::vector<std::string>> lists;
        for (const Kind& k : kinds) lists.push_back(json::probeKeys([&](const Fields& f) { readKind(f, k); }));
        return json::unionKeys(lists);
    }

    void readRoot(const Json& root) {
        Fields f(sink_, root, "", "a scene object");
        if (!f.valid()) return;
        if (auto v = f.integer("luxplan", {}, true); v && *v != 1)
            f.error("luxplan", "unsupported format version " + std::to_string(*v) + " (this luxplan reads version 1)");
        scene_.name = f.string("name").value_or(scene_.file.stem().string());
        size_t beforeSite = sink_.count();
        if (f.has("site")) readSite(f.get("site"), f.at("site"));
        siteValid_ = sink_.count() == beforeSite;
        if (f.has("daylight")) readDaylight(f.get("daylight"), f.at("daylight"));
        readMaintenanceFactor(f);
        if (f.has("materials")) readMaterials(f.get("materials"), f.at("materials"));
        if (auto* a = f.array("geometry"))
            for (size_t i = 0; i < a->size(); ++i) readStatic((*a)[i], pointer(f.at("geometry"), i));
        if (auto* a = f.array("luminaires"))
            for (size_t i = 0; i < a->size(); ++i) readEmitter((*a)[i], pointer(f.at("luminaires"), i), -1);
        if (f.has("templates")) readTemplates(f.get("templates"), f.at("templates"));
        size_t before = sink_.count();
        if (auto* a = f.array("entities"))
            for (size_t i = 0; i < a->size(); ++i) readEntity((*a)[i], pointer(f.at("entities"), i), -1);
        // Constraints naming an entity that failed to load would only repeat that error.
        entitiesIncomplete_ = sink_.count() != before;
        if (auto* a = f.array("samplers"))
            for (size_t i = 0; i < a->size(); ++i) readSampler((*a)[i], pointer(f.at("samplers"), i), -1);
        if (auto* a = f.array("constraints"))
            for (size_t i = 0; i < a->size(); ++i) readConstraint((*a)[i], pointer(f.at("constraints"), i), -1);
        for (const ScopedConstraint& c : entityConstraints_) readConstraint(c.json, c.path, c.entity);
        if (auto* a = f.array("cameras"))
            for (size_t i = 0; i < a->size(); ++i) readCamera((*a)[i], pointer(f.at("cameras"), i));
        if (f.has("objective")) {
            Fields o(sink_, f.get("objective"), f.at("objective"));
            scene_.objective.lightingWeight = o.number("lighting_weight", 0.5, kUnit);
            o.finish();
        }
        readOptimizer(f.has("optimizer") ? &f.get("optimizer") : nullptr, f.at("optimizer"));
        f.finish();
        checkUniqueNames();
    }

    // "maintenance_factor" (EN 12464-1): the share of the luminaires' new light left when
    // they are due for maintenance, in (0, 1]; absent, 1 (the light as new).
    void readMaintenanceFactor(const Fields& f) {
        auto mf = f.number("maintenance_factor");
        if (!mf) return;
        if (*mf > 0 && *mf <= 1) {
            scene_.maintenanceFactor = *mf;
            return;
        }
        std::string message = "maintenance factor " + formatNumber(*mf) +
                              " outside (0, 1]: the share of the luminaires' new light left at maintenance, e.g. 0.8";
        if (*mf > 1 && *mf <= 100) message += " (a fraction, not a percentage: " + formatNumber(*mf) + "% is " + formatNumber(*mf / 100) + ")";
        f.error("maintenance_factor", message);
    }

    void readCamera(const Json& j, const std::string& path) {
        Fields f(sink_, j, path);
        if (!f.valid()) return;
        SceneCamera c;
        c.jsonPath = path;
        c.name = scopedName(f, -1);
        auto eye = f.vec3("eye", true, kCoordinate);
        auto target = f.vec3("target", true, kCoordinate);
        c.fovDeg = f.number("fov_deg", 60.0, Range{0, 180, true, true, "deg"});
        f.finish();
        if (!eye || !target) return;
        if (length(*target - *eye) < 1e-6) {
            f.error("target", "the camera's target is its eye: it looks nowhere");
            return;
        }
        c.eye = *eye, c.target = *target;
        scene_.cameras.push_back(c);
    }

    // The settings' one table (settings_table.h), with the command line's --set over the file's keys.
    void readOptimizer(const Json* j, const std::string& path) {
        const std::vector<SettingOverride>& set = options_.settings;
        if (set.empty() || (j && !j->is_object())) {
            if (!j) return;
            Fields o(sink_, *j, path);
            readSettings(o, scene_.optimizer);
            o.finish();
            return;
        }
        Json merged = j ? *j : Json::object();
        std::map<std::string, std::string> keyPaths;
        for (const SettingOverride& o : set) {
            merged[o.key] = o.value;
            keyPaths[o.key] = "--set " + o.key + "=" + (o.value.is_string() ? o.value.get<std::string>() : o.value.dump());
        }
        Fields o(sink_, merged, path, keyPaths);
        readSettings(o, scene_.optimizer);
        o.finish();
    }

    void readSite(const Json& j, const std::string& path) {
        Fields f(sink_, j, path);
        // Which of the two a weather file's LOCATION must agree with (readWeather).
        siteLatitudeGiven_ = f.valid() && j.contains("latitude");
        siteLongitudeGiven_ = f.valid() && j.contains("longitude");
        scene_.site.latitudeDeg = f.number("latitude", 0.0, Range::closed(-90, 90, "deg"));
        scene_.site.longitudeDeg = f.number("longitude", 0.0, Range::closed(-180, 180, "deg"));
        scene_.site.northDeg = f.number("north_deg", 0.0, Range::closed(-360, 360, "deg"));
        f.finish();
    }

    std::optional<DateTime> readTime(const Fields& f, const char* key) {
        auto text = f.string(key);
        if (!text) return std::nullopt;
        std::string why;
        auto t = parseIso8601(*text, &why);
        if (!t) f.error(key, why);
        return t;
    }

    // The keys of one sky model.
    static void readSkyModel(const Fields& s, SkyModelType model, DaylightParams& d) {
        switch (model) {
            case SkyModelType::Preetham: d.turbidity = s.number("turbidity", 3.0); break;
            case SkyModelType::CieOvercast: d.horizontalIlluminanceLx = s.number("horizontal_illuminance_lx"); break;
            case SkyModelType::Uniform: d.luminanceNits = s.number("luminance_nits"); break;
            case SkyModelType::Perez: break;  // each hour's sky from the weather file
            case SkyModelType::CieGeneral:
                d.horizontalIlluminanceLx = s.number("horizontal_illuminance_lx");
                d.cieSkyType = s.integer("type").value_or(12);
                d.turbidity = s.number("turbidity", 3.0);
                break;
        }
    }

    // Types, units and keys here; the cross-field rules (what each sky model needs, the
    // time interval) are the daylight module's validateDaylight(), run once this passes.
    void readDaylight(const Json& j, const std::string& path) {
        size_t before = sink_.count();
        Fields f(sink_, j, path);
        if (!f.valid()) return;
        DaylightParams d;
        if (!f.has("sky")) f.missing("sky");
        else {
            Fields s(sink_, f.get("sky"), f.at("sky"));
            auto model = s.string("model", true);
            auto parsed = model ? skyModelNames().parse(*model) : std::nullopt;
            if (model && !parsed) s.error("model", skyModelNames().unknown("sky model", *model));
            static const std::vector<std::string> family = familyKeys(
                skyModelNames().entries, [](const Fields& k, const auto& e) { DaylightParams p; readSkyModel(k, e.first, p); });
            if (parsed) {
                d.model = *parsed;
                readSkyModel(s, d.model, d);
                s.finish("the " + *model + " sky", family);
            } else if (!model) {
                s.finish("", family);
            }
        }
        if (f.has("sun")) {
            const Json& sun = f.get("sun");
            if (sun.is_boolean()) {
                d.sun = sun.get<bool>();
            } else if (sun.is_object()) {
                Fields o(sink_, sun, f.at("sun"));
                SunOverride so;
                so.altitudeDeg = o.number("altitude_deg", {}, true).value_or(45);
                so.azimuthDeg = o.number("azimuth_deg", {}, true).value_or(180);
                so.normalIlluminanceLx = o.number("normal_illuminance_lx");
                d.sunOverride = so;
                o.finish();
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
        if (auto rel = f.string("weather")) readWeather(f, *rel, d);
        if (f.has("occupied")) readOccupied(f.get("occupied"), f.at("occupied"), d.occupied);
        f.finish();
        if (sink_.count() == before && siteValid_)
            for (Diagnostic diag : validateDaylight(d, scene_.site)) {
                diag.file = sink_.file;
                sink_.diagnostics.push_back(diag);
            }
        scene_.daylight = d;
    }

    // "weather": an EPW file (relative to the scene's folder); its errors keep their own
    // FILE:LINE. The site comes from the file: a scene's "site" may only repeat it.
    void readWeather(const Fields& f, const std::string& rel, DaylightParams& d) {
        const std::filesystem::path file = std::filesystem::path(rel).is_absolute() ? std::filesystem::path(rel) : dir_ / rel;
        try {
            d.weather = std::make_shared<const WeatherFile>(readEpw(file));
        } catch (const IoError& e) {
            f.error("weather", e.what());
            return;
        }
        if (d.model != SkyModelType::Perez)
            f.error("weather", "a weather file gives the hours of the \"perez\" sky; sky model \"" +
                                   std::string(skyModelNames().name(d.model)) + "\" does not use it");
        // Its hours are the steps: one per hour of the file.
        if (f.has("step_minutes"))
            f.error("step_minutes", "\"step_minutes\" does not apply with a weather file (its hours are the time steps)");
        const WeatherFile& w = *d.weather;
        const std::string name = file.filename().string();
        auto agree = [&](const char* key, bool given, double& site, double fromFile) {
            if (!given) {
                site = fromFile;
                return;
            }
            double diff = std::abs(site - fromFile);
            if (std::string(key) == "longitude") diff = std::min(diff, 360 - diff);  // across the date line
            if (diff > 0.1 + 1e-9)
                sink_.error(std::string("/site/") + key, formatNumber(site) + " disagrees with " + name + "'s LOCATION " + key +
                                                             " " + formatNumber(fromFile) + " by more than 0.1 degree");
        };
        agree("latitude", siteLatitudeGiven_, scene_.site.latitudeDeg, w.latitudeDeg);
        agree("longitude", siteLongitudeGiven_, scene_.site.longitudeDeg, w.longitudeDeg);
    }

    // "occupied": {"hours": [start, end], "weekdays": [ISO weekdays]}, each optional.
    void readOccupied(const Json& j, const std::string& path, DaylightParams::Occupancy& o) {
        Fields f(sink_, j, path);
        if (!f.valid()) return;
        if (auto h = f.numbers("hours", 2, Range::closed(0, 24, "h"))) {
            if ((*h)[0] < (*h)[1]) o.hours = {(*h)[0], (*h)[1]};
            else
                f.error("hours", "the first hour " + formatNumber((*h)[0]) + " must come before the second " +
                                     formatNumber((*h)[1]) + " (hours of one day, e.g. [8, 18])");
        }
        if (const Json* a = f.array("weekdays")) {
            if (a->empty()) f.error("weekdays", "no weekday: name at least one (1 = Monday .. 7 = Sunday)");
            std::vector<int> days;
            for (size_t i = 0; i < a->size(); ++i) {
                const Json& v = (*a)[i];
                const std::string at = pointer(f.at("weekdays"), i);
                if (!v.is_number() || v.get<double>() != std::floor(v.get<double>()) || v.get<double>() < 1 || v.get<double>() > 7) {
                    sink_.error(at, "expected a weekday 1 (Monday) .. 7 (Sunday), got " +
                                        (v.is_number() ? formatNumber(v.get<double>()) : typeName(v)));
                    continue;
                }
                const int day = v.get<int>();
                if (std::find(days.begin(), days.end(), day) != days.end())
                    sink_.error(at, "weekday " + std::to_string(day) + " repeated");
                else days.push_back(day);
            }
            if (!a->empty() && days.size() == a->size()) o.weekdays = days;
        }
        f.finish();
    }

    // The keys of one material type.
    static void readMaterialType(const Fields& f, MaterialType type, Material& m) {
        switch (type) {
            case MaterialType::Diffuse: m.reflectance = f.color("reflectance", true).value_or(Vec3(0.5, 0.5, 0.5)); break;
            case MaterialType::Glossy:
                m.reflectance = f.color("reflectance").value_or(Vec3(0.04, 0.04, 0.04));
                m.roughness = f.number("roughness", 0.1, Range{0, 1, true, false});
                m.base = f.color("base").value_or(Vec3(0, 0, 0));
                break;
            case MaterialType::Glass: m.transmittance = f.number("transmittance", 0.88, kUnit); break;
            case MaterialType::Mirror: m.reflectance = f.color("reflectance").value_or(Vec3(0.9, 0.9, 0.9)); break;
            case MaterialType::Translucent: {
                auto r = f.color("reflectance", true), t = f.color("transmittance", true);
                m.reflectance = r.value_or(Vec3(0.5, 0.5, 0.5));
                m.diffuseTransmittance = t.value_or(Vec3(0, 0, 0));
                if (!r || !t) break;
                // More out than in would create light.
                static const char* const channels[3] = {"red", "green", "blue"};
                for (int c = 0; c < 3; ++c)
                    if ((*r)[c] + (*t)[c] > 1) {
                        f.error("transmittance", "reflectance + transmittance must be at most 1, got " +
                                                     formatNumber((*r)[c]) + " + " + formatNumber((*t)[c]) + " in the " +
                                                     channels[c] + " channel");
                        break;
                    }
                break;
            }
        }
    }

    void readMaterials(const Json& j, const std::string& path) {
        if (!j.is_object()) {
            sink_.error(path, "expected an object of named materials, got " + typeName(j));
            return;
        }
        static const std::vector<std::string> family = familyKeys(
            materialTypeNames().entries, [](const Fields& k, const auto& e) { Material m; readMaterialType(k, e.first, m); });
        for (const auto& [name, value] : j.items()) {
            Fields f(sink_, value, pointer(path, name));
            if (!f.valid()) continue;
            Material m;
            m.name = name;
            auto type = f.string("type", true);
            auto parsed = type ? materialTypeNames().parse(*type) : std::nullopt;
            if (type && !parsed) f.error("type", materialTypeNames().unknown("material type", *type));
            if (parsed) {
                m.type = *parsed;
                readMaterialType(f, m.type, m);
                f.finish(article(*type + " material"), family);
            } else if (!type) {
                f.finish("", family);
            }
            scene_.materialIndex[name] = uint32_t(scene_.materials.size());
            scene_.materials.push_back(m);
        }
    }

    std::vector<std::string> materialNames() const {
        std::vector<std::string> names;
        for (const auto& [name, _] : scene_.materialIndex) names.push_back(name);
        return names;
    }

    std::optional<uint32_t> materialRef(const Fields& f, const char* key, bool required) {
        auto name = f.string(key, required);
        if (!name) return std::nullopt;
        auto it = scene_.materialIndex.find(*name);
        if (it == scene_.materialIndex.end()) {
            f.error(key, "unknown material \"" + *name + "\"" + didYouMean(*name, materialNames()));
            return std::nullopt;
        }
        return it->second;
    }

    // {"translate": [x,y,z], "rotate_deg": a, "scale": s | [sx,sy,sz]}
    Transform readTransform(const Fields& parent, const char* key) {
        if (!parent.has(key)) return Transform();
        Fields f(sink_, parent.get(key), parent.at(key));
        Vec3 scale(1, 1, 1);
        if (f.has("scale")) {
            if (f.get("scale").is_number()) {
                double s = f.number("scale", 1.0, kScale);
                scale = Vec3(s, s, s);
            } else {
                scale = f.vec3("scale", false, kScale).value_or(scale);
            }
        }
        Transform t = Transform::placement(f.vec3("translate", false, kCoordinate).value_or(Vec3()),
                                           f.number("rotate_deg", 0.0, json::rotationRange())) *
                      Transform::scale(scale);
        f.finish();
        return t;
    }

    TriangleMesh readMeshFile(const Fields& f, const char* key, uint32_t material) {
        auto rel = f.string(key, true);
        if (!rel) return {};
        std::filesystem::path file = std::filesystem::path(*rel).is_absolute() ? std::filesystem::path(*rel) : dir_ / *rel;
        try {
            return loadMeshFile(file, material);
        } catch (const FileError& e) {
            f.error(key, std::string("cannot read mesh: ") + e.what());
        } catch (const IoError& e) {
            f.error(key, "cannot read mesh \"" + file.string() + "\": " + e.what());
        }
        return {};
    }

    // A mesh after its transform: every vertex within the coordinate limit (a
    // vertex at 1e9 m, or a scale of 1e4 on one at 1e5, would reach Embree).
    void checkMeshPlace(const Fields& f, const char* key, const TriangleMesh& mesh) {
        for (const Vec3& p : mesh.positions)
            if (!(std::abs(p.x) <= limits::kMaxCoordinate && std::abs(p.y) <= limits::kMaxCoordinate &&
                  std::abs(p.z) <= limits::kMaxCoordinate)) {
                f.error(key, "mesh vertex (" + formatNumber(p.x) + ", " + formatNumber(p.y) + ", " + formatNumber(p.z) +
                                 ") after its transform lies outside [-" + formatNumber(limits::kMaxCoordinate) + ", " +
                                 formatNumber(limits::kMaxCoordinate) + "] m");
                return;
            }
    }

    std::optional<Bounds3> readMinMax(const Fields& f, const char* what) {
        auto lo = f.vec3("min", true, kCoordinate), hi = f.vec3("max", true, kCoordinate);
        f.finish();
        if (!lo || !hi) return std::nullopt;
        for (int a = 0; a < 3; ++a)
            if ((*hi)[a] <= (*lo)[a]) {
                f.error("max", std::string(what) + " is empty or inverted: max " + "xyz"[a] + " " +
                                   formatNumber((*hi)[a]) + " <= min " + formatNumber((*lo)[a]));
                return std::nullopt;
            }
        return Bounds3(*lo, *hi);
    }

    // The shape of a static item: "room", "box" or "mesh", each with its own keys.
    void readStaticShape(const Fields& f, StaticKind kind, StaticItem& item) {
        switch (kind) {
            case StaticKind::Room: readRoom(f, item); break;
            case StaticKind::Box: {
                uint32_t m = materialRef(f, "material", !item.invisible).value_or(0);
                if (f.has("box")) {
                    Fields b(sink_, f.get("box"), f.at("box"));
                    if (auto box = readMinMax(b, "box")) addBox(item.mesh, *box, m);
                }
                break;
            }
            case StaticKind::Mesh: {
                uint32_t m = materialRef(f, "material", !item.invisible).value_or(0);
                Transform t = readTransform(f, "transform");
                item.mesh.append(readMeshFile(f, "mesh", m), t);
                checkMeshPlace(f, "mesh", item.mesh);
                break;
            }
        }
    }

    void readStatic(const Json& j, const std::string& path) {
        static const EnumNames<StaticKind> shapes{{{StaticKind::Room, "room"}, {StaticKind::Box, "box"}, {StaticKind::Mesh, "mesh"}}};
        Fields f(sink_, j, path);
        if (!f.valid()) return;
        StaticItem item;
        item.jsonPath = path;
        item.name = f.string("name", true).value_or("");
        if (f.has("name") && f.get("name").is_string() && item.name.empty()) f.error("name", "geometry names must be non-empty");
        item.invisible = f.boolean("invisible").value_or(false);
        std::optional<StaticKind> kind;
        int count = 0;
        for (const auto& [k, name] : shapes.entries)
            if (f.has(name)) kind = k, ++count;
        if (count != 1) {
            f.error(count == 0 ? "needs one shape: \"room\", \"box\" or \"mesh\""
                               : "has more than one shape (\"room\", \"box\", \"mesh\")");
            return;
        }
        static const std::vector<std::string> family = familyKeys(shapes.entries, [this](const Fields& k, const auto& e) {
            StaticItem probe;
            readStaticShape(k, e.first, probe);
        });
        item.kind = *kind;
        readStaticShape(f, item.kind, item);
        f.finish(article(std::string(shapes.name(item.kind))), family);
        scene_.geometry.push_back(std::move(item));
    }

    void readRoom(const Fields& f, StaticItem& item) {
        RoomShell room;
        std::optional<Bounds3> box;
        if (f.has("room")) {
            Fields r(sink_, f.get("room"), f.at("room"));
            box = readMinMax(r, "room");
        }
        if (box) room.box = *box;
        if (!f.has("materials")) f.missing("materials");
        else {
            Fields m(sink_, f.get("materials"), f.at("materials"));
            room.floorMaterial = materialRef(m, "floor", true).value_or(0);
            room.wallMaterial = materialRef(m, "walls", true).value_or(0);
            room.ceilingMaterial = materialRef(m, "ceiling", true).value_or(0);
            m.finish();
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

    // The keys of a wall opening (along the wall) or a ceiling one (a rectangle).
    static void readOpeningPlace(const Fields& f, bool ceiling, Opening& o) {
        if (ceiling) {
            o.center = f.vec2("center", true, kCoordinate).value_or(Vec2());
            o.size = f.vec2("size", true, kLength).value_or(Vec2(1, 1));
        } else {
            o.offset = f.number("offset", kOffset, true).value_or(0);
            o.width = f.number("width", kLength, true).value_or(1);
            o.sill = f.number("sill", 0.0, kOffset);
            o.height = f.number("height", kLength, true).value_or(1);
        }
    }

    std::optional<Opening> readOpening(const Json& j, const std::string& path, const RoomShell& room, bool haveBox) {
        Fields f(sink_, j, path);
        if (!f.valid()) return std::nullopt;
        static const std::vector<std::string> family = json::unionKeys(
            {json::probeKeys([](const Fields& k) { Opening o; readOpeningPlace(k, true, o); }),
             json::probeKeys([](const Fields& k) { Opening o; readOpeningPlace(k, false, o); })});
        Opening o;
        auto wall = f.string("wall", true);
        if (f.has("material")) o.material = materialRef(f, "material", true);
        if (f.has("blind")) {
            Fields b(sink_, f.get("blind"), f.at("blind"), "a blind object");
            if (b.valid()) {
                o.blindMaterial = materialRef(b, "material", true);
                o.blindDeployed = b.boolean("deployed").value_or(true);
                b.finish();
            }
        }
        auto parsed = wall ? wallNames().parse(*wall) : std::nullopt;
        if (wall && !parsed) f.error("wall", wallNames().unknown("wall", *wall));
        if (!parsed) {
            f.finish("", family);
            return std::nullopt;
        }
        o.wall = *parsed;
        size_t before = sink_.count();
        readOpeningPlace(f, o.wall == Wall::Ceiling, o);
        f.finish(o.wall == Wall::Ceiling ? "a ceiling opening" : "a wall opening", family);
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
        Fields f(sink_, j, path);
        if (!f.valid()) return;
        static const std::vector<std::string> family = [] {
            std::vector<std::vector<std::string>> lists;
            for (const EmitterShapeEntry& e : emitterShapes()) lists.push_back(json::probeKeys([&](const Fields& k) { e.read(k); }));
            return json::unionKeys(lists);
        }();
        Emitter e;
        e.jsonPath = path;
        e.entity = entity;
        e.name = scopedName(f, entity);
        auto shape = f.string("shape", true);
        const EmitterShapeEntry* entry = shape ? findEmitterShape(*shape) : nullptr;
        if (shape && !entry)
            f.error("shape", "unknown emitter shape \"" + *shape + "\"" + didYouMean(*shape, emitterShapeNames()) + " (" +
                                 listNames(emitterShapeNames()) + ")");
        if (entry) e.shape = entry->read(f);
        auto photometry = f.string("photometry");
        auto flux = f.number("flux_lm", kNonNegative.limitedTo(limits::kMaxFluxLm), /*required=*/!photometry);
        e.fluxLm = flux.value_or(0);
        e.cctK = f.number("cct_k", 4000.0, Range::closed(1000, 40000, "K"));
        auto c0 = f.direction("c0");
        if (c0 && !photometry) f.error("c0", "\"c0\" orients a photometric luminaire: it needs \"photometry\"");
        if (photometry && e.shape) readPhotometry(f, *photometry, c0, flux, e);
        f.finish(entry ? article(*shape + " emitter") : "", family);
        if (!entry) return;
        int index = int(scene_.emitters.size());
        scene_.emitters.push_back(e);
        if (entity >= 0) scene_.entities[entity].emitters.push_back(index);
    }

    // A luminaire's "photometry": its shape becomes the luminous opening of the
    // file's distribution, gamma = 0 along its normal (a sphere's own "normal",
    // default straight down), C = 0 along "c0"; "flux_lm" scales it, else the file's.
    void readPhotometry(const Fields& f, const std::string& rel, std::optional<Vec3> c0, std::optional<double> flux,
                        Emitter& e) {
        const bool flat = e.shape->normal().has_value();
        Vec3 axis = flat ? *e.shape->normal() : f.direction("normal").value_or(Vec3(0, 0, -1));
        if (c0 && length(cross(*c0, axis)) < 1e-6) {
            f.error("c0", "\"c0\" is parallel to the luminaire's normal (gamma = 0)");
            c0.reset();
        }
        std::filesystem::path file = std::filesystem::path(rel).is_absolute() ? std::filesystem::path(rel) : dir_ / rel;
        auto cached = photometries_.find(file);
        if (cached == photometries_.end()) {
            std::shared_ptr<const IntensityDistribution> d;
            try {
                d = loadPhotometry(file);
            } catch (const IoError& err) {
                photometryErrors_[file] = err.what();
            }
            cached = photometries_.emplace(file, d).first;
        }
        if (!cached->second) {
            f.error("photometry", photometryErrors_[file]);
            return;
        }
        e.shape = photometricEmitter(e.shape, cached->second, axis, c0, rel);
        if (!flux) e.fluxLm = cached->second->flux();
    }

    std::optional<Region> readRegion(const Json& j, const std::string& path, double initialRotation) {
        Fields f(sink_, j, path);
        if (!f.valid()) return std::nullopt;
        Region r;
        auto lo = f.vec2("min", true, kCoordinate), hi = f.vec2("max", true, kCoordinate);
        if (lo && hi) {
            r.lo = *lo, r.hi = *hi;
            for (int a = 0; a < 2; ++a)
                if ((*hi)[a] < (*lo)[a])
                    f.error("max", std::string("region is inverted: max ") + "xy"[a] + " " + formatNumber((*hi)[a]) +
                                       " < min " + formatNumber((*lo)[a]));
        }
        if (f.has("rotations") && f.has("rotation_range")) {
            f.error("give either \"rotations\" or \"rotation_range\", not both");
            (void)f.get("rotations");
            (void)f.get("rotation_range");
        } else if (auto* rots = f.array("rotations")) {
            if (rots->empty()) f.error("rotations", "the set of rotations is empty");
            for (size_t i = 0; i < rots->size(); ++i) {
                if (!(*rots)[i].is_number()) {
                    sink_.error(pointer(f.at("rotations"), i), "expected a number, got " + typeName((*rots)[i]));
                    continue;
                }
                const double deg = (*rots)[i].get<double>();
                if (const std::string why = json::rotationRange().limitProblem(deg); !why.empty()) {
                    sink_.error(pointer(f.at("rotations"), i), why);
                    continue;
                }
                r.rotationsDeg.push_back(deg);
            }
        } else if (f.has("rotation_range")) {
            if (auto range = f.vec2("rotation_range", false, json::rotationRange())) {
                if (range->y < range->x)
                    f.error("rotation_range", "rotation range is inverted: " + formatNumber(range->y) + " < " +
                                                  formatNumber(range->x));
                r.continuousRotation = true;
                r.rotationMinDeg = range->x, r.rotationMaxDeg = range->y;
            }
        } else {
            r.rotationsDeg = {initialRotation};  // no rotation given: the entity keeps its initial one
        }
        static const EnumNames<RegionBound> bounds{{{RegionBound::Origin, "origin"}, {RegionBound::Footprint, "footprint"}}};
        if (auto bound = f.string("bound")) {
            if (auto parsed = bounds.parse(*bound)) r.bound = *parsed;
            else f.error("bound", bounds.unknown("region bound", *bound));
        }
        f.finish();
        return r;
    }

    // "templates": {"name": an entity without its name}. A template is read where an
    // entity uses it, so its problems are found (and reported once, at the template)
    // when it is used.
    void readTemplates(const Json& j, const std::string& path) {
        if (!j.is_object()) {
            sink_.error(path, "expected an object of templates by name, got " + typeName(j));
            templatesInvalid_ = true;
            return;
        }
        for (const auto& [name, value] : j.items()) {
            const std::string at = pointer(path, name);
            if (name.empty() || name.find('.') != std::string::npos) {
                sink_.error(at, "template names must be non-empty and must not contain '.'");
                continue;
            }
            if (!value.is_object()) {
                sink_.error(at, "expected a template object (an entity without \"name\"), got " + typeName(value));
                continue;
            }
            if (value.contains("name"))
                sink_.error(pointer(at, "name"), "a template takes its name from the entity that uses it");
            if (value.contains("template"))
                sink_.error(pointer(at, "template"), "a template cannot be made from another template (use it as a child)");
            templates_[name] = {&value, at};
        }
    }

    // An entity that uses a template: the template's keys, replaced by the entity's
    // own; each key's problems are reported where it was written.
    struct Instance {
        Json merged;
        std::map<std::string, std::string> keyPaths;
        std::string templateName;
    };
    std::optional<Instance> instantiate(const Json& j, const std::string& path) {
        const Json& name = j["template"];
        const std::string at = pointer(path, "template");
        if (!name.is_string()) {
            sink_.error(at, "expected a template name, got " + typeName(name));
            return std::nullopt;
        }
        auto it = templates_.find(name.get<std::string>());
        if (it == templates_.end() && templatesInvalid_) return std::nullopt;  // that error says it
        if (it == templates_.end()) {
            std::vector<std::string> names;
            for (const auto& [n, _] : templates_) names.push_back(n);
            sink_.error(at, "unknown template \"" + name.get<std::string>() + "\"" + didYouMean(name.get<std::string>(), names) +
                                (names.empty() ? " (the scene has no \"templates\")" : " (" + listNames(names) + ")"));
            return std::nullopt;
        }
        if (std::find(activeTemplates_.begin(), activeTemplates_.end(), it->first) != activeTemplates_.end()) {
            sink_.error(at, "template \"" + it->first + "\" contains itself");
            return std::nullopt;
        }
        Instance instance{*it->second.json, {}, it->first};
        for (const auto& [key, _] : it->second.json->items()) instance.keyPaths[key] = pointer(it->second.path, key);
        for (const auto& [key, value] : j.items()) {
            instance.merged[key] = value;
            instance.keyPaths.erase(key);
        }
        return instance;
    }

    void readEntity(const Json& j, const std::string& path, int parent) {
        if (j.is_object() && j.contains("template")) {
            auto instance = instantiate(j, path);
            if (!instance) return;
            activeTemplates_.push_back(instance->templateName);
            Fields f(sink_, instance->merged, path, std::move(instance->keyPaths));
            f.get("template");
            readEntityKeys(f, parent);
            activeTemplates_.pop_back();
            return;
        }
        Fields f(sink_, j, path);
        readEntityKeys(f, parent);
    }

    void readEntityKeys(const Fields& f, int parent) {
        if (!f.valid()) return;
        const std::string& path = f.path();
        f.has("template");  // a known key of every entity
        int index = int(scene_.entities.size());
        scene_.entities.emplace_back();
        {
            Entity& e = scene_.entities.back();
            e.jsonPath = path;
            e.parent = parent;
            e.name = f.string("name", true).value_or("#" + std::to_string(index));
            if (e.name.empty() || e.name.find('.') != std::string::npos)
                f.error("name", "entity names must be non-empty and must not contain '.' (it separates levels in dotted paths)");
            e.path = parent >= 0 ? scene_.entities[parent].path + "." + e.name : e.name;
            if (f.has("position")) {
                const Json& p = f.get("position");
                auto n = json::readNumbers(sink_, p, f.at("position"), p.is_array() && p.size() == 3 ? 3 : 2, kCoordinate);
                if (n) e.position = Vec3((*n)[0], (*n)[1], n->size() == 3 ? (*n)[2] : 0.0);
            }
            e.rotationDeg = f.number("rotation", 0.0, json::rotationRange());
        }
        if (parent >= 0) {
            scene_.entities[parent].children.push_back(index);
            scene_.entities[index].inRoom = scene_.entities[parent].inRoom;
        }

        bool fixed = f.boolean("fixed").value_or(false);
        if (f.has("placement")) {
            Fields p(sink_, f.get("placement"), f.at("placement"));
            // A fixed entity keeps its placement: its regions are not read.
            if (!fixed) {
                if (auto inRoom = p.boolean("in_room")) {
                    if (parent >= 0)
                        p.error("in_room", "\"in_room\" applies to top-level entities: a member's footprint is part of its group's");
                    else
                        scene_.entities[index].inRoom = *inRoom;
                }
                if (auto* regions = p.array("regions", true)) {
                    if (regions->empty()) p.error("regions", "placement has no regions");
                    for (size_t i = 0; i < regions->size(); ++i)
                        if (auto r = readRegion((*regions)[i], pointer(p.at("regions"), i), scene_.entities[index].rotationDeg))
                            scene_.entities[index].regions.push_back(*r);
                }
                p.finish();
            }
        }
        if (auto* fronts = f.array("fronts")) {
            std::vector<Vec2> list;
            if (fronts->empty()) f.error("fronts", "needs at least one front direction");
            for (size_t i = 0; i < fronts->size(); ++i) {
                auto n = json::readNumbers(sink_, (*fronts)[i], pointer(f.at("fronts"), i), 2);
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
        if (auto* children = f.array("children")) {
            // Checked before recursing: a deep nesting is refused at its first level too
            // many, without the stack or the paths of every level below.
            int depth = 1;
            for (int p = parent; p >= 0; p = scene_.entities[p].parent) ++depth;
            if (depth + 1 > limits::kMaxEntityDepth && !children->empty())
                f.error("children", "entities nested " + std::to_string(depth + 1) + " deep exceed the limit of " +
                                        std::to_string(limits::kMaxEntityDepth));
            else
                for (size_t i = 0; i < children->size(); ++i) readEntity((*children)[i], pointer(f.at("children"), i), index);
        }
        // Rules among the entity's members, naming them relatively: read once every
        // entity is known.
        if (auto* constraints = f.array("constraints"))
            for (size_t i = 0; i < constraints->size(); ++i)
                entityConstraints_.push_back({(*constraints)[i], pointer(f.at("constraints"), i), index});
        f.finish();
    }

    enum class PartKind { Box, Mesh, Preset };

    // The keys of one kind of part; fills `mesh` and `info` (entity frame).
    void readPartKind(const Fields& f, PartKind kind, TriangleMesh& mesh, PartInfo& info) {
        switch (kind) {
            case PartKind::Box: {
                info.kind = "box";
                info.material = materialRef(f, "material", true).value_or(0);
                if (!f.has("box")) return;
                Fields b(sink_, f.get("box"), f.at("box"));
                auto size = b.vec3("size", true, kLength);
                auto center = b.vec3("center", false, kCoordinate);
                b.finish();
                if (!size) return;
                Vec3 c = center.value_or(Vec3(0, 0, size->z / 2));
                addBox(mesh, Bounds3(c - *size * 0.5, c + *size * 0.5), info.material);
                return;
            }
            case PartKind::Mesh: {
                info.kind = "mesh";
                info.material = materialRef(f, "material", true).value_or(0);
                Transform t = readTransform(f, "transform");
                mesh.append(readMeshFile(f, "mesh", info.material), t);
                checkMeshPlace(f, "mesh", mesh);
                return;
            }
            case PartKind::Preset: readPreset(f, mesh, info); return;
        }
    }

    void readPreset(const Fields& f, TriangleMesh& mesh, PartInfo& info) {
        auto name = f.string("preset", true);
        const PresetInfo* preset = name ? findPreset(*name) : nullptr;
        if (name && !preset) {
            std::vector<std::string> known;
            for (const auto& p : presetCatalog()) known.push_back(p.name);
            f.error("preset", "unknown preset \"" + *name + "\"" + didYouMean(*name, known) + " (" + listNames(known, ",") + ")");
        }
        std::map<std::string, uint32_t> slots;
        bool hasSlots = f.has("materials");
        auto body = materialRef(f, "material", preset && !hasSlots);
        Vec3 size = f.vec3("size", false, kLength).value_or(preset ? preset->defaultSize : Vec3(1, 1, 1));
        Vec3 center = f.vec3("center", false, kCoordinate).value_or(Vec3(0, 0, size.z / 2));
        if (!preset) {
            if (hasSlots) f.get("materials");  // not checked against an unknown preset's slots
            return;
        }
        info.kind = preset->name;
        if (body) slots[preset->slots.front()] = *body;
        if (hasSlots) {
            Fields m(sink_, f.get("materials"), f.at("materials"), "an object of material slots");
            for (const auto& slot : preset->slots)
                if (auto mat = materialRef(m, slot.c_str(), false)) slots[slot] = *mat;
            m.finish();
            if (!slots.count(preset->slots.front()))
                m.error(preset->slots.front().c_str(), "missing the body material (give \"material\" or \"materials\"." +
                                                           preset->slots.front() + ")");
        }
        info.material = slots.count(preset->slots.front()) ? slots[preset->slots.front()] : 0;
        mesh.append(buildPreset(*preset, size, slots), Transform::translate(center - Vec3(0, 0, size.z / 2)));
    }

    void readPart(const Json& j, const std::string& path, int entity) {
        static const EnumNames<PartKind> kinds{{{PartKind::Box, "box"}, {PartKind::Mesh, "mesh"}, {PartKind::Preset, "preset"}}};
        Fields f(sink_, j, path);
        if (!f.valid()) return;
        std::optional<PartKind> kind;
        int count = 0;
        for (const auto& [k, name] : kinds.entries)
            if (f.has(name)) kind = k, ++count;
        if (count != 1) {
            f.error(count == 0 ? "needs one of \"box\", \"mesh\" or \"preset\"" : "has more than one of \"box\", \"mesh\", \"preset\"");
            return;
        }
        static const std::vector<std::string> family = familyKeys(kinds.entries, [this](const Fields& k, const auto& e) {
            TriangleMesh mesh;
            PartInfo info;
            readPartKind(k, e.first, mesh, info);
        });
        PartInfo info;
        TriangleMesh mesh;
        readPartKind(f, *kind, mesh, info);
        f.finish(article(std::string(kinds.name(*kind)) + " part"), family);
        info.bounds = mesh.bounds();
        Entity& e = scene_.entities[entity];
        info.firstTriangle = e.mesh.triangles.size(), info.triangles = mesh.triangles.size();
        e.parts.push_back(info);
        e.mesh.append(mesh);
    }

    void readSampler(const Json& j, const std::string& path, int entity) {
        Fields f(sink_, j, path);
        if (!f.valid()) return;
        static const std::vector<std::string> family = [] {
            std::vector<std::vector<std::string>> lists;
            for (const SamplerTypeEntry& t : samplerTypes()) lists.push_back(json::probeKeys([&](const Fields& k) { t.read(k); }));
            return json::unionKeys(lists);
        }();
        LightSamplerSpec s;
        s.jsonPath = path;
        s.file = sink_.file;
        s.entity = entity;
        s.name = scopedName(f, entity);
        auto type = f.string("type", true);
        const SamplerTypeEntry* entry = type ? findSamplerType(*type) : nullptr;
        if (type && !entry) {
            f.error("type", "unknown sampler type \"" + *type + "\"" + didYouMean(*type, samplerTypeNames()) + " (" +
                                listNames(samplerTypeNames()) + ")");
        }
        const size_t before = sink_.count();
        if (entry) s.type = entry->read(f);
        // Fitted to its room only when it was read without a problem, not to repeat one.
        if (entry && sink_.count() == before)
            if (auto fit = s.type->fitted(samplerSite(entity), f)) s.type = fit;
        readTarget(f, s, entry ? s.type->unit() : "");
        s.weight = f.number("weight", 1.0, kWeight);
        readStatistics(f, s, entry ? s.type.get() : nullptr, entry ? *type : "");
        f.finish(entry ? article(*type + " sampler") : "", family);
        if (!entry) return;
        int index = int(scene_.samplers.size());
        scene_.samplers.push_back(s);
        if (entity >= 0) scene_.entities[entity].samplers.push_back(index);
    }

    // A sampler's, emitter's or constraint's name, scoped by the entity it belongs to
    // ("ws1.desk.task"), so that two entities may use the same one.
    std::string scopedName(const Fields& f, int entity, bool required = true) {
        auto name = f.string("name", required);
        if (!name) return "";
        if (name->empty() || name->find('.') != std::string::npos) {
            f.error("name", "names must be non-empty and must not contain '.' (it separates an entity's path from the name)");
            return "";
        }
        return entity >= 0 ? scene_.entities[entity].path + "." + *name : *name;
    }

    // "target": [min, max], null for an open end (0 and infinity); true when valid.
    bool readTargetRange(const Fields& f, double& lo, double& hi, const char* unit) {
        if (!f.has("target")) {
            f.missing("target");
            return false;
        }
        const Json& t = f.get("target");
        if (!t.is_array() || t.size() != 2) {
            f.error("target", "expected [min, max], got " + typeName(t));
            return false;
        }
        bool ok = true;
        auto bound = [&](size_t i, double fallback) {
            if (t[i].is_null()) return fallback;
            if (!t[i].is_number()) {
                sink_.error(pointer(f.at("target"), i), "expected a number or null, got " + typeName(t[i]));
                ok = false;
                return fallback;
            }
            const double v = t[i].get<double>();
            // A bound of the cost C (limits.h): beyond it a penalty could overflow.
            const Range limit = Range{-kInf, kInf, false, false, unit}.limitedTo(limits::kMaxTargetValue);
            if (!limit.withinLimit(v)) {
                sink_.error(pointer(f.at("target"), i), limit.limitProblem(v));
                ok = false;
                return fallback;
            }
            return v;
        };
        lo = bound(0, 0.0);
        hi = bound(1, kInf);
        if (!ok) return false;
        const std::string u = *unit ? std::string(" ") + unit : "";
        if (hi < lo) f.error("target", "target range is reversed: max " + formatNumber(hi) + " < min " + formatNumber(lo) + u);
        else if (hi < 0)
            f.error("target", "impossible target: max " + formatNumber(hi) + u + " is below 0 and no light level can meet it");
        else if (lo < 0) f.error("target", "target min " + formatNumber(lo) + u + " is negative");
        else return true;
        return false;
    }

    void readTarget(const Fields& f, LightSamplerSpec& s, const char* unit) {
        readTargetRange(f, s.targetMin, s.targetMax, unit);
        // Default tolerance (the paper's L_rej): the width of the range, or half the
        // finite bound when the range is open or a single value.
        double width = s.targetMax - s.targetMin;
        double fallback = std::isfinite(width) && width > 0 ? width : 0.5 * (std::isfinite(s.targetMax) ? s.targetMax : s.targetMin);
        if (!(fallback > 0)) fallback = 1;
        s.tolerance = f.number("tolerance", fallback, json::toleranceRange(unit));
    }

    SamplerSite samplerSite(int entity) const {
        SamplerSite site;
        for (const StaticItem& g : scene_.geometry)
            if (g.room) site.rooms.push_back(g.room->box);
        site.carried = entity >= 0;
        return site;
    }

    // "a planar or volume sampler": the types whose points carry statistics.
    static const std::string& statisticsTypes() {
        static const std::string names = [] {
            std::vector<std::string> kinds;
            DiagnosticSink discard;
            const Json empty = Json::object();
            for (const SamplerTypeEntry& t : samplerTypes())
                if (t.read(Fields(discard, empty, ""))->hasPointStatistics()) kinds.push_back(t.name);
            return article(listNames(kinds) + " sampler");
        }();
        return names;
    }

    // The sampler's "statistics": goals on the min, max and U0 of its points, each
    // {"target": [min, max], "tolerance": t}, read in the order min, max, u0.
    void readStatistics(const Fields& f, LightSamplerSpec& s, const SamplerType* type, const std::string& typeLabel) {
        if (!f.has("statistics")) return;
        const Json& goals = f.get("statistics");
        if (type && !type->hasPointStatistics()) {
            f.error("statistics", "statistics are over the points of " + statisticsTypes() + ", whose value is their mean; " +
                                      article(typeLabel + " sampler") + " has none");
            return;
        }
        if (!goals.is_object()) {
            f.error("statistics", "expected an object of goals such as {\"u0\": {\"target\": [0.6, 1]}}, got " +
                                      json::typeName(goals));
            return;
        }
        static const EnumNames<Statistic> names{{{Statistic::Min, "min"}, {Statistic::Max, "max"}, {Statistic::U0, "u0"}}};
        for (const auto& [key, value] : goals.items())
            if (!names.parse(key))
                sink_.error(pointer(f.at("statistics"), key),
                            names.unknown("statistic", key) + (key == "mean" ? "; the mean's goal is the sampler's \"target\"" : ""));
        for (const auto& [statistic, name] : names.entries) {
            if (!goals.contains(name)) continue;
            StatisticGoal goal;
            goal.statistic = statistic;
            goal.jsonPath = pointer(f.at("statistics"), name);
            Fields g(sink_, goals[name], goal.jsonPath, "a statistics goal object");
            if (!g.valid()) continue;
            const char* unit = statistic == Statistic::U0 || !type ? "" : type->unit();
            if (readTargetRange(g, goal.targetMin, goal.targetMax, unit) && statistic == Statistic::U0 && goal.targetMin > 1)
                g.error("target", "U0 = min / mean is at most 1: a target min of " + formatNumber(goal.targetMin) +
                                      " cannot be met");
            // Default tolerance: half the bound the goal guards, its min (a floor, as a
            // u0 or min goal has) or else its max (a ceiling); the width of a range such
            // as [200, 1e9] would make the goal toothless.
            double fallback = 0.5 * (goal.targetMin > 0 ? goal.targetMin : goal.targetMax);
            if (!(fallback > 0) || !std::isfinite(fallback)) fallback = 1;
            goal.tolerance = g.number("tolerance", fallback, json::toleranceRange(unit));
            g.finish();
            s.statistics.push_back(goal);
        }
    }

    std::vector<std::string> entityNames() const {
        std::vector<std::string> names{"room"};
        for (const Entity& e : scene_.entities) names.push_back(e.path);
        return names;
    }

    // "an alignment constraint": the types whose "b" may be the room.
    static const std::string& roomConstraints() {
        static const std::string names = [] {
            std::vector<std::string> kinds;
            DiagnosticSink discard;
            const Json empty = Json::object();
            for (const ConstraintKindEntry& k : constraintKinds())
                if (k.read(Fields(discard, empty, ""))->acceptsRoom()) kinds.push_back(k.name);
            return article(listNames(kinds) + " constraint");
        }();
        return names;
    }

    // `scope`: the entity whose "constraints" the reference is in (its members are named
    // relatively), -1 for the scene's.
    int entityRef(const Fields& f, const char* key, bool allowRoom, int scope = -1) {
        auto name = f.string(key, true);
        if (!name) return -1;
        if (*name == "room") {
            if (allowRoom) return kRoomEntity;
            f.error(key, "\"room\" is only valid as \"b\" of " + roomConstraints());
            return -1;
        }
        if (scope >= 0) {
            const std::string& prefix = scene_.entities[scope].path;
            int e = scene_.findEntity(prefix + "." + *name);
            if (e < 0 && !entitiesIncomplete_) {
                std::vector<std::string> members;
                for (const Entity& m : scene_.entities)
                    if (m.path.rfind(prefix + ".", 0) == 0) members.push_back(m.path.substr(prefix.size() + 1));
                f.error(key, "\"" + prefix + "\" has no member \"" + *name + "\"" + didYouMean(*name, members) +
                                 (members.empty() ? "" : " (" + listNames(members) + ")") +
                                 "; an entity's constraints name its members relatively");
            }
            return e;
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
        if (e < 0 && !entitiesIncomplete_) f.error(key, "unknown entity \"" + *name + "\"" + didYouMean(*name, entityNames()));
        return e;
    }

    // A relational constraint's keys besides "type" and "weight": its type's own,
    // then the two ends every type has.
    void readRelational(const Fields& f, const ConstraintKindEntry& entry, ConstraintSpec& c, int scope = -1) {
        c.kind = entry.read(f);
        c.a = entityRef(f, "a", false, scope);
        c.b = entityRef(f, "b", c.kind->acceptsRoom(), scope);
        if (c.a >= 0 && c.a == c.b) f.error("b", "a constraint needs two different entities");
    }

    // The overlap rule's keys: a rule of the scene, set by a "constraints" entry.
    static void readOverlapRule(const Fields& f, OverlapRule& rule) {
        rule.tolerance = f.number("tolerance", 0.05, Range::closed(limits::kMinOverlapTolerance, 1));
        rule.wallTolerance = 1e-3 * f.number("wall_tolerance_l", 1e3 * rule.wallTolerance, Range::atLeast(0, "l"));
    }

    void readConstraint(const Json& j, const std::string& path, int scope) {
        Fields f(sink_, j, path);
        if (!f.valid()) return;
        static const std::vector<std::string> family = [this] {
            std::vector<std::vector<std::string>> lists;
            for (const ConstraintKindEntry& k : constraintKinds())
                lists.push_back(json::probeKeys([&](const Fields& p) {
                    ConstraintSpec c;
                    readRelational(p, k, c);
                    p.has("name");
                }));
            lists.push_back(json::probeKeys([](const Fields& p) {
                OverlapRule rule;
                readOverlapRule(p, rule);
            }));
            return json::unionKeys(lists);
        }();
        auto type = f.string("type", true);
        double weight = f.number("weight", 1.0, kWeight);
        const bool overlap = type && *type == kOverlapRuleName;
        const ConstraintKindEntry* entry = type ? findConstraintKind(*type) : nullptr;
        if (overlap && scope >= 0) {
            f.error("type", "the overlap rule holds for the whole scene: set it in the top-level \"constraints\"");
            OverlapRule ignored;
            readOverlapRule(f, ignored);
        } else if (overlap) {
            readOverlapRule(f, scene_.overlap);
            scene_.overlap.weight = weight;
            scene_.overlap.jsonPath = path;
        } else if (type && !entry) {
            f.error("type", "unknown constraint type \"" + *type + "\"" + didYouMean(*type, constraintTypeNames()) + " (" +
                                listNames(constraintTypeNames()) + ")");
        }
        ConstraintSpec c;
        c.jsonPath = path;
        c.weight = weight;
        if (entry) {
            readRelational(f, *entry, c, scope);
            c.name = scopedName(f, scope, /*required=*/false);
        }
        f.finish(entry || overlap ? article(*type + " constraint") : "", family);
        if (entry) scene_.constraints.push_back(c);
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
        for (const auto& c : scene_.constraints) unique("constraint", c.name, c.jsonPath);
        for (const auto& c : scene_.cameras) unique("camera", c.name, c.jsonPath);
    }

    // What only the whole scene shows: its triangle count.
    void checkScene() {
        uint64_t triangles = 0;
        for (const auto& g : scene_.geometry) triangles += g.mesh.triangleCount();
        for (const auto& e : scene_.entities) triangles += e.mesh.triangleCount();
        if (triangles > limits::kMaxSceneTriangles)
            sink_.error("", "the scene's " + std::to_string(triangles) + " triangles exceed the limit of " +
                                std::to_string(limits::kMaxSceneTriangles));
        checkGlareSources();
    }

    // A glare eye surveys its sources one by one (SamplerType::glareSources): a DGP eye
    // every luminaire and every sun disk, counted here only when one asks.
    void checkGlareSources() {
        const int64_t luminaires = int64_t(scene_.emitters.size());
        std::optional<int64_t> sunDisks;
        for (const LightSamplerSpec& s : scene_.samplers) {
            const bool seesSuns = s.type->glareSources(0, 1) > 0;
            if (seesSuns && !sunDisks) {
                sunDisks = 0;
                if (scene_.daylight)
                    for (const DaylightInstant& i : daylightInstants(*scene_.daylight, scene_.site)) *sunDisks += i.sunUp();
            }
            const int64_t suns = seesSuns ? *sunDisks : 0;
            if (s.type->glareSources(luminaires, suns) <= limits::kMaxGlareSources) continue;
            std::string what = std::to_string(luminaires) + (luminaires == 1 ? " luminaire" : " luminaires");
            if (seesSuns) what += " and " + std::to_string(suns) + " sun disks (one per daylight step with the sun up)";
            sink_.error(s.jsonPath, std::string("a ") + s.type->name() + " sampler surveys each " +
                                        (seesSuns ? "luminaire and sun disk" : "luminaire") + " as a glare source of its own: " +
                                        what + " exceed the limit of " + std::to_string(limits::kMaxGlareSources) +
                                        (suns > 0 ? "; a longer \"step_minutes\" or a shorter period has fewer" : ""));
        }
    }

    void buildVoxels() {
        // Each solid on its own (a few tenths of a second in all for the paper's offices).
        std::vector<std::pair<const TriangleMesh*, VoxelGrid*>> solids;
        for (auto& e : scene_.entities)
            if (e.hasGeometry()) solids.push_back({&e.mesh, &e.voxels});
        for (auto& g : scene_.geometry)
            if (g.kind != StaticKind::Room) solids.push_back({&g.mesh, &g.voxels});
        parallelFor(solids.size(), [&](size_t i) { *solids[i].second = voxelizeSolid(*solids[i].first, options_.voxelSize); });
    }

    struct Template {
        const Json* json;  // in the scene's document, which outlives the reading
        std::string path;
    };
    struct ScopedConstraint {
        Json json;
        std::string path;
        int entity;
    };
    std::map<std::string, Template> templates_;
    bool templatesInvalid_ = false;
    std::vector<std::string> activeTemplates_;  // the templates being instantiated, outermost first
    std::vector<ScopedConstraint> entityConstraints_;

    LoadOptions options_;
    bool entitiesIncomplete_ = false;
    bool siteValid_ = true;
    bool siteLatitudeGiven_ = false, siteLongitudeGiven_ = false;
    DiagnosticSink sink_;
    Scene scene_;
    std::filesystem::path dir_;
    // Each photometric file is read once however many luminaires use it (null: it
    // could not be read, for the reason in photometryErrors_).
    std::map<std::filesystem::path, std::shared_ptr<const IntensityDistribution>> photometries_;
    std::map<std::filesystem::path, std::string> photometryErrors_;
};

}  // namespace

Scene loadScene(const std::filesystem::path& file, const LoadOptions& options) {
    return Loader(file, options).load();
}

}  // namespace luxplan::io
