// A stand-in for the light, for planning where the chain starts (OptimizerOptions::
// plannedStart): every upward planar sampler that moves with furniture (a desk's task
// grid) reads the horizontal illuminance of the room without its movable furniture,
// measured once on a grid of cells at the sampler's height and interpolated at its
// points. Where a desk stands in the room's light decides most of its illuminance; what
// the furniture adds (its shadows, its reflections) and the samplers it cannot stand in
// for (screens' glare, walls, annual goals, fixed points) are left to the chain, which
// traces them. Their terms count as met here, in L's denominator all the same.
#pragma once

#include <vector>

#include <luxplan/core/math.h>
#include <luxplan/scene/layout.h>
#include <luxplan/scene/scene.h>

namespace luxplan {

class LightSurrogate {
public:
    // `cellMetres`: the grid's cells (the room's box split evenly, centred as the plan's
    // work plane is). A scene without a room shell or without such samplers is empty().
    LightSurrogate(const Scene& scene, double cellMetres = 0.25);

    bool empty() const { return fields_.empty(); }
    // Where the illuminance is wanted, facing up: every field's cell centres, in order.
    std::vector<Vec3> points() const;
    // Their measured illuminance (lx), in points()'s order.
    void setIlluminance(const std::vector<double>& values);
    bool ready() const { return ready_; }
    // The samplers it stands in for (Scene::samplers indices).
    const std::vector<int>& samplers() const { return standIns_; }

    // Eq. 3's L for the layout whose world transforms are `world`, the stood-in
    // samplers read from the fields, their bands narrowed by a tenth of their width at
    // each finite end (what the surrogate cannot see), every other term at penalty 0.
    double lighting(const std::vector<Transform>& world) const;
    // A stood-in sampler's value (its points' mean) there.
    double value(int sampler, const std::vector<Transform>& world) const;

private:
    struct Field {
        double height = 0;  // world z of the cell centres
        Vec2 origin;        // the corner of cell (0, 0)
        int nx = 1, ny = 1;
        std::vector<double> lux;  // row-major, x fastest
        double at(Vec2 p, double cell) const;  // bilinear between cell centres, clamped at the edges
    };
    std::vector<double> pointValues(int sampler, const std::vector<Transform>& world) const;

    const Scene* scene_;
    double cell_;
    std::vector<Field> fields_;
    std::vector<int> fieldOf_;    // per sampler: its field, -1 when not stood in for
    std::vector<int> standIns_;
    double termWeights_ = 0;      // L's denominator: every term's weight, every sampler's
    bool ready_ = false;
};

}  // namespace luxplan
