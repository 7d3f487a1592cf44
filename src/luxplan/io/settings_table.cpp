#include "settings_table.h"

#include <algorithm>
#include <iomanip>
#include <map>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include <luxplan/core/names.h>

namespace luxplan::io {
namespace {

using json::Fields;
using json::Range;
using S = OptimizerSettings;
using json::Json;

const EnumNames<bool>& onOffNames() {
    static const EnumNames<bool> names{{{true, "on"}, {false, "off"}}};
    return names;
}
const EnumNames<bool>& samplingNames() {
    static const EnumNames<bool> names{{{true, "sobol"}, {false, "random"}}};
    return names;
}
const EnumNames<SunPatchUse>& sunPatchesNames() {
    static const EnumNames<SunPatchUse> names{{{SunPatchUse::On, "on"}, {SunPatchUse::Off, "off"}, {SunPatchUse::Report, "report"}}};
    return names;
}
const EnumNames<bool>& hierarchyNames() {
    static const EnumNames<bool> names{{{false, "hierarchical"}, {true, "flat"}}};
    return names;
}
const EnumNames<bool>& startNames() {
    static const EnumNames<bool> names{{{false, "uniform"}, {true, "scene"}}};
    return names;
}

// The rows' access by type: each reads its field only when the key is present and
// valid, and writes it as the file holds it.
SettingAccess boolKey(const char* key, bool S::*field) {
    return {[key, field](const Fields& f, S& s) {
                if (auto v = f.boolean(key)) s.*field = *v;
            },
            [field](const S& s) { return Json(s.*field); }};
}
SettingAccess intKey(const char* key, int S::*field, Range range) {
    return {[key, field, range](const Fields& f, S& s) {
                if (auto v = f.integer(key, range)) s.*field = *v;
            },
            [field](const S& s) { return Json(s.*field); }};
}
SettingAccess numberKey(const char* key, double S::*field, Range range) {
    return {[key, field, range](const Fields& f, S& s) {
                if (auto v = f.number(key, range)) s.*field = *v;
            },
            [field](const S& s) { return Json(s.*field); }};
}
template <class T>
SettingAccess choiceKey(const char* key, T S::*field, const EnumNames<T>& (*names)()) {
    return {[key, field, names](const Fields& f, S& s) {
                auto text = f.string(key);
                if (!text) return;
                if (auto v = names().parse(*text)) s.*field = *v;
                else f.error(key, names().unknown(key, *text));
            },
            [field, names](const S& s) { return Json(names().name(s.*field)); }};
}
// An optional choice: unset, the command's default (written as null).
template <class T>
SettingAccess optionalChoiceKey(const char* key, std::optional<T> S::*field, const EnumNames<T>& (*names)()) {
    return {[key, field, names](const Fields& f, S& s) {
                auto text = f.string(key);
                if (!text) return;
                if (auto v = names().parse(*text)) s.*field = *v;
                else f.error(key, names().unknown(key, *text));
            },
            [field, names](const S& s) { return (s.*field) ? Json(names().name(*(s.*field))) : Json(nullptr); }};
}

// paths_per_point sets the search's count, and the report's and the selection's
// defaults follow it (neither below it); a later key may set those itself.
void readPaths(const Fields& f, S& s) {
    auto paths = f.integer("paths_per_point", Range::atLeast(1));
    if (!paths) return;
    s.pathsPerPoint = s.searchPathsPerPoint = *paths;
    s.reportPathsPerPoint = std::max(kDefaultReportPaths, *paths);
    s.selectionPathsPerPoint = std::min(s.reportPathsPerPoint, std::max(kDefaultSelectionPaths, *paths));
}
// A file that sets the report's count alone keeps its selection at that count, or at
// the default where that is fewer.
void readReportPaths(const Fields& f, S& s) {
    auto report = f.integer("report_paths_per_point", Range::atLeast(1));
    if (!report) return;
    s.reportPathsPerPoint = *report;
    s.selectionPathsPerPoint = std::min(*report, std::max(kDefaultSelectionPaths, s.pathsPerPoint));
}
// A number (a constant temperature: a plain Metropolis chain) or {"start", "end"} (geometric cooling).
void readTemperature(const Fields& f, S& s) {
    if (!f.has("temperature")) return;
    const json::Json& t = f.get("temperature");
    if (t.is_number()) {
        s.constantTemperature = true;
        s.temperatureStart = s.temperatureEnd = f.number("temperature", 0.1, Range::positive());
    } else {
        Fields tf(f.sink(), t, f.at("temperature"), "a number or {\"start\", \"end\"}");
        s.temperatureStart = tf.number("start", 0.1, Range::positive());
        s.temperatureEnd = tf.number("end", 0.001, Range::positive());
        tf.finish();
    }
}

Json writeTemperature(const S& s) {
    if (s.constantTemperature) return s.temperatureStart;
    return Json{{"start", s.temperatureStart}, {"end", s.temperatureEnd}};
}

// Settings that cannot hold together, each pair named by its keys.
struct Exclusion {
    const char *a, *b;
    bool S::*fa;
    bool S::*fb;
    const char* why;
};
const Exclusion kExclusions[] = {
    {"check_cache", "full_evaluation", &S::checkCache, &S::fullEvaluation, "check_cache checks the path cache, which full_evaluation does without"},
    {"check_cache", "fresh_noise", &S::checkCache, &S::freshNoise, "check_cache checks the path cache, which fresh_noise does without"},
    {"nested", "cycle", &S::nested, &S::cycle, "the object-level proposals follow the group just proposed, or any group"},
};

std::string rangeText(Range r) { return r.describe(); }

}  // namespace

const std::vector<SettingKey>& settingKeys() {
    static const std::vector<SettingKey> table = {
        // The search.
        {"iterations", "whole number", rangeText(Range::atLeast(0)), "10000", "optimize",
         "proposals, both levels together (optimize --iterations)", intKey("iterations", &S::iterations, Range::atLeast(0))},
        {"seed", "whole number", "[0, 2^64 - 1]", "1", "measure, optimize, render, report",
         "the random seed (--seed); the same scene, seed and thread count give the same result",
         {[](const Fields& f, S& s) {
              if (auto v = f.unsignedInteger("seed")) s.seed = *v;
          },
          [](const S& s) { return Json(s.seed); }}},
        {"paths_per_point", "whole number", rangeText(Range::atLeast(1)), "64",
         "optimize", "paths per sampler point in the search (optimize --paths); given, the report's and the selection's defaults are "
         "not below it",
         {readPaths, [](const S& s) { return Json(s.searchPathsPerPoint); }}},
        {"report_paths_per_point", "whole number", rangeText(Range::atLeast(1)), "32000, or paths_per_point where more",
         "measure, optimize, render, report", "paths per point of the result's report, measure, render and report (their --paths)",
         {readReportPaths, [](const S& s) { return Json(s.reportPathsPerPoint); }}},
        {"selection_paths_per_point", "whole number", rangeText(Range::atLeast(1)),
         "1000 (or paths_per_point where more), at most report_paths_per_point", "optimize",
         "paths per point of the search's independent measurements: a zero cost's confirmation, the candidates' re-measures",
         intKey("selection_paths_per_point", &S::selectionPathsPerPoint, Range::atLeast(1))},
        {"inner_iterations", "whole number", rangeText(Range::closed(0, 1000)), "0", "optimize",
         "object-level proposals per group-level one; 0: by the levels' degrees of freedom",
         intKey("inner_iterations", &S::innerIterations, Range::closed(0, 1000))},
        {"nested", "true or false", "", "false", "optimize",
         "object-level proposals move the members of the group just proposed", boolKey("nested", &S::nested)},
        {"polish_share", "number", rangeText(Range::closed(0, 0.9)), "0.2", "optimize",
         "each cycle's last share: a zero-temperature polish of the best layout; 0: none",
         numberKey("polish_share", &S::polishShare, Range::closed(0, 0.9))},
        {"restart_share", "number", rangeText(Range::closed(0, 0.5)), "0.3", "optimize",
         "the schedule and its polish in cycles of this share of the run, each later one from the polished best, "
         "warm again at a fifth of the start temperature; 0: one cycle",
         numberKey("restart_share", &S::restartShare, Range::closed(0, 0.5))},
        {"guided", "true or false", "", "true", "optimize",
         "the guided move: placements drawn from a map of where each entity's targets held", boolKey("guided", &S::guided)},
        {"plan_iterations", "whole number", rangeText(Range::closed(0, 1000000)), "20000", "optimize",
         "the planned start: proposals of a chain on the desks' illuminance in the room without its furniture and the "
         "exact rules, no light traced, whose best is where the search starts (from uniform draws only); 0: the drawn start",
         intKey("plan_iterations", &S::planIterations, Range::closed(0, 1000000))},
        {"plans", "whole number", rangeText(Range::closed(1, 64)), "8", "optimize",
         "plans of the planned start, each corrected by a traced look; the start is the one whose independent measurement "
         "reads the lowest C, and one that meets every goal ends the planning",
         intKey("plans", &S::plans, Range::closed(1, 64))},
        {"suggestions", "whole number", rangeText(Range::closed(0, 50)), "0", "optimize",
         "distinct layouts written beside the result (optimize --suggestions)",
         intKey("suggestions", &S::suggestions, Range::closed(0, 50))},
        {"margin", "number", rangeText(Range::closed(0, 5)), "2", "optimize",
         "the search's margin inside every lighting band, in standard errors of its estimate",
         numberKey("margin", &S::margin, Range::closed(0, 5))},
        {"adaptive_share", "true or false", "", "true", "optimize",
         "the object level's share of proposals follows what each level's proposals yield",
         boolKey("adaptive_share", &S::adaptiveShare)},
        {"hierarchy", "hierarchical or flat", "", "hierarchical", "optimize",
         "flat: no groups, every object on its own, groups kept by cohesion constraints (the paper's Figure 6)",
         choiceKey<bool>("hierarchy", &S::flat, hierarchyNames)},
        {"start", "uniform or scene", "", "uniform", "optimize",
         "the start layout: uniform draws from the regions, or the scene's placement",
         choiceKey<bool>("start", &S::startFromScene, startNames)},
        {"temperature", "number > 0, or {\"start\", \"end\"}", "", "{\"start\": 0.1, \"end\": 0.001}", "optimize",
         "a number: a constant temperature (a plain Metropolis chain); an object: geometric cooling from start to end",
         {readTemperature, writeTemperature}},
        // How light is traced, and the search's experiments.
        {"sampling", "sobol or random", "", "sobol", "measure, optimize",
         "the paths' first vertices: scrambled low-discrepancy numbers, or PCG only",
         choiceKey<bool>("sampling", &S::lowDiscrepancy, samplingNames)},
        {"sun_patches", "on, off or report", "", "measure, render, report: on; optimize: report", "measure, optimize, render, report",
         "sample the room's sunlit patches at every surface a path meets: everywhere, nowhere, or all but the search "
         "(the same values, less noise where sunlight bounces)",
         optionalChoiceKey<SunPatchUse>("sun_patches", &S::sunPatches, sunPatchesNames)},
        {"exterior_sun", "on or off", "", "on", "measure, optimize, render, report",
         "follow the sky's samples through the openings to sunlit surfaces outside and take the sun's and sky's light there "
         "(the same values either way)",
         choiceKey<bool>("exterior_sun", &S::exteriorSun, onOffNames)},
        {"light_roulette", "number", rangeText(Range::closed(0, kMostLightRoulette)), "measure: 0; optimize: 0.2", "measure, optimize",
         "a light sample worth less than this share of its sampler's variance per path is traced by roulette (optimize: in the "
         "search only); 0: every sample. Unbiased",
         {[](const Fields& f, S& s) {
              if (auto v = f.number("light_roulette", Range::closed(0, kMostLightRoulette))) s.lightRoulette = *v;
          },
          [](const S& s) { return s.lightRoulette ? Json(*s.lightRoulette) : Json(nullptr); }}},
        {"adaptive", "true or false", "", "false", "measure",
         "each sampler stops once its value +- 3 standard errors lies in one linear piece of its penalty (--paths the most)",
         boolKey("adaptive", &S::adaptive)},
        {"fixed_paths", "true or false", "", "false", "optimize",
         "the search traces exactly paths_per_point for every sampler (default: a sampler stops once its penalty is settled)",
         boolKey("fixed_paths", &S::fixedPaths)},
        {"full_evaluation", "true or false", "", "false", "optimize",
         "trace every path of every evaluated layout (default: only the paths a move can change)",
         boolKey("full_evaluation", &S::fullEvaluation)},
        {"check_cache", "true or false", "", "false", "optimize",
         "trace every path the path cache reads back again and compare them bit for bit (report.json's path_cache_check)",
         boolKey("check_cache", &S::checkCache)},
        {"fresh_noise", "true or false", "", "false", "optimize",
         "draw every lighting estimate anew and test with the penalty method (default: common random numbers)",
         boolKey("fresh_noise", &S::freshNoise)},
        {"noise_blind", "true or false", "", "false", "optimize",
         "the paper's plain Metropolis test on the estimates, the temperature free to fall below their noise",
         boolKey("noise_blind", &S::noiseBlind)},
        {"single_test", "true or false", "", "false", "optimize",
         "one Metropolis test after lighting every proposal (default: the rules' change first, delayed acceptance)",
         boolKey("single_test", &S::singleTest)},
        {"cycle", "true or false", "", "false", "optimize",
         "object-level proposals move any group's members (the paper's plain cycle: nested false, said)",
         boolKey("cycle", &S::cycle)},
        {"flat", "true or false", "", "false", "measure, optimize",
         "measure: the flattened scene (optimize's layout_flat.json); optimize: hierarchy flat",
         boolKey("flat", &S::flatScene)},
        {"snapshots", "whole number", rangeText(Range::closed(0, 1000)), "0", "optimize",
         "snapshots.json: the best layout at this many checkpoints (iteration ceil(iterations (k/N)^2)); 0: none",
         intKey("snapshots", &S::snapshots, Range::closed(0, 1000))},
    };
    return table;
}

void readSettings(const Fields& f, OptimizerSettings& s) {
    if (!f.valid()) return;
    for (const SettingKey& row : settingKeys()) row.access.read(f, s);
    for (const Exclusion& e : kExclusions)
        if (s.*e.fa && s.*e.fb)
            f.error(e.b, "\"" + std::string(e.a) + "\" and \"" + e.b + "\" exclude each other (" + e.why + ")");
}

Json settingsJson(const OptimizerSettings& s) {
    Json object = Json::object();
    for (const SettingKey& row : settingKeys())
        if (Json v = row.access.write(s); !v.is_null()) object[row.key] = std::move(v);
    return object;
}

SettingOverride parseSetting(const std::string& text) {
    const size_t eq = text.find('=');
    if (eq == std::string::npos) throw std::invalid_argument("expected KEY=VALUE, got \"" + text + "\" (no \"=\")");
    const std::string key = text.substr(0, eq), value = text.substr(eq + 1);
    if (key.empty()) throw std::invalid_argument("expected KEY=VALUE, got \"" + text + "\" (no key before \"=\")");
    std::vector<std::string> keys;
    for (const SettingKey& row : settingKeys()) keys.push_back(row.key);
    if (std::find(keys.begin(), keys.end(), key) == keys.end())
        throw std::invalid_argument("unknown setting \"" + key + "\"" + didYouMean(key, keys) + " (luxplan settings lists them: " +
                                    listNames(keys, ",") + ")");
    if (value.empty()) throw std::invalid_argument("no value after \"" + key + "=\"");
    // What a JSON file would hold: true, 3, 0.5, {"start": 1, "end": 0.01}; any other
    // text is a string (on, sobol).
    json::Json v = json::Json::parse(value, nullptr, false);
    if (v.is_discarded() || !(v.is_boolean() || v.is_number() || v.is_object())) v = value;
    return {key, v};
}

std::vector<std::string> settingProblems(const std::vector<SettingOverride>& settings) {
    json::Json object = json::Json::object();
    std::map<std::string, std::string> paths;
    for (const SettingOverride& o : settings) {
        object[o.key] = o.value;
        paths[o.key] = "--set " + o.key + "=" + (o.value.is_string() ? o.value.get<std::string>() : o.value.dump());
    }
    json::DiagnosticSink sink;
    Fields f(sink, object, "", paths);
    OptimizerSettings s;
    readSettings(f, s);
    f.finish();
    std::vector<std::string> lines;
    for (const Diagnostic& d : sink.diagnostics) lines.push_back(d.jsonPath + ": " + d.message);
    return lines;
}

std::string settingsTableText() {
    std::ostringstream out;
    out << "Settings: keys of the scene file's \"optimizer\" object, and of --set KEY=VALUE on measure, optimize, render and "
           "report (--set wins over the scene file; --seed, --paths, --iterations and --suggestions over both).\n";
    for (const SettingKey& row : settingKeys()) {
        out << "\n  " << row.key << " = " << row.type;
        if (!row.range.empty()) out << (row.range[0] == '[' || row.range[0] == '(' ? " in " : " ") << row.range;
        out << " (default " << row.fallback << "; " << row.commands << ")\n      " << row.doc << "\n";
    }
    return out.str();
}

}  // namespace luxplan::io
