// Alignment, distance, focus and conversation penalties (paper Eqs. 4, 5, 7, 8).
#include <luxplan/constraints/relational.h>

#include <cmath>
#include <stdexcept>

#include <luxplan/constraints/penalty.h>

namespace luxplan {

static double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }

std::vector<Vec2> frontsIn(const std::vector<Vec2>& fronts, const Transform& frame) {
    std::vector<Vec2> out;
    for (Vec2 f : fronts) {
        Vec3 w = frame.applyVector({f.x, f.y, 0});
        Vec2 xy(w.x, w.y);
        double len = length(xy);
        if (len > 0) out.push_back(xy * (1.0 / len));
    }
    return out;
}

double axialAngle(const std::vector<Vec2>& fa, const std::vector<Vec2>& fb) {
    double best = kPi / 2;
    for (Vec2 u : fa)
        for (Vec2 v : fb) best = std::min(best, std::atan2(std::abs(cross(u, v)), std::abs(dot(u, v))));
    return best;
}

double facingAngle(const std::vector<Vec2>& fronts, const Vec3& from, const Vec3& to) {
    Vec2 d(to.x - from.x, to.y - from.y);
    if (length(d) < 1e-9) return kPi / 2;
    double best = kPi;
    for (Vec2 u : fronts) best = std::min(best, std::atan2(std::abs(cross(u, d)), dot(u, d)));
    return best;
}

std::vector<Vec2> worldFronts(const Scene& scene, const std::vector<Transform>& world, int e) {
    return frontsIn(scene.entities[e].fronts, world[e]);
}

namespace {

// Where a constraint end is and which way it faces: the entity's centre and fronts,
// or, for an end that stands for a former group, the group's.
struct End {
    Vec3 center;
    std::vector<Vec2> fronts;
};

End resolveEnd(const Scene& scene, const EntityInfo& info, const std::vector<Transform>& world, int e,
               const std::optional<GroupEnd>& group) {
    if (!group) return {entityCenter(info, world, e), worldFronts(scene, world, e)};
    const Transform worldFromGroup = world[e] * group->entityFromGroup;
    const Transform groupFromWorld = worldFromGroup.inverse();
    Bounds3 box;
    for (int m : group->members) box.extend((groupFromWorld * world[m]).apply(info.localBounds(m)));
    return {group->members.empty() ? worldFromGroup.t : worldFromGroup.applyPoint(box.center()),
            frontsIn(group->fronts, worldFromGroup)};
}

double facingAngle(const End& s, const End& t) { return facingAngle(s.fronts, s.center, t.center); }

}  // namespace

double anglePenalty(double angleRad, double toleranceDeg) {
    double theta = radians(toleranceDeg);
    return penalty(angleRad, 0.0, theta, theta * kAlignmentRejectFraction, kGeometricStiffness);
}

double distanceElasticLimit(const ConstraintSpec& spec) {
    if (spec.distanceTolerance) return *spec.distanceTolerance;
    double width = spec.maxDistance - spec.minDistance;
    if (std::isfinite(width) && width > 0) return kDistanceRejectFraction * width;
    double bound = std::isfinite(spec.maxDistance) && spec.maxDistance > 0 ? spec.maxDistance : spec.minDistance;
    if (std::isfinite(bound) && bound > 0) return kDistanceRejectFraction * bound;
    return kMinDistanceElasticLimit;
}

PenaltyTerm evaluateRelational(const Scene& scene, const EntityInfo& info, const std::vector<Transform>& world,
                               int constraintIndex) {
    const ConstraintSpec& c = scene.constraints[constraintIndex];
    PenaltyTerm t;
    t.constraint = constraintIndex;
    t.a = c.a, t.b = c.b;
    t.weight = c.weight;
    const End a = resolveEnd(scene, info, world, c.a, c.groupA);
    const End b = c.b == kRoomEntity ? End{Vec3(), {Vec2(1, 0), Vec2(0, 1)}} : resolveEnd(scene, info, world, c.b, c.groupB);
    auto distancePenalty = [&](double d) {
        return penalty(d, c.minDistance, c.maxDistance, distanceElasticLimit(c), kGeometricStiffness);
    };
    switch (c.type) {
        case ConstraintType::Alignment:  // Eq. 4, best pair of fronts
            t.kind = TermKind::Alignment;
            t.value = axialAngle(a.fronts, b.fronts);
            t.reference = radians(c.toleranceDeg);
            t.penalty = anglePenalty(t.value, c.toleranceDeg);
            t.rejects = rejects(t.penalty);
            break;
        case ConstraintType::Distance:  // Eq. 5
            t.kind = TermKind::Distance;
            t.value = length(a.center - b.center);
            t.reference = c.maxDistance;
            t.penalty = distancePenalty(t.value);
            t.rejects = rejects(t.penalty);
            break;
        case ConstraintType::Focus:  // Eq. 7: G_A between a's front and the direction to b
            t.kind = TermKind::Focus;
            t.value = facingAngle(a, b);
            t.reference = radians(c.toleranceDeg);
            t.penalty = anglePenalty(t.value, c.toleranceDeg);
            t.rejects = rejects(t.penalty);
            break;
        case ConstraintType::Conversation: {  // Eq. 8: mutual focus and a distance limiter
            t.kind = TermKind::Conversation;
            t.value = length(a.center - b.center);
            t.reference = c.maxDistance;
            t.parts = {anglePenalty(facingAngle(a, b), c.toleranceDeg), anglePenalty(facingAngle(b, a), c.toleranceDeg),
                       distancePenalty(t.value)};
            t.penalty = (t.parts[0] + t.parts[1] + t.parts[2]) / 3.0;
            t.rejects = rejects(t.parts[0]) || rejects(t.parts[1]) || rejects(t.parts[2]);
            break;
        }
        case ConstraintType::Overlap:
            throw std::invalid_argument("evaluateRelational: overlap is not a relational constraint");
    }
    return t;
}

}  // namespace luxplan
