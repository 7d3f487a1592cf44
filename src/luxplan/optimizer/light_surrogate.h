// A stand-in for the light, for planning where the chain starts (OptimizerOptions::
// plannedStart). Every upward planar sampler that moves with furniture (a desk's task
// grid) reads a field: the horizontal illuminance of the room without its movable
// furniture, measured once on a grid of cells at the sampler's height and interpolated
// at its points. Every other sampler that moves with furniture (a screen's glare eye)
// reads a pose table: its values with the piece that carries it (the topmost movable
// entity above it, the workstation a screen stands on) and no other movable piece, at
// the nodes of a grid of the piece's positions (at most half a metre apart) and at each
// of its headings, traced once (LightingEvaluator::aloneInEmptyRoom); pieces built
// alike share one. Where a piece stands in the room's light decides most of what its
// samplers read; what the other furniture adds (shadows, reflections) enters as one
// scale per sampler from a traced look (correction()). Glare surveys, statistics goals,
// fixed points and annual goals are left to the chain, which traces them: their terms
// count as met here, in L's denominator all the same.
#pragma once

#include <algorithm>
#include <array>
#include <vector>

#include <luxplan/core/math.h>
#include <luxplan/scene/layout.h>
#include <luxplan/scene/scene.h>

namespace luxplan {

class LightSurrogate {
public:
    // `cellMetres`: the fields' cells (the room's box split evenly, centred as the plan's
    // work plane is). A scene without a room shell or without such samplers is empty().
    LightSurrogate(const Scene& scene, double cellMetres = 0.25);

    bool empty() const { return fields_.empty() && tables_.empty(); }
    // Where the illuminance is wanted, facing up: every field's cell centres, in order.
    std::vector<Vec3> points() const;
    // Their measured illuminance (lx), in points()'s order.
    void setIlluminance(const std::vector<double>& values);
    bool ready() const { return ready_; }
    // The samplers its fields stand in for (Scene::samplers indices).
    const std::vector<int>& samplers() const { return standIns_; }

    // The pose tables: each one's entity, the placements where it is traced (heading by
    // heading, the grid row by row, x fastest) and its samplers (Scene::samplers indices).
    struct PoseQuery {
        int entity = -1;
        std::vector<Placement> placements;
        std::vector<int> samplers;
    };
    // One query per table that must be traced (a table shared with an earlier one is not
    // asked again).
    std::vector<PoseQuery> poseQueries() const;
    // Their values, in poseQueries()'s order: per query, per placement, per sampler.
    // Not called (or called with an empty list): the tables' samplers count as met.
    void setPoseValues(const std::vector<std::vector<std::vector<double>>>& values);
    bool hasPoseTables() const { return !tables_.empty(); }
    // The movable entities between a table's samplers and its entity (a monitor on its
    // workstation): the tables hold them at the scene's placement, and so must a plan.
    const std::vector<int>& heldAtScenePlacement() const { return held_; }

    // One scale per sampler (Scene::samplers order) on what the surrogate reads: what the
    // furniture adds or takes (a desk's own shadows), as far as one traced layout can tell
    // it. Empty: every scale 1. A value, so that plans corrected apart can run at once.
    using Correction = std::vector<double>;
    // What light traced at `layout` (`traced`, one result per Scene::samplers entry) read
    // over what the uncorrected surrogate reads there, each stood-in sampler's, at most a
    // factor kMaxCorrection either way (1 for the others).
    Correction correction(const Layout& layout, const std::vector<Transform>& world,
                          const std::vector<SamplerResult>& traced) const;

    // Eq. 3's L for `layout`, whose world transforms are `world`: the stood-in samplers
    // read from the fields and the tables, scaled by `correction`, their bands narrowed by
    // a tenth of their width at each bound above 0 (what the surrogate cannot see), every
    // other term at penalty 0.
    double lighting(const Layout& layout, const std::vector<Transform>& world, const Correction& correction = {}) const;
    // A stood-in sampler's value (its points' mean, or its table's value) there.
    double value(int sampler, const Layout& layout, const std::vector<Transform>& world,
                 const Correction& correction = {}) const;

private:
    struct Field {
        double height = 0;  // world z of the cell centres
        Vec2 origin;        // the corner of cell (0, 0)
        int nx = 1, ny = 1;
        std::vector<double> lux;  // row-major, x fastest
        double at(Vec2 p, double cell) const;  // bilinear between cell centres, clamped at the edges
    };
    // A table's grid of positions (nodes from lo, `step` apart, clamped at the ends),
    // its headings, and its values: [heading][row][column][sampler].
    struct PoseTable {
        int entity = -1;
        std::vector<int> samplers;
        Vec2 lo, step;
        int nx = 1, ny = 1;
        std::vector<double> headingsDeg;
        std::vector<double> values;
        int sharesWith = -1;  // an earlier table built alike, whose values it takes
        bool traced = false;
        std::vector<Placement> placements(const Scene& scene) const;
        double at(int samplerSlot, const Placement& p) const;
    };
    void addPoseTables();
    std::vector<double> pointValues(int sampler, const std::vector<Transform>& world, double scale) const;
    double tableValue(int sampler, const Layout& layout, double scale) const;

    const Scene* scene_;
    double cell_;
    std::vector<Field> fields_;
    std::vector<int> fieldOf_;    // per sampler: its field, -1 when not stood in for
    std::vector<PoseTable> tables_;
    std::vector<int> held_;
    std::vector<std::array<int, 2>> tableOf_;  // per sampler: its table and slot there, or -1
    std::vector<int> standIns_;
    double termWeights_ = 0;      // L's denominator: every term's weight, every sampler's
    bool ready_ = false;
};

}  // namespace luxplan
