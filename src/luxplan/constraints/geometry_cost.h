// The geometric term G(x) of Eq. 1: every relational constraint of the scene and
// the overlap rule between entities, as one weighted, normalized sum of Eq. 2
// penalties, plus the rejection test (any geometric P > 1) that gates the expensive
// lighting term. The hard limits (overlap with walls, static geometry and blockers
// beyond Scene::overlap.wallTolerance; footprints beyond their bounds, footprint.h)
// only reject: like the paper's placement constraints, they are no part of G.
#pragma once

#include <string>
#include <vector>

#include <luxplan/constraints/entity_info.h>
#include <luxplan/constraints/footprint.h>
#include <luxplan/constraints/overlap.h>
#include <luxplan/constraints/terms.h>

namespace luxplan {

struct GeometryResult {
    // G = (sum_c w_c P_c + w_o sum_pairs P_pair) / (sum_c w_c + w_o): every relational
    // constraint c counts once with its weight, and the overlap rule counts once with
    // weight w_o (Scene::overlap.weight, default 1) and penalty equal to
    // the sum of Eq. 6 over all candidate pairs of entities. 0 when every weight is 0.
    // Cohesion constraints (flattenScene()) add to the sum but not to the normalizer.
    double cost = 0;
    bool rejected = false;       // some geometric penalty is above 1, or a hard limit is passed
    std::string rejectedBy;      // the first rejecting term, described
    // Sum of max(0, P - 1) over the rejecting penalties; a hard overlap adds
    // ((V - limit) / kHardOverlapScale)^2, a footprint (excess / kFootprintScale)^2.
    double violation = 0;
    double overlapPenalty = 0;   // sum over the pairs of entities of Eq. 6
    // Filled when asked for: every relational constraint (scene order), then the
    // overlap rule's pairs with a non-zero shared volume (hard ones with penalty 0
    // within their limit, 1 + the violation beyond), then every footprint beyond its bound.
    std::vector<PenaltyTerm> terms;
    std::vector<FootprintTerm> footprints;
};

// The volume (m^3) over which a hard overlap's violation grows by 1 beyond its limit.
inline constexpr double kHardOverlapScale = 0.001;

class GeometryEvaluator {
public:
    explicit GeometryEvaluator(const Scene& scene);

    // G(x) for the world transforms of a layout (worldTransforms()). The overlap
    // cache follows the transforms it is given: only entities whose world transform
    // changed since the previous call are recomputed.
    GeometryResult evaluate(const std::vector<Transform>& world, bool breakdown = false);
    // Keeps the last evaluated state as the one revert() returns to.
    void commit() { overlap_.commit(); }
    // Returns the overlap cache to the last committed state (after a rejected proposal).
    void revert() { overlap_.revert(); }

    const EntityInfo& info() const { return info_; }
    const OverlapEvaluator& overlap() const { return overlap_; }
    const FootprintEvaluator& footprint() const { return footprint_; }

private:
    const Scene* scene_;
    EntityInfo info_;
    OverlapEvaluator overlap_;
    FootprintEvaluator footprint_;
};

}  // namespace luxplan
