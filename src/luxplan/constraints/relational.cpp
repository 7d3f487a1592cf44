// Alignment, distance, focus and conversation penalties (paper Eqs. 4, 5, 7, 8).
#include <luxplan/constraints/relational.h>

#include <cmath>
#include <stdexcept>

#include <luxplan/constraints/penalty.h>

namespace luxplan {

static double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }

std::vector<Vec2> worldFronts(const Scene& scene, const std::vector<Transform>& world, int e) {
    std::vector<Vec2> fronts;
    for (Vec2 f : scene.entities[e].fronts) {
        Vec3 w = world[e].applyVector({f.x, f.y, 0});
        Vec2 xy(w.x, w.y);
        double len = length(xy);
        if (len > 0) fronts.push_back(xy * (1.0 / len));
    }
    return fronts;
}

double alignmentAngle(const Scene& scene, const std::vector<Transform>& world, int a, int b) {
    std::vector<Vec2> fa = worldFronts(scene, world, a);
    std::vector<Vec2> fb = b == kRoomEntity ? std::vector<Vec2>{Vec2(1, 0), Vec2(0, 1)} : worldFronts(scene, world, b);
    double best = kPi / 2;
    for (Vec2 u : fa)
        for (Vec2 v : fb) best = std::min(best, std::atan2(std::abs(cross(u, v)), std::abs(dot(u, v))));
    return best;
}

double focusAngle(const Scene& scene, const EntityInfo& info, const std::vector<Transform>& world, int s, int t) {
    Vec3 d3 = entityCenter(info, world, t) - entityCenter(info, world, s);
    Vec2 d(d3.x, d3.y);
    if (length(d) < 1e-9) return kPi / 2;
    double best = kPi;
    for (Vec2 u : worldFronts(scene, world, s)) best = std::min(best, std::atan2(std::abs(cross(u, d)), dot(u, d)));
    return best;
}

double centerDistance(const EntityInfo& info, const std::vector<Transform>& world, int s, int t) {
    return length(entityCenter(info, world, s) - entityCenter(info, world, t));
}

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
    auto distancePenalty = [&](double d) {
        return penalty(d, c.minDistance, c.maxDistance, distanceElasticLimit(c), kGeometricStiffness);
    };
    switch (c.type) {
        case ConstraintType::Alignment:  // Eq. 4, best pair of fronts
            t.kind = TermKind::Alignment;
            t.value = alignmentAngle(scene, world, c.a, c.b);
            t.reference = radians(c.toleranceDeg);
            t.penalty = anglePenalty(t.value, c.toleranceDeg);
            t.rejects = rejects(t.penalty);
            break;
        case ConstraintType::Distance:  // Eq. 5
            t.kind = TermKind::Distance;
            t.value = centerDistance(info, world, c.a, c.b);
            t.reference = c.maxDistance;
            t.penalty = distancePenalty(t.value);
            t.rejects = rejects(t.penalty);
            break;
        case ConstraintType::Focus:  // Eq. 7: G_A between a's front and the direction to b
            t.kind = TermKind::Focus;
            t.value = focusAngle(scene, info, world, c.a, c.b);
            t.reference = radians(c.toleranceDeg);
            t.penalty = anglePenalty(t.value, c.toleranceDeg);
            t.rejects = rejects(t.penalty);
            break;
        case ConstraintType::Conversation: {  // Eq. 8: mutual focus and a distance limiter
            t.kind = TermKind::Conversation;
            t.value = centerDistance(info, world, c.a, c.b);
            t.reference = c.maxDistance;
            t.parts = {anglePenalty(focusAngle(scene, info, world, c.a, c.b), c.toleranceDeg),
                       anglePenalty(focusAngle(scene, info, world, c.b, c.a), c.toleranceDeg), distancePenalty(t.value)};
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
