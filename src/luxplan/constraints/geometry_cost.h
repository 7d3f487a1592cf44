// The geometric term G(x) of Eq. 1: every relational constraint of the scene and
// the overlap rule, as one weighted, normalized sum of Eq. 2 penalties, plus the
// rejection test (any geometric P > 1) that gates the expensive lighting term.
#pragma once

#include <string>
#include <vector>

#include <luxplan/constraints/entity_info.h>
#include <luxplan/constraints/overlap.h>
#include <luxplan/constraints/terms.h>

namespace luxplan {

struct GeometryResult {
    // G = (sum_c w_c P_c + w_o sum_pairs P_pair) / (sum_c w_c + w_o): every relational
    // constraint c counts once with its weight, and the overlap rule counts once with
    // weight w_o (Scene::overlap.weight, default 1) and penalty equal to
    // the sum of Eq. 6 over all candidate pairs. 0 when every weight is 0. Cohesion
    // constraints (flattenScene()) add to the sum but not to the normalizer.
    double cost = 0;
    bool rejected = false;       // some geometric penalty is above 1
    std::string rejectedBy;      // the first rejecting term, described
    double violation = 0;        // sum of max(0, P - 1) over the rejecting penalties
    double overlapPenalty = 0;   // sum over the pairs of Eq. 6
    // Filled when asked for: every relational constraint (scene order), then the
    // overlap rule's pairs with a non-zero shared volume.
    std::vector<PenaltyTerm> terms;
};

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

private:
    const Scene* scene_;
    EntityInfo info_;
    OverlapEvaluator overlap_;
};

}  // namespace luxplan
