#include <luxplan/optimizer/light_map.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <luxplan/constraints/penalty.h>
#include <luxplan/optimizer/interchangeable.h>
#include <luxplan/optimizer/placement.h>

namespace luxplan {
namespace {

bool placeable(const Entity& e) {
    for (const Region& r : e.regions) {
        if (r.hi.x > r.lo.x || r.hi.y > r.lo.y) return true;
        if (r.continuousRotation ? r.rotationMaxDeg > r.rotationMinDeg : distinctRotations(r).size() > 1) return true;
    }
    return e.regions.size() > 1;
}

int binsAlong(double extent, double cell) { return extent > 0 ? std::max(1, int(std::ceil(extent / cell - 1e-9))) : 1; }

}  // namespace

LightMap::LightMap(const Scene& scene, const std::vector<int>& entities, LightMapOptions options)
    : scene_(&scene), options_(options), poolOf_(scene.entities.size(), -1), samplersOf_(scene.entities.size()) {
    if (!(options_.cellMetres > 0) || options_.rotationBins < 1 || !(options_.temperature > 0) ||
        !(options_.uniformShare > 0 && options_.uniformShare <= 1) || options_.memory < 1)
        throw std::invalid_argument("LightMap: options out of range");
    for (size_t k = 0; k < scene.samplers.size(); ++k)
        for (int e = scene.samplers[k].entity; e >= 0; e = scene.entities[size_t(e)].parent) samplersOf_[size_t(e)].push_back(int(k));
    for (int e : entities) {
        const Entity& entity = scene.entities.at(size_t(e));
        if (entity.parent >= 0 || !entity.movable() || samplersOf_[size_t(e)].empty() || !placeable(entity)) continue;
        // The pool of an entity the scene cannot tell from this one, else a new one.
        for (int m : mapped_)
            if (interchangeable(scene, e, m)) poolOf_[size_t(e)] = poolOf_[size_t(m)];
        mapped_.push_back(e);
        if (poolOf_[size_t(e)] >= 0) continue;
        Pool pool;
        size_t cells = 0;
        for (size_t i = 0; i < entity.regions.size(); ++i) {
            const Region& r = entity.regions[i];
            Grid g;
            g.region = int(i);
            g.nx = binsAlong(r.hi.x - r.lo.x, options_.cellMetres);
            g.ny = binsAlong(r.hi.y - r.lo.y, options_.cellMetres);
            g.nr = r.continuousRotation ? (r.rotationMaxDeg > r.rotationMinDeg ? options_.rotationBins : 1)
                                        : std::max<int>(1, int(distinctRotations(r).size()));
            g.cellMeasure = regionMeasure(r) / (double(g.nx) * g.ny * g.nr);
            g.first = cells;
            cells += size_t(g.nx) * size_t(g.ny) * size_t(g.nr);
            pool.totalMeasure += regionMeasure(r);
            pool.grids.push_back(g);
        }
        pool.penalty.assign(cells, std::numeric_limits<double>::quiet_NaN());
        pool.seen.assign(cells, 0);
        poolOf_[size_t(e)] = int(pools_.size());
        pools_.push_back(std::move(pool));
    }
}

void LightMap::clear() {
    observations_ = 0;
    for (Pool& pool : pools_) {
        std::fill(pool.penalty.begin(), pool.penalty.end(), std::numeric_limits<double>::quiet_NaN());
        std::fill(pool.seen.begin(), pool.seen.end(), 0);
    }
}

size_t LightMap::cellOf(const Pool& pool, const Entity& entity, const Placement& p) const {
    const Grid& g = pool.grids.at(size_t(p.region));
    const Region& r = entity.regions[size_t(p.region)];
    auto bin = [](double v, double lo, double hi, int n) {
        if (n <= 1 || !(hi > lo)) return 0;
        return std::clamp(int(std::floor((v - lo) / (hi - lo) * n)), 0, n - 1);
    };
    const int ix = bin(p.position.x, r.lo.x, r.hi.x, g.nx), iy = bin(p.position.y, r.lo.y, r.hi.y, g.ny);
    int ir = 0;
    if (r.continuousRotation) {
        const double span = std::min(r.rotationMaxDeg - r.rotationMinDeg, 360.0);
        ir = bin(normalizeRotation(r, p.rotationDeg), r.rotationMinDeg, r.rotationMinDeg + span, g.nr);
    } else {
        const std::vector<double> rotations = distinctRotations(r);
        for (size_t k = 0; k < rotations.size(); ++k)
            if (sameRotation(rotations[k], p.rotationDeg)) ir = int(k);
    }
    return g.first + (size_t(ir) * size_t(g.ny) + size_t(iy)) * size_t(g.nx) + size_t(ix);
}

std::vector<double> LightMap::weights(const Pool& pool) const {
    // A cell never seen weighs as much as the best: the map explores what it does not know.
    std::vector<double> w(pool.penalty.size());
    for (size_t c = 0; c < w.size(); ++c)
        w[c] = std::isnan(pool.penalty[c]) ? 1.0 : std::exp(-pool.penalty[c] / options_.temperature);
    return w;
}

void LightMap::observe(const Layout& layout, const std::vector<SamplerResult>& samplers) {
    if (samplers.size() != scene_->samplers.size()) return;
    if (options_.freezeAfter > 0 && observations_ >= options_.freezeAfter) return;
    ++observations_;
    for (int e : mapped_) {
        const Placement& p = layout.placements[size_t(e)];
        if (p.region < 0) continue;
        double penalty = 0;
        for (int k : samplersOf_[size_t(e)])
            penalty += scene_->samplers[size_t(k)].weight * lightingPenalty(scene_->samplers[size_t(k)], samplers[size_t(k)].value);
        Pool& pool = pools_[size_t(poolOf_[size_t(e)])];
        const size_t c = cellOf(pool, scene_->entities[size_t(e)], p);
        // The mean of the last ~memory observations: the cell's light changes as the
        // rest of the layout does.
        int& n = pool.seen[c];
        n = std::min(n + 1, options_.memory);
        double& v = pool.penalty[c];
        v = std::isnan(v) ? penalty : v + (penalty - v) / double(n);
    }
}

double LightMap::logDensity(int entity, const Placement& p) const {
    const Pool& pool = pools_.at(size_t(poolOf_.at(size_t(entity))));
    const std::vector<double> w = weights(pool);
    double total = 0;
    for (double x : w) total += x;
    const size_t c = cellOf(pool, scene_->entities[size_t(entity)], p);
    const Grid& g = pool.grids[size_t(p.region)];
    const double u = options_.uniformShare;
    return std::log(u / pool.totalMeasure + (1 - u) * w[c] / (total * g.cellMeasure));
}

double LightMap::penaltyAt(int entity, const Placement& p) const {
    const Pool& pool = pools_.at(size_t(poolOf_.at(size_t(entity))));
    return pool.penalty[cellOf(pool, scene_->entities[size_t(entity)], p)];
}

double LightMap::propose(int entity, Placement& p, Rng& rng) const {
    if (!covers(entity)) throw std::invalid_argument("LightMap::propose: entity not mapped");
    const Entity& e = scene_->entities[size_t(entity)];
    const Pool& pool = pools_[size_t(poolOf_[size_t(entity)])];
    const double before = logDensity(entity, p);
    const double z = p.position.z;
    if (rng.uniform() < options_.uniformShare) {
        p = samplePlacement(e, z, rng);
    } else {
        const std::vector<double> w = weights(pool);
        double total = 0;
        for (double x : w) total += x;
        double u = rng.uniform() * total;
        size_t c = w.size() - 1;
        for (size_t i = 0; i < w.size(); ++i) {
            u -= w[i];
            if (u < 0) {
                c = i;
                break;
            }
        }
        // The cell's region, then uniform inside the cell.
        size_t gi = 0;
        while (gi + 1 < pool.grids.size() && pool.grids[gi + 1].first <= c) ++gi;
        const Grid& g = pool.grids[gi];
        const Region& r = e.regions[size_t(g.region)];
        const size_t local = c - g.first;
        const int ix = int(local % size_t(g.nx)), iy = int(local / size_t(g.nx) % size_t(g.ny)),
                  ir = int(local / (size_t(g.nx) * size_t(g.ny)));
        const double ex = r.hi.x - r.lo.x, ey = r.hi.y - r.lo.y;
        p.region = g.region;
        p.position.x = ex > 0 ? r.lo.x + (ix + rng.uniform()) * ex / g.nx : r.lo.x;
        p.position.y = ey > 0 ? r.lo.y + (iy + rng.uniform()) * ey / g.ny : r.lo.y;
        // Inside the box's closed interval, as a proposal must be (float rounding).
        p.position.x = std::clamp(p.position.x, r.lo.x, r.hi.x), p.position.y = std::clamp(p.position.y, r.lo.y, r.hi.y);
        p.position.z = z;
        if (r.continuousRotation) {
            const double span = std::min(r.rotationMaxDeg - r.rotationMinDeg, 360.0);
            p.rotationDeg = r.rotationMinDeg + (ir + rng.uniform()) * span / g.nr;
            p.rotationDeg = std::clamp(p.rotationDeg, r.rotationMinDeg, r.rotationMinDeg + span);
        } else {
            const std::vector<double> rotations = distinctRotations(r);
            p.rotationDeg = rotations.empty() ? e.rotationDeg : rotations[size_t(ir)];
        }
    }
    return before - logDensity(entity, p);
}

}  // namespace luxplan
