// Writers for the optimizer's report.json and trace.csv.
#include <luxplan/optimizer/report.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include <nlohmann/json.hpp>

#include <luxplan/constraints/constraint_type.h>
#include <luxplan/core/atomic_file.h>
#include <luxplan/core/error.h>
#include <luxplan/constraints/penalty.h>
#include <luxplan/json/fields.h>
#include <luxplan/lightsamplers/sampler_type.h>
#include <luxplan/optimizer/flatten.h>
#include <luxplan/optimizer/reach.h>
#include <luxplan/optimizer/sampler_report.h>

namespace luxplan {
namespace {

using Json = nlohmann::ordered_json;


const char* targetName(OverlapTarget t) {
    switch (t) {
        case OverlapTarget::Entity: return "entity";
        case OverlapTarget::Static: return "static";
        case OverlapTarget::Walls: return "walls";
    }
    return "?";
}

Json moveJson(const MoveStats& s) {
    return {{"proposed", s.proposed}, {"accepted", s.accepted}, {"outside", s.outside},
            {"rejected_geometry", s.rejectedGeometry}, {"screened", s.screened}, {"acceptance", s.acceptance()},
            {"paths_traced", s.pathsTraced}};
}

Json termJson(const Scene& scene, const PenaltyTerm& t) {
    Json j;
    j["type"] = termName(t);
    if (t.overlap()) {
        if (!scene.overlap.jsonPath.empty()) j["json_path"] = scene.overlap.jsonPath;
        j["a"] = scene.entities[t.a].path;
        j["target"] = targetName(t.target);
        if (t.target == OverlapTarget::Entity) j["b"] = scene.entities[t.b].path;
        else if (t.target == OverlapTarget::Static) j["b"] = scene.geometry[t.b].name;
        else j["b"] = "walls";
        j["value"] = json::numberOrNull(t.value);
        j["unit"] = "m3";
        j["reference"] = t.reference;
    } else {
        const ConstraintSpec& c = scene.constraints[t.constraint];
        if (!c.name.empty()) j["name"] = c.name;
        j["json_path"] = c.jsonPath;
        // A flat scene's constraint on a former group names the group, as the scene does.
        const auto* flat = dynamic_cast<const FlatConstraint*>(c.kind.get());
        j["a"] = flat && flat->groupA() ? flat->groupA()->path : scene.entities[t.a].path;
        j["b"] = t.b == kRoomEntity ? std::string("room") : flat && flat->groupB() ? flat->groupB()->path : scene.entities[t.b].path;
        t.kind->report(t, j);
    }
    j["penalty"] = json::numberOrNull(t.penalty);
    j["weight"] = t.weight;
    j["rejects"] = t.rejects;
    return j;
}

}  // namespace

GoalCount countGoals(const Scene& scene, const OptimizerResult& r) {
    GoalCount g;
    const Evaluation& best = r.bestEvaluation;
    g.lighting = int(scene.samplers.size());
    for (size_t k = 0; k < scene.samplers.size() && k < best.samplers.samplers.size(); ++k) {
        const SamplerRange range = k < r.samplerRanges.size() ? r.samplerRanges[k] : SamplerRange{};
        const Reach reach = reachVerdict(scene.samplers[k], range, best.samplers.samplers[k]).reach;
        g.lightingMet += reach == Reach::Met;
        g.lightingWithinNoise += reach == Reach::WithinNoise;
    }
    const bool hardLimitPassed = r.bestGeometry.rejected && !r.feasible;
    for (const PenaltyTerm& t : r.bestGeometry.terms)
        if (!t.overlap()) {
            ++g.rules;
            if (!hardLimitPassed && t.penalty == 0) ++g.rulesHeld;
        }
    ++g.rules;  // overlap, one rule
    if (!hardLimitPassed && r.bestGeometry.overlapPenalty == 0) ++g.rulesHeld;
    return g;
}

std::string GoalCount::sentence() const {
    std::string s = std::to_string(lightingMet) + " of " + std::to_string(lighting) + " lighting goals met";
    if (lightingWithinNoise > 0)
        s += " (" + std::to_string(lightingWithinNoise) + " more at " + (lightingWithinNoise == 1 ? "its" : "their") +
             " bound within noise)";
    return s + ", " + std::to_string(rulesHeld) + " of " + std::to_string(rules) + " rules held";
}

std::string reportJson(const Scene& scene, const OptimizerResult& r, const RunSettings& settings) {
    const Evaluation& best = r.bestEvaluation;
    Json j;
    j["scene"] = scene.name;
    j["file"] = scene.file.string();
    // A layout past a hard limit has no cost (rejected_by says which); L is null where
    // the light was not measured.
    j["C"] = best.rejected ? Json(nullptr) : json::numberOrNull(best.cost);
    j["C_std_error"] = best.rejected ? Json(nullptr) : json::numberOrNull(best.costError);
    j["L"] = best.lightingEvaluated || scene.samplers.empty() ? json::numberOrNull(best.lighting) : Json(nullptr);
    j["G"] = best.rejected ? Json(nullptr) : json::numberOrNull(best.geometry);
    j["lighting_weight"] = scene.objective.lightingWeight;
    // The luminaires' share of their light as new in every illuminance (1: as new).
    j["maintenance_factor"] = scene.maintenanceFactor;
    j["lighting_evaluated"] = best.lightingEvaluated;
    j["feasible"] = r.feasible;
    if (best.rejected) j["rejected_by"] = best.rejectedBy;
    const GoalCount goals = countGoals(scene, r);
    j["goals"] = {{"lighting_met", goals.lightingMet}, {"lighting", goals.lighting},
                  {"lighting_within_noise", goals.lightingWithinNoise},
                  {"rules_held", goals.rulesHeld}, {"rules", goals.rules}};
    j["iterations"] = r.iterations;
    j["best_iteration"] = r.bestIteration;
    j["zero_cost_confirmations"] = r.confirmations;
    j["zero_cost_refutations_borrowed"] = r.borrowedRefutations;
    // How the result was chosen: the search's estimate of it, and every candidate with
    // its independent re-measure (the result is measured once more for C above).
    j["search_estimate"] = {{"C", json::numberOrNull(r.bestSearchEvaluation.cost)}, {"L", json::numberOrNull(r.bestSearchEvaluation.lighting)},
                            {"C_std_error", json::numberOrNull(r.bestSearchEvaluation.costError)}};
    Json candidates = Json::array();
    for (size_t i = 0; i < r.candidates.size(); ++i) {
        const Candidate& c = r.candidates[i];
        Json e = {{"iteration", c.iteration}, {"search_C", json::numberOrNull(c.search.cost)}, {"chosen", int(i) == r.chosenCandidate}};
        if (c.independent) {
            e["remeasured_C"] = json::numberOrNull(c.independent->cost);
            e["remeasured_C_std_error"] = json::numberOrNull(c.independent->costError);
        }
        candidates.push_back(e);
    }
    j["candidates"] = candidates;
    // `measure --layout layout.json --seed S --paths N` repeats the report's measurement.
    // Null where no light was measured (no samplers): always present, for scripts.
    j["report_measurement"] = {{"seed", nullptr}, {"paths_per_point", nullptr}};
    if (r.reportSeed != 0) {
        int paths = 0;
        for (const SamplerResult& m : best.samplers.samplers) paths = std::max(paths, m.pathsPerPoint);
        j["report_measurement"] = {{"seed", r.reportSeed}, {"paths_per_point", paths}};
    }
    j["seconds"] = r.seconds;
    j["start_seconds"] = r.startSeconds;
    j["stop_reason"] = stopReasonName(r.stop);
    const Evaluation& start = r.startEvaluation;
    const bool startUnlit = !start.lightingEvaluated && !scene.samplers.empty() && scene.objective.lightingWeight > 0;
    j["start"] = {{"C", start.rejected || startUnlit ? Json(nullptr) : json::numberOrNull(start.cost)},
                  {"L", start.lightingEvaluated || scene.samplers.empty() ? json::numberOrNull(start.lighting) : Json(nullptr)},
                  {"G", start.rejected ? Json(nullptr) : json::numberOrNull(start.geometry)}, {"feasible", r.startFeasible},
                  {"planned", r.planned}};

    Json constraints = Json::array();
    Json pairs = Json::array();
    for (const PenaltyTerm& t : r.bestGeometry.terms)
        (t.overlap() ? pairs : constraints).push_back(termJson(scene, t));
    j["constraints"] = constraints;
    j["overlap"] = {{"tolerance", scene.overlap.tolerance}, {"weight", scene.overlap.weight},
                    {"penalty", r.bestGeometry.overlapPenalty}, {"pairs", pairs}};

    Json samplers = Json::array();
    for (size_t k = 0; k < best.samplers.samplers.size() && k < scene.samplers.size(); ++k) {
        const SamplerResult& m = best.samplers.samplers[k];
        const LightSamplerSpec& s = scene.samplers[k];
        const SamplerRow row(s, m);
        Json e = {{"name", s.name}, {"type", s.type->name()}, {"description", s.type->describe()}, {"unit", s.type->unit()},
                  {"value", json::numberOrNull(m.value)}, {"std_error", json::numberOrNull(m.standardError)}, {"target", {json::numberOrNull(s.targetMin), json::numberOrNull(s.targetMax)}},
                  {"tolerance", s.tolerance}, {"weight", s.weight}, {"penalty", json::numberOrNull(row.penalty())}};
        if (!m.points.empty()) e["points"] = m.points;
        if (s.type->hasPointStatistics()) e["covered"] = m.covered;
        if (k < r.lightingNotes.samplers.size()) e.update(r.lightingNotes.samplers[k]);
        if (k < r.samplerRanges.size()) {
            const SamplerRange& range = r.samplerRanges[k];
            const ReachVerdict verdict = reachVerdict(s, range, m);
            e["reach"] = {{"verdict", reachName(verdict.reach)},
                          {"lowest_seen", json::numberOrNull(range.lowest)},
                          {"highest_seen", json::numberOrNull(range.highest)},
                          {"layouts_measured", range.layouts}};
            if (!verdict.reason.empty()) e["reach"]["reason"] = verdict.reason;
        }
        e.update(row.detailsJson());
        samplers.push_back(e);
    }
    j["samplers"] = samplers;

    Json moves, levels = Json::array();
    for (MoveType t : kMoveTypes) {
        MoveStats total;
        for (const LevelStats& level : r.levels) {
            const MoveStats& s = level.moves[int(t)];
            total.proposed += s.proposed, total.accepted += s.accepted;
            total.outside += s.outside, total.rejectedGeometry += s.rejectedGeometry, total.screened += s.screened;
            total.pathsTraced += s.pathsTraced;
        }
        moves[moveName(t)] = moveJson(total);
    }
    for (const LevelStats& level : r.levels) {
        Json entities = Json::array(), m;
        for (int e : level.entities) entities.push_back(scene.entities[size_t(e)].path);
        for (MoveType t : kMoveTypes) m[moveName(t)] = moveJson(level.moves[int(t)]);
        levels.push_back({{"name", level.name}, {"entities", entities}, {"moves", m}});
    }
    j["moves"] = moves;
    if (!r.suggestions.empty()) {
        Json list = Json::array();
        for (size_t i = 0; i < r.suggestions.size(); ++i) {
            const Evaluation& e = *r.suggestions[i].independent;
            list.push_back({{"file", suggestionFile(i)}, {"C", json::numberOrNull(e.cost)},
                            {"C_std_error", json::numberOrNull(e.costError)}, {"iteration", r.suggestions[i].iteration}});
        }
        j["suggestions"] = list;
    }
    j["levels"] = levels;
    j.update(r.lightingNotes.run);

    j["polish_from"] = r.polishFrom;
    j["settings"] = settings;
    return j.dump(2) + "\n";
}

std::string suggestionFile(size_t index) { return "suggestions/" + std::to_string(index + 1) + ".json"; }

void writeReport(const std::filesystem::path& file, const Scene& scene, const OptimizerResult& result,
                 const RunSettings& settings) {
    writeFileAtomically(file, reportJson(scene, result, settings));
}

void writeTrace(const std::filesystem::path& file, const OptimizerResult& result) {
    std::ostringstream out;
    out.precision(10);
    out << "iteration,current,best,feasible,temperature,acceptance\n";
    for (const TracePoint& t : result.trace) {
        out << t.iteration << ',' << t.current << ',';
        if (std::isfinite(t.best)) out << t.best;
        out << ',' << (t.feasible ? 1 : 0) << ',' << t.temperature << ',' << t.acceptance << '\n';
    }
    writeFileAtomically(file, out.str());
}

void writeOptimizerOutputs(const std::filesystem::path& folder, const Scene& scene, const OptimizerResult& result,
                           const RunSettings& settings) {
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    if (ec) throw IoError("cannot create " + folder.string() + ": " + ec.message());
    writeReport(folder / "report.json", scene, result, settings);
    writeTrace(folder / "trace.csv", result);
}

}  // namespace luxplan
