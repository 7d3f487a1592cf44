// The plan view: the room from above with walls, openings, luminaires, furniture
// footprints and fronts, the light samplers coloured by whether they meet their
// targets, and a false-colour map of work-plane illuminance underneath with isolux
// contours, a legend centred on the targets and Em, Emin, Emax and U0.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <luxplan/core/point_statistics.h>
#include <luxplan/lightsamplers/light_samplers.h>
#include <luxplan/output/false_color.h>
#include <luxplan/output/image.h>
#include <luxplan/scene/layout.h>

namespace luxplan {

// Horizontal illuminance (lx, upward hemisphere) at the centres of nx x ny square cells
// at world height `height`; values row-major, x fastest, row 0 at the lowest y.
struct IlluminanceGrid {
    Vec2 origin;  // (x, y) of the corner of cell (0, 0)
    double cellSize = 0.25;
    double height = 0.8;  // world z of the cell centres
    int nx = 0, ny = 0;
    std::vector<double> values;
    std::vector<double> errors;  // standard error of each value

    double at(int i, int j) const { return values[size_t(j) * size_t(nx) + size_t(i)]; }
    Vec3 cellCenter(int i, int j) const {
        return {origin.x + (i + 0.5) * cellSize, origin.y + (j + 0.5) * cellSize, height};
    }
};

// Measures the grid at `height` metres above the room's floor (room.lo.z + height) with
// `paths` illuminance samples per cell, each seeded from (seed, tag, cell, path): results
// do not depend on the thread count. The nx = ceil(width / cellSize) by ny columns
// and rows of square cells are centred on the room, so the edge cells overhang the walls by
// less than half a cell and every cell centre is inside. A centre inside furniture reads
// whatever the tracer finds there (usually about 0).
IlluminanceGrid measureWorkPlane(const PathTracer& tracer, const Bounds3& room, double height = 0.8,
                                 double cellSize = 0.25, int paths = 64, uint64_t seed = 1);

// Which cells of `grid` are free floor: 1 unless the cell's centre is inside a part of
// furniture (where the layout puts it) or inside fixed geometry. Those cells read
// about 0 lx and are no part of a work plane, so the plan hatches them and leaves them
// out of its statistics and contours.
std::vector<char> freeCells(const Scene& scene, const Layout& layout, const IlluminanceGrid& grid);

// Em, Emin, Emax and U0 over the free cells (all cells when `free` is empty).
PointStatistics workPlaneStatistics(const IlluminanceGrid& grid, const std::vector<char>& free = {});

// The plan's colour scale: targetFalseColor over the targets of the scene's
// illuminance samplers that have point statistics (planar and volume: the lowest
// minimum to the highest maximum), else a logarithmic autoFalseColor of `values`.
FalseColor planFalseColor(const Scene& scene, const std::vector<double>& values);

struct PlanOptions {
    double pixelsPerMetre = 80;
    int margin = 50;            // pixels around the room
    std::string title;          // drawn at the top when not empty
    bool entityLabels = true;
    bool samplerLabels = true;
    bool contours = true;       // isolux lines at the legend's ticks
    double labelHeight = 14;    // px: the labels' line height (label_font.h)
    std::optional<FalseColor> colors;  // default: planFalseColor of the work plane
};

// Coloured quadrilaterals on the floor in place of the work-plane map, with their own
// legend (e.g. the annual plan's share of hours in range at each sampler point).
struct PlanCells {
    std::vector<std::array<Vec3, 4>> quads;  // world corners, in order around the quad
    std::vector<double> values;              // one per quad; NaN: hatched (no value, e.g. covered)
    FalseColor colors;
    std::string unit;                        // above the legend
};

// What was measured for the layout (all optional).
struct PlanData {
    std::optional<std::vector<SamplerResult>> samplers;  // measureSamplers(...).samplers
    std::optional<IlluminanceGrid> workPlane;
    std::optional<PlanCells> cells;  // drawn over the work plane, if both are given
};

// The plan at PlanOptions::pixelsPerMetre, +y up, with a scale bar, a north arrow
// (Site::northDeg) and, when a work-plane grid is given, its isolux contours, its
// legend and its Em, Emin, Emax and U0 on the right (PlanData::cells: the cells
// instead, with their legend). Samplers are green when they meet
// their targets, red otherwise, grey when no results are given; with results, a table
// under the plan gives each work plane's (planar sampler's) Em, Emin, Emax and U0.
// A label drawn on the plan: its text and its box (pixels, the background's edges).
struct PlanLabel {
    std::string text;
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

// The labels (samplers with their values, entities, fixed objects, isolux values) are
// drawn in DejaVu Sans at PlanOptions::labelHeight (label_font.h) and never over one
// another: each takes the free spot nearest where it belongs, or is left out (a
// sampler's label may go further, with a leader line back). `labels`, if given,
// receives the boxes of those drawn.
Image renderPlan(const Scene& scene, const Layout& layout, const PlanOptions& options = {},
                 const PlanData& data = {}, std::vector<PlanLabel>* labels = nullptr);

}  // namespace luxplan
