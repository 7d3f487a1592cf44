// The annual plan's cells from the planar samplers' grids, and the annual pictures' files.
#include <luxplan/output/annual_plan.h>

#include <cmath>
#include <set>

#include <luxplan/annual/annual_metrics.h>
#include <luxplan/core/error.h>
#include <luxplan/lightsamplers/sampler_type.h>
#include <luxplan/output/temporal_map.h>

namespace luxplan {
namespace {

const LightSamplerSpec* specNamed(const Scene& scene, const std::string& name) {
    for (const LightSamplerSpec& s : scene.samplers)
        if (s.name == name) return &s;
    return nullptr;
}

// A file name from a sampler's name: letters, digits, '-', '_' and '.' kept.
std::string fileStem(const std::string& name) {
    std::string out;
    for (char c : name) {
        const bool keep = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_' || c == '.';
        out += keep ? c : '_';
    }
    return out.empty() ? std::string("sampler") : out;
}

}  // namespace

PlanCells annualPlanCells(const Scene& scene, const Layout& layout, const AnnualSeries& series) {
    PlanCells cells;
    cells.colors.scale = ColorScale::Linear;
    cells.colors.maxValue = 100;
    cells.unit = "% of hours in range";
    const std::vector<Transform> world = worldTransforms(scene, layout);
    for (const AnnualSampler& s : series.samplers) {
        if (!s.planar) continue;
        const LightSamplerSpec* spec = specNamed(scene, s.name);
        if (!spec) continue;
        const std::optional<std::array<int, 2>> grid = spec->type->pointGrid();
        const Transform t = spec->entity >= 0 ? world[size_t(spec->entity)] : Transform();
        const SamplerDrawing drawing = spec->type->place(t)->drawing();
        // A planar sampler's outline is its rectangle, corner 0 at the grid's first
        // point's corner, 1 along the first side, 3 along the second (planar.cpp).
        if (!grid || drawing.outline.size() != 4 || size_t((*grid)[0]) * size_t((*grid)[1]) != s.points.size()) continue;
        const Vec3 c0 = drawing.outline[0];
        const Vec3 du = (drawing.outline[1] - c0) / double((*grid)[0]), dv = (drawing.outline[3] - c0) / double((*grid)[1]);
        const AnnualMetrics m = annualMetrics(s, series);
        for (int j = 0; j < (*grid)[1]; ++j)
            for (int i = 0; i < (*grid)[0]; ++i) {
                const Vec3 p = c0 + du * double(i) + dv * double(j);
                cells.quads.push_back({p, p + du, p + du + dv, p + dv});
                cells.values.push_back(100 * m.pointsInRange[size_t(j) * size_t((*grid)[0]) + size_t(i)]);
            }
    }
    return cells;
}

namespace {

Image annualPlanOf(const Scene& scene, const Layout& layout, const AnnualSeries& series, PlanCells cells, PlanOptions options) {
    if (options.title.empty()) options.title = "Share of " + std::to_string(series.hours.size()) + " hours in each point's target band";
    PlanData data;
    data.cells = std::move(cells);
    return renderPlan(scene, layout, options, data);
}

}  // namespace

Image renderAnnualPlan(const Scene& scene, const Layout& layout, const AnnualSeries& series, const PlanOptions& options) {
    return annualPlanOf(scene, layout, series, annualPlanCells(scene, layout, series), options);
}

std::vector<std::filesystem::path> writeAnnualPictures(const std::filesystem::path& folder, const Scene& scene,
                                                       const Layout& layout, const AnnualSeries& series) {
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    if (ec) throw IoError("cannot create " + folder.string() + ": " + ec.message());
    std::vector<std::filesystem::path> written;
    PlanCells cells = annualPlanCells(scene, layout, series);
    if (!cells.quads.empty()) {
        written.push_back(folder / "annual_plan.png");
        writePng(annualPlanOf(scene, layout, series, std::move(cells), {}), written.back());
    }
    std::set<std::string> stems;
    for (const AnnualSampler& s : series.samplers) {
        // Two names that differ only in replaced characters get distinct files.
        std::string stem = fileStem(s.name);
        for (int k = 2; !stems.insert(stem).second; ++k) stem = fileStem(s.name) + "_" + std::to_string(k);
        TemporalMapOptions o;
        const LightSamplerSpec* spec = specNamed(scene, s.name);
        o.unit = spec ? spec->type->unit() : (s.planar ? "lx" : "");
        written.push_back(folder / ("temporal_map_" + stem + ".png"));
        writePng(renderTemporalMap(s, series.hours, o), written.back());
    }
    return written;
}

}  // namespace luxplan
