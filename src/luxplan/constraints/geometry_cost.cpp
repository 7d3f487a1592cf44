// G(x): relational constraints plus overlap, normalized, with the rejection test.
#include <luxplan/constraints/geometry_cost.h>

#include <luxplan/constraints/penalty.h>
#include <luxplan/constraints/relational.h>

namespace luxplan {

GeometryEvaluator::GeometryEvaluator(const Scene& scene)
    : scene_(&scene), info_(scene), overlap_(scene, info_), footprint_(scene, info_) {}

GeometryResult GeometryEvaluator::evaluate(const std::vector<Transform>& world, bool breakdown) {
    GeometryResult r;
    double sum = 0, weights = 0;
    auto reject = [&](const PenaltyTerm& t) {
        if (!r.rejected) r.rejectedBy = describe(*scene_, t);
        r.rejected = true;
    };
    for (size_t i = 0; i < scene_->constraints.size(); ++i) {
        const ConstraintSpec& c = scene_->constraints[i];
        if (c.a < 0 || (c.b < 0 && c.b != kRoomEntity)) continue;
        PenaltyTerm t = evaluateRelational(*scene_, info_, world, int(i));
        sum += t.weight * t.penalty;
        if (c.kind->countsInNormalizer()) weights += t.weight;
        if (t.parts.empty())
            r.violation += std::max(0.0, t.penalty - 1.0);
        else
            for (double p : t.parts) r.violation += std::max(0.0, p - 1.0);
        if (t.rejects) reject(t);
        if (breakdown) r.terms.push_back(t);
    }

    overlap_.update(world);
    for (const auto& pair : overlap_.pairs()) {
        if (pair.volume <= 0) continue;
        PenaltyTerm t;
        t.a = pair.a, t.b = pair.b, t.target = pair.target, t.walls = pair.walls;
        t.value = pair.volume;
        t.reference = pair.reference;
        t.weight = scene_->overlap.weight;
        if (pair.hard()) {
            // A hard limit: nothing within it, rejected beyond (a volume a hair over it
            // too, so the test is on the volume, not on P).
            t.rejects = pair.volume > pair.reference;
            double excess = (pair.volume - pair.reference) / kHardOverlapScale;
            t.penalty = t.rejects ? 1 + excess * excess : 0.0;
        } else {
            // Eq. 6: P(V_s n V_t, 0, 0, V_ref, 2)
            t.penalty = penalty(pair.volume, 0.0, 0.0, pair.reference, kGeometricStiffness);
            t.rejects = rejects(t.penalty);
            r.overlapPenalty += t.penalty;
        }
        r.violation += std::max(0.0, t.penalty - 1.0);
        if (t.rejects) reject(t);
        if (breakdown) r.terms.push_back(t);
    }
    for (const FootprintTerm& f : footprint_.evaluate(world)) {
        r.violation += f.penalty - 1;
        if (!r.rejected) r.rejectedBy = describe(*scene_, f);
        r.rejected = true;
        if (breakdown) r.footprints.push_back(f);
    }
    sum += scene_->overlap.weight * r.overlapPenalty;
    weights += scene_->overlap.weight;
    r.cost = weights > 0 ? sum / weights : 0.0;
    return r;
}

}  // namespace luxplan
