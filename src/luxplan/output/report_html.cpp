// report.html: the run summary as one static page; every value is escaped, every
// link is relative to the page and only made to files that exist.
#include <luxplan/output/report_html.h>

#include <luxplan/optimizer/report.h>
#include <luxplan/output/report_viewer.h>
#include <luxplan/optimizer/reach.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <sstream>

#include <luxplan/constraints/constraint_type.h>
#include <luxplan/core/atomic_file.h>
#include <luxplan/core/error.h>
#include <luxplan/core/format.h>
#include <luxplan/constraints/penalty.h>
#include <luxplan/lightsamplers/sampler_type.h>
#include <luxplan/optimizer/sampler_report.h>
#include <luxplan/scene/layout.h>

namespace luxplan {
namespace {

constexpr const char* kStyle = R"(
body { font-family: system-ui, -apple-system, "Segoe UI", Helvetica, Arial, sans-serif; margin: 2em auto;
       max-width: 1200px; padding: 0 1em; color: #222; background: #fff; line-height: 1.4; }
h1 { font-size: 1.6em; margin-bottom: 0.2em; }
h2 { font-size: 1.25em; border-bottom: 1px solid #ddd; padding-bottom: 0.2em; margin-top: 1.8em; }
table { border-collapse: collapse; margin: 0.5em 0; font-size: 0.92em; }
th, td { border: 1px solid #ddd; padding: 0.25em 0.6em; text-align: left; vertical-align: top; }
th { background: #f4f4f4; }
td.num { text-align: right; font-variant-numeric: tabular-nums; }
.met { background: #dff3df; color: #15591a; font-weight: bold; }
.missed { background: #fbe0e0; color: #8a1414; font-weight: bold; }
.warn { background: #fff1cc; color: #7a5800; font-weight: bold; }
.muted { color: #777; }
figure { margin: 1em 0; }
figure img { max-width: 100%; height: auto; border: 1px solid #ddd; image-rendering: auto; }
figcaption { color: #555; font-size: 0.9em; }
dl.summary { display: grid; grid-template-columns: max-content auto; gap: 0.15em 1.2em; }
dl.summary dt { font-weight: bold; }
dl.summary dd { margin: 0; }
footer { margin-top: 3em; color: #888; font-size: 0.85em; }
p.lead { color: #555; margin-top: 0; }
p.verdict { padding: 0.4em 0.7em; display: inline-block; }
table.results td.result { white-space: nowrap; }
h1.appendix { font-size: 1.4em; margin-top: 2.5em; border-top: 3px solid #ccc; padding-top: 0.6em; }
.print-only { display: none; }
/* On paper (report.pdf): A4, no table or picture split across pages, pictures to the
   page's width, the appendix on a page of its own, no interactive 3D view. */
@media print {
  @page { size: A4; margin: 14mm 12mm; }
  body { max-width: none; margin: 0; padding: 0; font-size: 10pt; }
  table { font-size: 8.5pt; }
  table, tr, figure, dl.summary, p.verdict { break-inside: avoid; page-break-inside: avoid; }
  thead { display: table-header-group; }
  h1, h2, h3 { break-after: avoid; page-break-after: avoid; }
  figure img { max-width: 100%; width: auto; max-height: 24cm; border: none; }
  h1.appendix { break-before: page; page-break-before: always; border-top: none; margin-top: 0; }
  .screen-only, canvas { display: none !important; }
  .print-only { display: block; }
  a { color: inherit; text-decoration: none; }
  .met, .missed, .warn, th { -webkit-print-color-adjust: exact; print-color-adjust: exact; }
}
)";

// Captions of kReportImages, in its order.
constexpr const char* kImageCaptions[] = {
    "Plan: work-plane illuminance in false colour on a scale centred on the targets, isolux lines, Em, Emin, Emax "
    "and U0; light samplers green where they meet their targets, red where they miss them.",
    "The start layout and the shown layout side by side (same colour scale).",
    "Path-traced view (luminance tone mapped, colour from what each pixel sees).",
    "The same view in false colour of luminance (cd/m2, logarithmic).",
    "Convergence: current cost (grey) and best cost so far (blue) per iteration.",
    "The year: each task point's share of the occupied hours with the sun up whose illuminance lies in its sampler's "
    "target band (daylight coefficients under each hour's sky from the weather file)."};
static_assert(std::size(kImageCaptions) == std::size(kReportImages));

// Notes on kReportFiles, in its order.
constexpr const char* kFileNotes[] = {"the scene under the layout, binary glTF 2.0 (Blender: File > Import > glTF)",
                                      "the layout: where each movable entity stands (docs/scene-format.md, layout.json)", "costs, samplers, constraints and moves as JSON",
                                      "iteration, current and best cost"};
static_assert(std::size(kFileNotes) == std::size(kReportFiles));

// `digits` decimals; a dash for NaN, the infinity sign for an infinity.
std::string number(double v, int digits) {
    if (std::isnan(v)) return "&ndash;";
    if (std::isinf(v)) return v > 0 ? "&infin;" : "&minus;&infin;";
    return fixedDigits(v, digits);
}

std::string range(double lo, double hi, int digits) {
    std::string s = "[";
    s += number(lo, digits);
    s += ", ";
    s += number(hi, digits);
    s += "]";
    return s;
}

std::string cell(const std::string& html, const char* cls = nullptr) {
    return cls ? std::string("<td class=\"") + cls + "\">" + html + "</td>" : "<td>" + html + "</td>";
}

std::string entityName(const Scene& scene, int e) {
    if (e == kRoomEntity) return "room";
    if (e < 0 || size_t(e) >= scene.entities.size()) return "?";
    return scene.entities[size_t(e)].path;
}

std::string overlapTarget(const Scene& scene, const PenaltyTerm& t) {
    switch (t.target) {
        case OverlapTarget::Entity: return entityName(scene, t.b);
        case OverlapTarget::Static:
            return t.b >= 0 && size_t(t.b) < scene.geometry.size() ? scene.geometry[size_t(t.b)].name : "?";
        case OverlapTarget::Walls: return "walls";
    }
    return "?";
}

void summary(std::ostringstream& out, const Scene& scene, const ReportData& data) {
    out << "<h2>Scene</h2>\n<dl class=\"summary\">\n";
    auto item = [&](const std::string& key, const std::string& valueHtml) {
        out << "<dt>" << escapeHtml(key) << "</dt><dd>" << valueHtml << "</dd>\n";
    };
    item("name", escapeHtml(scene.name));
    if (!scene.file.empty()) item("file", escapeHtml(scene.file.string()));
    if (const RoomShell* room = scene.room()) {
        Vec3 s = room->box.size();
        item("room", number(s.x, 2) + " &times; " + number(s.y, 2) + " &times; " + number(s.z, 2) + " m, " +
                         std::to_string(room->openings.size()) + " openings");
    }
    size_t fixed = 0, movable = 0;
    for (const Emitter& e : scene.emitters) fixed += e.entity < 0;
    for (const Entity& e : scene.entities) movable += e.movable();
    item("luminaires", std::to_string(fixed) + " fixed, " + std::to_string(scene.emitters.size() - fixed) + " on entities");
    if (scene.maintenanceFactor != 1)
        item("maintenance factor", number(scene.maintenanceFactor, 2) +
                                       " (maintained illuminance: the luminaires' light scaled by it, the daylight not)");
    item("entities", std::to_string(scene.entities.size()) + " (" + std::to_string(movable) + " movable)");
    item("samplers", std::to_string(scene.samplers.size()));
    item("constraints", std::to_string(scene.constraints.size()));
    if (scene.daylight) {
        std::string when = scene.daylight->from ? scene.daylight->from->str() : "";
        if (scene.daylight->to) when += " to " + scene.daylight->to->str();
        item("daylight", escapeHtml(std::string(skyModelNames().name(scene.daylight->model)) + " sky" +
                                    (when.empty() ? "" : ", " + when)));
    } else {
        item("daylight", "none (night)");
    }
    item("lighting weight", number(scene.objective.lightingWeight, 2));
    if (!data.layoutLabel.empty()) item("layout shown", escapeHtml(data.layoutLabel));
    out << "</dl>\n";
}

void optimizerSummary(std::ostringstream& out, const Scene& scene, const OptimizerResult& r) {
    out << "<h2>Optimization</h2>\n<table>\n<tr><th></th><th>C</th><th>L</th><th>G</th><th>feasible</th></tr>\n";
    auto row = [&](const char* name, const Evaluation& e, bool feasible) {
        // A layout whose light was never measured has no L, and so no C: never a 0.
        const bool unlit = !e.lightingEvaluated && !scene.samplers.empty() && scene.objective.lightingWeight > 0;
        const std::string notMeasured = "<span class=\"muted\">not measured</span>";
        out << "<tr><th>" << name << "</th>" << cell(unlit ? notMeasured : number(e.cost, 4), nullptr)
            << cell(unlit ? notMeasured : number(e.lighting, 4))
            << cell(number(e.geometry, 4)) << cell(feasible ? "yes" : "no", feasible ? "met" : "missed") << "</tr>\n";
    };
    row("start", r.startEvaluation, r.startFeasible);
    row("best", r.bestEvaluation, r.feasible);
    out << "</table>\n<p>" << r.iterations << " iterations in " << number(r.seconds, 1) << " s, stopped by "
        << escapeHtml(stopReasonName(r.stop)) << "; best found at iteration " << r.bestIteration << "; seed "
        << r.options.seed << ", " << (r.options.hierarchy == Hierarchy::Flat ? "flat" : "hierarchical") << ".";
    if (r.bestEvaluation.rejected) out << " Rejected by " << escapeHtml(r.bestEvaluation.rejectedBy) << ".";
    out << "</p>\n";
    if (r.feasible) {
        const GoalCount goals = countGoals(scene, r);
        out << "<p class=\"" << (goals.all() ? "met" : "missed") << "\">" << escapeHtml(goals.sentence())
            << " (a rule at any penalty above 0 is not held).</p>\n";
    }
}

// RFC 4648 base64 of `bytes`.
std::string reportBase64(const std::string& bytes) {
    static const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    for (size_t i = 0; i < bytes.size(); i += 3) {
        const uint32_t a = uint8_t(bytes[i]), b = i + 1 < bytes.size() ? uint8_t(bytes[i + 1]) : 0,
                       c = i + 2 < bytes.size() ? uint8_t(bytes[i + 2]) : 0;
        const uint32_t n = a << 16 | b << 8 | c;
        out += alphabet[n >> 18 & 63];
        out += alphabet[n >> 12 & 63];
        out += i + 1 < bytes.size() ? alphabet[n >> 6 & 63] : '=';
        out += i + 2 < bytes.size() ? alphabet[n & 63] : '=';
    }
    return out;
}

// The file's bytes as a data: URI, so that the page carries its pictures (and
// report.pdf prints them) without the files beside it. Throws IoError.
std::string pictureDataUri(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw IoError("cannot read " + file.string() + " for report.html");
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return "data:image/png;base64," + reportBase64(bytes);
}

void pictures(std::ostringstream& out, const std::filesystem::path& folder) {
    std::ostringstream figs;
    for (size_t i = 0; i < std::size(kReportImages); ++i) {
        const char* file = kReportImages[i];
        if (!std::filesystem::is_regular_file(folder / file)) continue;
        // Embedded; the link opens the PNG file beside the page at full size.
        figs << "<figure><a href=\"" << escapeHtml(file) << "\"><img src=\"" << pictureDataUri(folder / file)
             << "\" alt=\"" << escapeHtml(kImageCaptions[i]) << "\"></a><figcaption>" << escapeHtml(kImageCaptions[i])
             << "</figcaption></figure>\n";
    }
    std::vector<std::filesystem::path> maps;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
        const std::string name = entry.path().filename().string();
        if (name.starts_with("temporal_map_") && name.ends_with(".png") && entry.is_regular_file()) maps.push_back(entry.path());
    }
    std::sort(maps.begin(), maps.end());
    for (const std::filesystem::path& map : maps) {
        const std::string name = map.filename().string();
        const std::string caption = "Temporal map of " + name.substr(13, name.size() - 17) +
                                    ": its value in each occupied hour of the year, day of the year across, hour of the day "
                                    "up, in false colour.";
        figs << "<figure><a href=\"" << escapeHtml(name) << "\"><img src=\"" << pictureDataUri(map) << "\" alt=\""
             << escapeHtml(caption) << "\"></a><figcaption>" << escapeHtml(caption) << "</figcaption></figure>\n";
    }
    if (!figs.str().empty()) out << "<h2>Pictures</h2>\n" << figs.str();
    std::ostringstream files;
    for (size_t i = 0; i < std::size(kReportFiles); ++i) {
        if (!std::filesystem::is_regular_file(folder / kReportFiles[i])) continue;
        files << "<li><a href=\"" << escapeHtml(kReportFiles[i]) << "\">" << escapeHtml(kReportFiles[i]) << "</a>: "
              << escapeHtml(kFileNotes[i]) << "</li>\n";
    }
    if (!files.str().empty()) out << "<h2>Files</h2>\n<ul>\n" << files.str() << "</ul>\n";
}

std::string percent(double share) { return fixedDigits(100 * share, 0) + "%"; }

// A goal's status in words and its cell's class: met, at its bound within noise (past
// it by less than a standard error: not called missed), or missed.
struct GoalStatus {
    const char* words;
    const char* cls;
};
GoalStatus goalStatus(bool met, double value, double standardError, double lo, double hi) {
    if (met) return {"met", "met"};
    const double past = value < lo ? lo - value : value - hi;
    if (standardError > 0 && past <= standardError) return {"at bound (within noise)", "warn"};
    return {"missed", "missed"};
}
GoalStatus samplerStatus(const SamplerRow& row) {
    if (row.met()) return {"met", "met"};
    return reachVerdict(row.sampler(), SamplerRange(), row.result()).reach == Reach::WithinNoise
               ? GoalStatus{"at bound (within noise)", "warn"}
               : GoalStatus{"missed", "missed"};
}

// Each scene sampler's measurement shown on the page (the data's, else the result's),
// null where it was not measured.
std::vector<const SamplerResult*> shownSamplers(const Scene& scene, const std::vector<SamplerResult>& measured,
                                                const OptimizerResult* result) {
    std::vector<const SamplerResult*> rows(scene.samplers.size(), nullptr);
    const std::vector<SamplerResult>* source = !measured.empty() ? &measured
                                               : result && result->bestEvaluation.lightingEvaluated
                                                   ? &result->bestEvaluation.samplers.samplers
                                                   : nullptr;
    for (size_t k = 0; source && k < rows.size() && k < source->size(); ++k) rows[k] = &(*source)[k];
    return rows;
}

// The results table's verdict on one goal, in words a client reads: pass, at bound
// (within noise) (past the bound by less than the value's standard error: never
// called a fail), or fail.
GoalStatus clientStatus(const LightingTerm& t) {
    const GoalStatus status = goalStatus(t.penalty == 0, t.value, t.standardError, t.targetMin, t.targetMax);
    if (std::string(status.cls) == "met") return {"pass", "met"};
    if (std::string(status.cls) == "warn") return status;
    return {"fail", "missed"};
}

// A unit after a number ("" for the quantities that are their own unit: UGR, DGP).
std::string unitAfter(const LightSamplerSpec& s) {
    const std::string u = s.type->unit();
    if (s.type->valueFormat().unitless) return "";
    if (u == "cd/m2") return "&nbsp;cd/m&sup2;";
    return "&nbsp;" + escapeHtml(u);
}

// A sampler's value with `digits` decimals and `unit` after it; "&lt;10" below its
// type's floor.
std::string samplerValueHtml(const SamplerRow& row, int digits, const std::string& unit) {
    const double v = row.result().value;
    if (v < row.format().floor) return escapeHtml(row.valueText(digits));
    return number(v, digits) + unit;
}

// A target band as a client reads it: "&ge; 300 lx", "&le; 19", "300 to 500 lx".
std::string targetWords(double lo, double hi, int digits, const std::string& unit) {
    const bool low = std::isfinite(lo) && lo > 0, high = std::isfinite(hi);
    if (low && high) return number(lo, digits) + " to " + number(hi, digits) + unit;
    if (low) return "&ge; " + number(lo, digits) + unit;
    if (high) return "&le; " + number(hi, digits) + unit;
    return "any";
}

// What a quantity is called in the results: by the sampler's type. A mean illuminance
// is a maintained one (EN 12464-1) only where a maintenance factor below 1 made it so.
std::string quantityName(const Scene& scene, const LightSamplerSpec& s) {
    return s.type->quantityHtml(scene.maintenanceFactor < 1);
}

// The goals sentence for the page: the optimizer's count when the page shows its
// result; else counted here from the samplers and the rules shown (as countGoals).
std::string goalsSentence(const Scene& scene, const OptimizerResult* result, const ReportData& data,
                          const std::vector<const SamplerResult*>& rows, const GeometryResult* geometry, const char*& cls) {
    // Green when every goal is met, amber when the only shortfalls are within noise.
    auto classOf = [](const GoalCount& g) {
        if (g.all()) return "met";
        return g.lightingMet + g.lightingWithinNoise == g.lighting && g.rulesHeld == g.rules ? "warn" : "missed";
    };
    if (result && !data.geometry) {
        const GoalCount goals = countGoals(scene, *result);
        cls = classOf(goals);
        return goals.sentence();
    }
    GoalCount g;
    g.lighting = int(scene.samplers.size());
    for (size_t k = 0; k < rows.size(); ++k) {
        if (!rows[k]) continue;
        const Reach reach = reachVerdict(scene.samplers[k], SamplerRange(), *rows[k]).reach;
        g.lightingMet += reach == Reach::Met;
        g.lightingWithinNoise += reach == Reach::WithinNoise;
    }
    if (!geometry) {
        cls = classOf(g);
        std::string sentence = g.sentence();
        return sentence.substr(0, sentence.rfind(", "));  // no rules evaluated: the lighting goals only
    }
    for (const PenaltyTerm& t : geometry->terms)
        if (!t.overlap()) {
            ++g.rules;
            g.rulesHeld += !geometry->rejected && t.penalty == 0;
        }
    ++g.rules;  // overlap, one rule
    g.rulesHeld += !geometry->rejected && geometry->overlapPenalty == 0;
    cls = classOf(g);
    return g.sentence();
}

// One results row: a quantity, its value, its target and its verdict ("no target"
// for a figure no goal is set on).
void resultRow(std::ostringstream& out, const std::string& nameCell, const std::string& quantity, const std::string& value,
               const std::string& target, const GoalStatus* status) {
    out << "<tr>" << nameCell << cell(quantity) << "<td class=\"num\">" << value << "</td>" << cell(target);
    if (status) out << "<td class=\"result " << status->cls << "\">" << status->words << "</td>";
    else out << "<td class=\"result muted\">no target</td>";
    out << "</tr>\n";
}

// Results first: the goals sentence, per task area (planar sampler) Em, Emin and U0
// against their targets, the glare samplers (ugr, dgp, directional) and any other
// sampler as rows of their own, and C, L and G each in a sentence.
void resultsSection(std::ostringstream& out, const Scene& scene, const OptimizerResult* result, const ReportData& data) {
    out << "<h2 id=\"results\">Results</h2>\n";
    const std::vector<const SamplerResult*> rows = shownSamplers(scene, data.samplers, result);
    const GeometryResult* geometry = data.geometry ? &*data.geometry : result ? &result->bestGeometry : nullptr;
    const char* cls = "missed";
    if (result && !result->feasible) {
        out << "<p class=\"verdict missed\">No layout kept every design rule within its hard limit"
            << (result->bestEvaluation.rejectedBy.empty() ? "" : " (" + escapeHtml(result->bestEvaluation.rejectedBy) + ")")
            << ": the layout shown is the least violating one.</p>\n";
    } else {
        const std::string sentence = goalsSentence(scene, result, data, rows, geometry, cls);
        out << "<p class=\"verdict " << cls << "\">" << escapeHtml(sentence)
            << (geometry ? " (a rule at any penalty above 0 is not held)" : "") << ".</p>\n";
    }
    if (scene.samplers.empty()) out << "<p class=\"muted\">The scene has no light samplers: no lighting goals.</p>\n";

    // Task areas: the planar samplers.
    std::ostringstream areas, glare, other;
    for (size_t k = 0; k < rows.size(); ++k) {
        const LightSamplerSpec& s = scene.samplers[k];
        const ResultGroup group = s.type->resultGroup();
        const std::string unit = unitAfter(s);
        const int digits = s.type->valueFormat().summaryDigits;
        std::ostringstream& table = group == ResultGroup::TaskArea ? areas : group == ResultGroup::Glare ? glare : other;
        if (!rows[k]) {
            table << "<tr>" << cell("<b>" + escapeHtml(s.name) + "</b>") << cell(quantityName(scene, s))
                  << "<td class=\"num\">&ndash;</td>" << cell(targetWords(s.targetMin, s.targetMax, digits, unit))
                  << "<td class=\"result muted\">not measured</td></tr>\n";
            continue;
        }
        const SamplerRow row(s, *rows[k]);
        const std::vector<LightingTerm>& terms = row.terms();
        // The value against the sampler's target.
        const GoalStatus valueStatus = clientStatus(terms.front());
        const std::string value = samplerValueHtml(row, digits, unit);
        if (group != ResultGroup::TaskArea || !row.statistics()) {
            resultRow(table, cell("<b>" + escapeHtml(s.name) + "</b>"), quantityName(scene, s), value,
                      targetWords(s.targetMin, s.targetMax, digits, unit), &valueStatus);
            continue;
        }
        // A task area: Em, then Emin and U0 (and Emax where a goal is set on it), each
        // against its statistics goal if it has one.
        const PointStatistics& st = *row.statistics();
        auto goal = [&](Statistic statistic) -> const LightingTerm* {
            for (size_t i = 1; i < terms.size(); ++i)
                if (terms[i].statistic == statistic) return &terms[i];
            return nullptr;
        };
        struct Figure {
            std::string quantity, value, target;
            std::optional<GoalStatus> status;
        };
        std::vector<Figure> figures;
        figures.push_back({quantityName(scene, s), value, targetWords(s.targetMin, s.targetMax, digits, unit), valueStatus});
        const bool points = !rows[k]->points.empty();
        for (Statistic statistic : {Statistic::Min, Statistic::U0, Statistic::Max}) {
            const LightingTerm* t = goal(statistic);
            if (!t && (!points || statistic == Statistic::Max)) continue;
            const bool ratio = statistic == Statistic::U0;
            const std::string u = ratio ? "" : unit;
            const int d = ratio ? 2 : digits;
            const double v = t ? t->value : st.of(statistic).value;
            const char* name = statistic == Statistic::Min   ? "E<sub>min</sub>"
                               : statistic == Statistic::U0 ? "U<sub>0</sub> = E<sub>min</sub> / E<sub>m</sub>"
                                                            : "E<sub>max</sub>";
            Figure f{name, number(v, d) + (std::isfinite(v) ? u : ""), t ? targetWords(t->targetMin, t->targetMax, d, u) : "&ndash;",
                     std::nullopt};
            if (t) f.status = clientStatus(*t);
            figures.push_back(f);
        }
        for (size_t i = 0; i < figures.size(); ++i) {
            const std::string nameCell =
                i == 0 ? "<td rowspan=\"" + std::to_string(figures.size()) + "\"><b>" + escapeHtml(s.name) + "</b></td>" : "";
            resultRow(table, nameCell, figures[i].quantity, figures[i].value, figures[i].target,
                      figures[i].status ? &*figures[i].status : nullptr);
        }
    }
    const char* head = "<table class=\"results\">\n<thead><tr><th>%s</th><th>quantity</th><th>value</th><th>target</th>"
                       "<th>result</th></tr></thead>\n";
    auto table = [&](const char* title, const char* first, const std::ostringstream& body) {
        if (body.str().empty()) return;
        char header[512];
        std::snprintf(header, sizeof header, head, first);
        out << "<h3>" << title << "</h3>\n" << header << body.str() << "</table>\n";
    };
    table("Task areas", "task area", areas);
    table("Glare", "viewpoint", glare);
    table("Other light samplers", "sampler", other);
    if (!scene.samplers.empty())
        out << "<p class=\"muted\"><b>pass</b>: inside its target. <b>at bound (within noise)</b>: outside its target by "
               "less than the measurement's standard error, so as good as on the bound. <b>fail</b>: outside its target "
               "by more than that. Illuminance in lx, luminance in cd/m&sup2;; E<sub>m</sub> is the mean over the task "
               "area's grid of points, E<sub>min</sub> the lowest point.</p>\n";

    // C, L and G, each in a sentence.
    const double w = scene.objective.lightingWeight;
    std::optional<double> c, l, g;
    std::string rejectedBy;
    if (result && !data.geometry) {
        const Evaluation& e = result->bestEvaluation;
        if (e.lightingEvaluated || scene.samplers.empty()) l = e.lighting;
        if (!e.rejected) g = e.geometry;
        rejectedBy = e.rejectedBy;
    } else {
        bool measured = !rows.empty();
        std::vector<SamplerResult> values;
        for (const SamplerResult* r : rows) {
            measured = measured && r;
            if (r) values.push_back(*r);
        }
        if (measured) l = lightingCostOfResults(scene, values);
        if (scene.samplers.empty()) l = 0;
        if (geometry && !geometry->rejected) g = geometry->cost;
        if (geometry) rejectedBy = geometry->rejectedBy;
    }
    if (l && g) c = scene.objective.cost(*l, *g);
    auto figure = [](const std::optional<double>& v) { return v ? number(*v, 4) : std::string("&ndash;"); };
    out << "<h3>The objective</h3>\n<dl class=\"summary\">\n"
        << "<dt>C = " << figure(c) << "</dt><dd>the objective, C = w&middot;L + (1 &minus; w)&middot;G with the lighting "
        << "weight w = " << number(w, 2) << ": what the search makes as small as it can; 0 when every lighting goal is "
        << "met and every design rule holds.</dd>\n"
        << "<dt>L = " << figure(l) << "</dt><dd>the lighting penalty: 0 when every lighting goal is met, growing as "
        << "values fall further outside their targets" << (l ? "" : " (not measured)") << ".</dd>\n"
        << "<dt>G = " << figure(g) << "</dt><dd>the design-rule penalty: 0 when every design rule (distances, "
        << "alignments, overlaps, footprints) holds"
        << (g ? std::string("") : geometry ? ", none here: a hard limit is passed" + (rejectedBy.empty() ? std::string("") : " (" + escapeHtml(rejectedBy) + ")") : std::string(" (not evaluated)"))
        << ".</dd>\n</dl>\n";
}

void samplerTable(std::ostringstream& out, const Scene& scene, const std::vector<SamplerResult>& measured,
                  const OptimizerResult* result, const std::vector<SamplerBudget>& budgets) {
    if (scene.samplers.empty()) return;
    const std::vector<const SamplerResult*> rows = shownSamplers(scene, measured, result);
    // The measured samplers' rows (none where not measured).
    std::vector<std::optional<SamplerRow>> presented(rows.size());
    int met = 0, known = 0;
    bool statistics = false, goals = false;
    for (size_t k = 0; k < rows.size(); ++k) {
        if (!rows[k]) continue;
        const SamplerRow& row = presented[k].emplace(scene.samplers[k], *rows[k]);
        ++known;
        met += row.met();
        statistics = statistics || row.statistics();
        goals = goals || row.terms().size() > 1;
    }
    out << "<h2>Light samplers</h2>\n";
    if (known) out << "<p>" << met << " of " << known << " samplers meet their targets.</p>\n";
    else out << "<p class=\"muted\">Not measured (the lighting term was not evaluated).</p>\n";
    const bool withBudgets = budgets.size() == rows.size();
    const bool withRanges = result && result->samplerRanges.size() == rows.size();
    out << "<table>\n<tr><th>name</th><th>type</th><th>entity</th><th>value</th><th>unit</th><th>target</th>"
           "<th>tolerance</th><th>penalty</th><th>status</th>"
        << (withBudgets ? "<th>light from</th>" : "") << "</tr>\n";
    std::vector<std::pair<std::string, std::string>> misses;  // (name, why), listed under the table
    for (size_t k = 0; k < rows.size(); ++k) {
        const LightSamplerSpec& s = scene.samplers[k];
        out << "<tr>" << cell(escapeHtml(s.name)) << "<td title=\"" << escapeHtml(s.type->describe()) << "\">"
            << escapeHtml(s.type->name()) << "</td>"
            << cell(s.entity >= 0 ? escapeHtml(entityName(scene, s.entity)) : "<span class=\"muted\">fixed</span>");
        if (presented[k]) {
            const GoalStatus status = samplerStatus(*presented[k]);
            out << "<td class=\"num\">" << number(rows[k]->value, 1) << "</td>" << cell(escapeHtml(s.type->unit()))
                << cell(range(s.targetMin, s.targetMax, 0)) << "<td class=\"num\">" << number(s.tolerance, 1) << "</td>"
                << "<td class=\"num\">" << number(presented[k]->penalty(), 3) << "</td>" << cell(status.words, status.cls);
            if (withBudgets) out << cell(escapeHtml(describeBudget(scene, budgets[k])));
            if (withBudgets || withRanges) {
                std::string why;
                if (withRanges) {
                    const ReachVerdict verdict = reachVerdict(s, result->samplerRanges[k], *rows[k]);
                    if (verdict.reach != Reach::Met) {
                        why = reachName(verdict.reach);
                        if (!verdict.reason.empty()) why += ": " + verdict.reason;
                    }
                }
                if (withBudgets) {
                    const std::string advice = missAdvice(scene, s, rows[k]->value, budgets[k]);
                    if (!advice.empty()) why += (why.empty() ? "" : ". ") + advice;
                    if (!advice.empty() && !withRanges) why += " (one layout measured: no search says whether it can be met)";
                }
                if (!why.empty()) misses.push_back({s.name, why});
            }
        } else {
            out << "<td class=\"num\">&ndash;</td>" << cell(escapeHtml(s.type->unit())) << cell(range(s.targetMin, s.targetMax, 0))
                << "<td class=\"num\">" << number(s.tolerance, 1) << "</td><td class=\"num\">&ndash;</td>"
                << cell("not measured", "muted");
            if (withBudgets) out << cell("&ndash;");
        }
        out << "</tr>\n";
    }
    out << "</table>\n";
    if (withBudgets)
        out << "<p class=\"muted\">Light from: the share of each sampler's light that comes straight from the sun, the sky "
               "(with the ground outside), each luminaire, and from light reflected by the room's surfaces first "
               "(interreflection), over all its points or strata.</p>\n";
    if (!misses.empty()) {
        out << "<h3>Why samplers miss, and whether they can be met</h3>\n<ul>\n";
        for (const auto& [name, why] : misses) out << "<li><b>" << escapeHtml(name) << "</b>: " << escapeHtml(why) << "</li>\n";
        out << "</ul>\n";
    }
    if (statistics) {
        // EN 12464-1's figures over each planar and volume sampler's points.
        out << "<h3>Statistics over the points (EN 12464-1: E<sub>m</sub>, E<sub>min</sub>, E<sub>max</sub>, "
               "U<sub>0</sub>)</h3>\n<table>\n<tr><th>name</th><th>points</th><th>mean</th><th>min</th><th>max</th>"
               "<th>U<sub>0</sub> = min / mean</th><th>unit</th></tr>\n";
        for (size_t k = 0; k < rows.size(); ++k) {
            const LightSamplerSpec& s = scene.samplers[k];
            if (!presented[k] || !presented[k]->statistics()) continue;
            const PointStatistics& st = *presented[k]->statistics();
            std::string grid = std::to_string(rows[k]->points.size());
            if (auto g = s.type->pointGrid()) grid = std::to_string((*g)[0]) + " &times; " + std::to_string((*g)[1]);
            out << "<tr>" << cell(escapeHtml(s.name)) << cell(grid) << "<td class=\"num\">" << number(st.mean.value, 1)
                << "</td><td class=\"num\">" << number(st.min.value, 1) << "</td><td class=\"num\">"
                << number(st.max.value, 1) << "</td><td class=\"num\">" << number(st.u0.value, 2) << "</td>"
                << cell(escapeHtml(s.type->unit())) << "</tr>\n";
        }
        out << "</table>\n";
    }
    // The glare sources each UGR and DGP sampler found (docs/glare.md).
    bool glare = false;
    for (const SamplerResult* r : rows) glare = glare || (r && r->glare);
    if (glare) {
        out << "<h3>Glare sources (UGR: CIE 117; DGP: Wienold and Christoffersen 2006)</h3>\n<table>\n<tr><th>name</th>"
               "<th>value</th><th>E<sub>v</sub> (lx)</th><th>L<sub>b</sub> (cd/m&sup2;)</th><th>source</th><th>direction</th>"
               "<th>L (cd/m&sup2;)</th><th>&omega; (sr)</th><th>P</th></tr>\n";
        for (size_t k = 0; k < rows.size(); ++k) {
            if (!presented[k] || !rows[k]->glare) continue;
            const GlareSurvey& g = *rows[k]->glare;
            const SamplerRow& row = *presented[k];
            const std::string value = samplerValueHtml(row, row.format().digits, "");
            const std::string head = "<tr>" + cell(escapeHtml(scene.samplers[k].name)) + "<td class=\"num\">" + value +
                                     "</td><td class=\"num\">" + number(g.verticalIlluminance, 0) + "</td><td class=\"num\">" +
                                     number(g.backgroundLuminance, 1) + "</td>";
            if (g.sources.empty()) out << head << "<td colspan=\"5\">no source</td></tr>\n";
            for (const GlareSource& src : g.sources)
                out << head << cell(glareSourceKindName(src.kind)) << "<td>[" << number(src.direction.x, 2) << ", " << number(src.direction.y, 2) << ", "
                    << number(src.direction.z, 2) << "]</td><td class=\"num\">" << number(src.luminance, 0)
                    << "</td><td class=\"num\">" << number(src.solidAngle, 5) << "</td><td class=\"num\">"
                    << number(src.positionIndex, 2) << "</td></tr>\n";
        }
        out << "</table>\n";
    }
    if (goals) {
        out << "<h3>Statistics goals</h3>\n<table>\n<tr><th>name</th><th>statistic</th><th>value</th><th>target</th>"
               "<th>tolerance</th><th>penalty</th><th>status</th></tr>\n";
        for (size_t k = 0; k < rows.size(); ++k)
            for (size_t i = 1; presented[k] && i < presented[k]->terms().size(); ++i) {
                const LightingTerm& t = presented[k]->terms()[i];
                const int digits = t.statistic == Statistic::U0 || t.statistic == Statistic::AnnualInRange ? 2 : 1;
                const GoalStatus status = goalStatus(t.penalty == 0, t.value, t.standardError, t.targetMin, t.targetMax);
                out << "<tr>" << cell(escapeHtml(scene.samplers[k].name)) << cell(statisticNames().name(t.statistic))
                    << "<td class=\"num\">" << number(t.value, digits) << "</td>" << cell(range(t.targetMin, t.targetMax, digits))
                    << "<td class=\"num\">" << number(t.tolerance, digits) << "</td><td class=\"num\">" << number(t.penalty, 3)
                    << "</td>" << cell(status.words, status.cls) << "</tr>\n";
            }
        out << "</table>\n";
    }
}

// The period hour by hour: one row per instant, one column per sampler, each value
// green when it meets the sampler's goals at that hour, red when not.
void hourTable(std::ostringstream& out, const Scene& scene, const std::vector<ReportData::Hour>& hours) {
    if (hours.empty() || scene.samplers.empty()) return;
    out << "<h2>The daylight hour by hour</h2>\n<p class=\"muted\">Each instant measured alone (as <code>measure --at</code>), "
           "for the layout shown; the tables above average the whole period.</p>\n<table>\n<tr><th>time</th>";
    for (const LightSamplerSpec& s : scene.samplers)
        out << "<th>" << escapeHtml(s.name) << " (" << escapeHtml(s.type->unit()) << ")</th>";
    out << "<th>met</th></tr>\n";
    for (const ReportData::Hour& h : hours) {
        out << "<tr>" << cell(escapeHtml(h.at));
        int met = 0;
        for (size_t k = 0; k < scene.samplers.size(); ++k) {
            if (k >= h.samplers.size()) {
                out << cell("&ndash;");
                continue;
            }
            // An hour is judged by the goals of an instant: the annual goal is the year's.
            LightSamplerSpec instantGoals = scene.samplers[k];
            instantGoals.annual.reset();
            const SamplerRow row(instantGoals, h.samplers[k]);
            const GoalStatus status = samplerStatus(row);
            met += row.met();
            out << "<td class=\"num " << status.cls << "\">" << number(h.samplers[k].value, 1) << "</td>";
        }
        out << "<td class=\"num\">" << met << " of " << scene.samplers.size() << "</td></tr>\n";
    }
    out << "</table>\n";
}

void constraintTables(std::ostringstream& out, const Scene& scene, const GeometryResult& g) {
    std::ostringstream rel, pairs;
    int relCount = 0, pairCount = 0;
    for (const PenaltyTerm& t : g.terms) {
        const char* cls = t.rejects ? "missed" : (t.penalty > 0 ? "warn" : "met");
        const char* status = t.rejects ? "rejects" : (t.penalty > 0 ? "penalized" : "met");
        if (t.overlap()) {
            ++pairCount;
            pairs << "<tr>" << cell(escapeHtml(entityName(scene, t.a))) << cell(escapeHtml(overlapTarget(scene, t)))
                  << "<td class=\"num\">" << number(t.value, 4) << "</td><td class=\"num\">" << number(t.reference, 4)
                  << "</td><td class=\"num\">" << number(t.penalty, 3) << "</td>" << cell(status, cls) << "</tr>\n";
            continue;
        }
        ++relCount;
        // An angle is held to its tolerance, a distance to its range.
        const bool angle = t.kind->measuresAngle();
        std::string value = angle ? number(degrees(t.value), 1) + " deg" : number(t.value, 2) + " m";
        std::string bound;
        if (auto tolerance = t.kind->toleranceDeg(); angle && tolerance) bound = "&le; " + number(*tolerance, 1) + " deg";
        else if (auto r = t.kind->distanceRange(); !angle && r) bound = range(r->min, r->max, 2) + " m";
        rel << "<tr>" << cell(escapeHtml(termName(t))) << cell(escapeHtml(entityName(scene, t.a)))
            << cell(escapeHtml(entityName(scene, t.b))) << "<td class=\"num\">" << value << "</td>" << cell(bound)
            << "<td class=\"num\">" << number(t.weight, 2) << "</td><td class=\"num\">" << number(t.penalty, 3) << "</td>"
            << cell(status, cls) << "</tr>\n";
    }
    out << "<h2>Constraints</h2>\n<p>G = " << number(g.cost, 4) << (g.rejected ? ", rejected by " + escapeHtml(g.rejectedBy) : "")
        << ".</p>\n";
    if (relCount)
        out << "<table>\n<tr><th>type</th><th>a</th><th>b</th><th>value</th><th>bound</th><th>weight</th><th>penalty</th>"
               "<th>status</th></tr>\n"
            << rel.str() << "</table>\n";
    else
        out << "<p class=\"muted\">No relational constraints.</p>\n";
    out << "<h2>Overlaps</h2>\n<p>Overlap penalty " << number(g.overlapPenalty, 4) << " (tolerance "
        << number(100 * scene.overlap.tolerance, 1) << "% of the smaller volume); walls, static geometry and blockers: "
        << number(1e3 * scene.overlap.wallTolerance, 1) << " litres at most.</p>\n";
    for (const FootprintTerm& f : g.footprints) out << "<p class=\"missed\">" << escapeHtml(describe(scene, f)) << "</p>\n";
    if (pairCount)
        out << "<table>\n<tr><th>a</th><th>b</th><th>shared volume (m&sup3;)</th><th>reference (m&sup3;)</th>"
               "<th>penalty</th><th>status</th></tr>\n"
            << pairs.str() << "</table>\n";
    else
        out << "<p class=\"muted\">No overlapping pairs.</p>\n";
}

void moveTable(std::ostringstream& out, const OptimizerResult& r) {
    if (r.levels.empty()) return;
    out << "<h2>Moves</h2>\n<table>\n<tr><th>level</th><th>move</th><th>proposed</th><th>accepted</th><th>outside</th>"
           "<th>rejected (geometry)</th><th>screened (rules' change, no light traced)</th><th>acceptance</th>"
           "<th>paths traced (light)</th></tr>\n";
    for (const LevelStats& level : r.levels) {
        for (MoveType t : kMoveTypes) {
            const MoveStats& s = level.moves[int(t)];
            if (s.proposed == 0) continue;  // a move this level does not make
            out << "<tr>" << cell(escapeHtml(level.name) + " <span class=\"muted\">(" + std::to_string(level.entities.size()) +
                                  " entities)</span>")
                << cell(escapeHtml(moveName(t))) << "<td class=\"num\">" << s.proposed << "</td><td class=\"num\">"
                << s.accepted << "</td><td class=\"num\">" << s.outside << "</td><td class=\"num\">" << s.rejectedGeometry
                << "</td><td class=\"num\">" << s.screened << "</td><td class=\"num\">" << number(100 * s.acceptance(), 1)
                << "%</td><td class=\"num\">" << s.pathsTraced << "</td></tr>\n";
        }
    }
    out << "</table>\n";
}

void timingTable(std::ostringstream& out, const std::vector<ReportTiming>& timings) {
    if (timings.empty()) return;
    out << "<h2>Timings</h2>\n<table>\n<tr><th>step</th><th>seconds</th></tr>\n";
    for (const ReportTiming& t : timings)
        out << "<tr>" << cell(escapeHtml(t.what)) << "<td class=\"num\">" << number(t.seconds, 2) << "</td></tr>\n";
    out << "</table>\n";
}

}  // namespace

std::string missAdvice(const Scene& scene, const LightSamplerSpec& sampler, double value, const SamplerBudget& budget) {
    const bool low = value < sampler.targetMin, high = value > sampler.targetMax;
    if (!low && !high) return "";
    // The largest source among daylight (sun and sky), each luminaire, and reflected light.
    const double daylight = budget.sun + budget.sky;
    size_t lamp = 0;
    for (size_t e = 1; e < budget.emitters.size(); ++e)
        if (budget.emitters[e] > budget.emitters[lamp]) lamp = e;
    const double lampShare = budget.emitters.empty() ? 0 : budget.emitters[lamp];
    const std::string lampName = budget.emitters.empty() || lamp >= scene.emitters.size() ? "" : scene.emitters[lamp].name;
    std::string text = low ? "below its target" : "above its target";
    if (daylight + lampShare + budget.interreflected <= 0) return text + "; no light reaches it";
    if (daylight >= lampShare && daylight >= budget.interreflected) {
        text += "; " + percent(daylight) + " of its light is daylight (sun " + percent(budget.sun) + ", sky " + percent(budget.sky) + ")";
        if (low) text += ": nearer the window, or more light from a luminaire";
        else text += budget.sun >= budget.sky ? ": out of the sun patch, or a blind" : ": farther from the window, or a blind";
    } else if (lampShare >= budget.interreflected) {
        text += "; " + percent(lampShare) + " of its light is from " + lampName;
        text += low ? ": nearer it, or more flux" : ": farther from it, or less flux";
    } else {
        text += "; " + percent(budget.interreflected) + " of its light is reflected";
        text += low ? ": lighter surfaces around it, or a direct source" : ": darker surfaces around it";
    }
    return text;
}

std::string escapeHtml(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    for (char c : text) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            case '\'': out += "&#39;"; break;
            default: out += c;
        }
    }
    return out;
}

std::string reportHtml(const std::filesystem::path& folder, const Scene& scene, const OptimizerResult* result,
                       const ReportData& data) {
    std::string title = data.title.empty() ? "luxplan: " + scene.name : data.title;
    std::ostringstream out;
    out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
        << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>" << escapeHtml(title)
        << "</title>\n<style>" << kStyle << "</style>\n</head>\n<body>\n<h1>" << escapeHtml(title) << "</h1>\n";
    out << "<p class=\"lead\">" << escapeHtml(scene.name)
        << (data.layoutLabel.empty() ? "" : ", layout shown: " + escapeHtml(data.layoutLabel)) << ".</p>\n";
    // For the client: the results, the pictures, the room in 3D (on screen), the
    // daylight hour by hour, the scene and the files.
    resultsSection(out, scene, result, data);
    pictures(out, folder);
    if (std::string viewer = viewerSection(folder); !viewer.empty())
        out << "<div class=\"screen-only\">\n" << viewer << "</div>\n"
            << "<p class=\"print-only muted\">The room in 3D: open report.html in a browser to turn it.</p>\n";
    else if (!data.viewerNote.empty())
        out << "<div class=\"screen-only\">\n<h2>The room in 3D</h2>\n<p class=\"muted\">" << escapeHtml(data.viewerNote)
            << "</p>\n</div>\n";
    hourTable(out, scene, data.hours);
    summary(out, scene, data);
    // For the engineer: the search, the samplers' detail and light budgets, the rules'
    // terms, the moves and the timings.
    out << "<h1 class=\"appendix\" id=\"appendix\">Appendix: engineering detail</h1>\n";
    if (result) optimizerSummary(out, scene, *result);
    samplerTable(out, scene, data.samplers, result, data.budgets);
    if (data.geometry) constraintTables(out, scene, *data.geometry);
    else if (result) constraintTables(out, scene, result->bestGeometry);
    if (result) moveTable(out, *result);
    timingTable(out, data.timings);
    out << "<footer>Written by luxplan. " << (scene.maintenanceFactor != 1 ? "Maintained illuminance" : "Illuminance")
        << " in lx, luminance in cd/m&sup2;.</footer>\n</body>\n</html>\n";
    return out.str();
}

void writeReportHtml(const std::filesystem::path& folder, const Scene& scene, const OptimizerResult* result,
                     const ReportData& data) {
    writeFileAtomically(folder / "report.html", reportHtml(folder, scene, result, data));
}

}  // namespace luxplan
