// What the light already told the search: for each top-level movable entity that
// carries light samplers (itself or anything below it), a coarse map of its own
// samplers' penalty over its placement regions, filled from every layout the search
// lit. The guided move (MoveType::Guided) draws a new placement from it: cells where the
// entity's own targets held are drawn more often, cells not yet seen as often as the
// best, and a share of the draws stays uniform, so that every placement can be proposed.
#pragma once

#include <cstdint>
#include <vector>

#include <luxplan/core/rng.h>
#include <luxplan/scene/sampler_result.h>
#include <luxplan/scene/layout.h>

namespace luxplan {

struct LightMapOptions {
    double cellMetres = 0.5;     // the cells' side (a region's extent is split evenly)
    int rotationBins = 8;        // cells per rotation interval (discrete rotations: one each)
    double temperature = 0.1;    // a cell's weight is exp(-penalty / temperature)
    double uniformShare = 0.2;   // of the draws, uniform over the regions (as a jump)
    int memory = 8;              // a cell's value: the mean of its last ~memory observations
    // Observations after which the map stops changing (0: never). A frozen map makes
    // the guided move an exact Metropolis-Hastings proposal from then on (the chain
    // tests); a map that keeps learning is an adaptive chain, which the search is.
    int64_t freezeAfter = 0;
};

class LightMap {
public:
    // Maps the entities of `entities` that have no parent, carry samplers below them and
    // can be placed anywhere else in a region (an extent or two rotations). Entities the
    // scene cannot tell apart (optimizer/interchangeable.h) share one map.
    LightMap(const Scene& scene, const std::vector<int>& entities, LightMapOptions options = {});

    bool covers(int entity) const { return entity >= 0 && size_t(entity) < poolOf_.size() && poolOf_[size_t(entity)] >= 0; }
    bool empty() const { return pools_.empty(); }
    // Forgets every observation (a new run).
    void clear();

    // A lit layout: each mapped entity's own samplers' penalty (weighted as in Eq. 3),
    // noted in the cell where it stands.
    void observe(const Layout& layout, const std::vector<SamplerResult>& samplers);

    // The guided move: a new placement of `entity` drawn from its map (the region by
    // the cells' weights, uniform inside the cell; with `uniformShare`, uniform over the
    // union of its regions). Returns log q(x' -> x) / q(x -> x') = log q(x) - log q(x'):
    // an independence proposal, exact for the map as it stands.
    double propose(int entity, Placement& placement, Rng& rng) const;
    // log of the proposal density at a placement (base measure: regionMeasure()).
    double logDensity(int entity, const Placement& placement) const;
    // The penalty noted at a placement's cell (NaN: never seen).
    double penaltyAt(int entity, const Placement& placement) const;

private:
    struct Grid {  // one region's cells
        int region = 0, nx = 1, ny = 1, nr = 1;
        double cellMeasure = 1;  // every cell's share of the region's measure
        size_t first = 0;        // index of its first cell in the pool's arrays
    };
    struct Pool {
        std::vector<Grid> grids;          // one per region of the entities (they share regions)
        std::vector<double> penalty;      // per cell; NaN: never seen
        std::vector<int> seen;            // per cell: observations, capped at memory
        double totalMeasure = 0;
    };
    size_t cellOf(const Pool& pool, const Entity& entity, const Placement& p) const;
    std::vector<double> weights(const Pool& pool) const;

    const Scene* scene_;
    LightMapOptions options_;
    std::vector<Pool> pools_;
    std::vector<int> poolOf_;                  // per entity: its pool, or -1
    std::vector<std::vector<int>> samplersOf_; // per entity: the samplers it carries, below it included
    std::vector<int> mapped_;                  // the mapped entities
    int64_t observations_ = 0;
};

}  // namespace luxplan
