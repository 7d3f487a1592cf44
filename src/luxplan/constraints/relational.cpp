// What the relational constraint types share: ends, angles, Eqs. 4 and 5 as
// penalties, and the evaluation of a scene's constraint through its kind.
#include <luxplan/constraints/relational.h>

#include <cmath>

#include <nlohmann/json.hpp>

#include <luxplan/constraints/penalty.h>
#include <luxplan/core/format.h>
#include <luxplan/json/fields.h>

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

double facingAngle(const ConstraintEnd& from, const ConstraintEnd& to) {
    return facingAngle(from.fronts, from.center, to.center);
}

std::vector<Vec2> worldFronts(const Scene& scene, const std::vector<Transform>& world, int e) {
    return frontsIn(scene.entities[e].fronts, world[e]);
}

double anglePenalty(double angleRad, double toleranceDeg) {
    double theta = radians(toleranceDeg);
    return penalty(angleRad, 0.0, theta, theta * kAlignmentRejectFraction, kGeometricStiffness);
}

double distanceElasticLimit(const DistanceRange& range) {
    if (range.tolerance) return *range.tolerance;
    double width = range.max - range.min;
    if (std::isfinite(width) && width > 0) return kDistanceRejectFraction * width;
    double bound = std::isfinite(range.max) && range.max > 0 ? range.max : range.min;
    if (std::isfinite(bound) && bound > 0) return kDistanceRejectFraction * bound;
    return kMinDistanceElasticLimit;
}

double distancePenalty(double distance, const DistanceRange& range) {
    return penalty(distance, range.min, range.max, distanceElasticLimit(range), kGeometricStiffness);
}

double readToleranceDeg(const json::Fields& f) {
    return f.number("tolerance_deg", 10.0, json::Range::closed(limits::kMinToleranceDeg, 180, "deg"));
}

DistanceRange readDistanceRange(const json::Fields& f) {
    auto lo = f.number("min", json::distanceBoundRange(), true);
    // "max": null leaves the range open above.
    bool open = f.has("max") && f.get("max").is_null();
    auto hi = open ? std::optional<double>(kInf) : f.number("max", json::distanceBoundRange(), true);
    if (lo && hi && *hi < *lo)
        f.error("max", "distance range is reversed: max " + json::formatNumber(*hi) + " < min " + json::formatNumber(*lo) + " m");
    DistanceRange r;
    r.min = lo.value_or(0), r.max = hi.value_or(kInf);
    r.tolerance = f.number("tolerance", json::distanceToleranceRange());
    return r;
}

std::string AngleConstraint::describe() const { return describeTolerance(toleranceDeg_); }

std::string AngleConstraint::describe(const PenaltyTerm& t) const {
    return describeNumber(degrees(t.value)) + " deg, tolerance " + describeNumber(degrees(t.reference)) + " deg";
}

void AngleConstraint::report(const PenaltyTerm& t, nlohmann::ordered_json& j) const {
    j["value"] = json::numberOrNull(degrees(t.value));
    j["unit"] = "deg";
    j["tolerance"] = toleranceDeg_;
}

void AngleConstraint::hold(double angleRad, PenaltyTerm& t) const {
    t.value = angleRad;
    t.reference = radians(toleranceDeg_);
    t.penalty = anglePenalty(t.value, toleranceDeg_);
    t.rejects = rejects(t.penalty);
}

ConstraintEnd entityEnd(const Scene& scene, const EntityInfo& info, const std::vector<Transform>& world, int e) {
    if (e == kRoomEntity) return {Vec3(), {Vec2(1, 0), Vec2(0, 1)}};
    return {entityCenter(info, world, e), worldFronts(scene, world, e)};
}

std::array<ConstraintEnd, 2> ConstraintKind::ends(const Scene& scene, const EntityInfo& info,
                                                  const std::vector<Transform>& world, int a, int b) const {
    return {entityEnd(scene, info, world, a), entityEnd(scene, info, world, b)};
}

PenaltyTerm evaluateRelational(const Scene& scene, const EntityInfo& info, const std::vector<Transform>& world,
                               int constraintIndex) {
    const ConstraintSpec& c = scene.constraints[constraintIndex];
    PenaltyTerm t;
    t.kind = c.kind.get();
    t.constraint = constraintIndex;
    t.a = c.a, t.b = c.b;
    t.weight = c.weight;
    const auto [a, b] = c.kind->ends(scene, info, world, c.a, c.b);
    c.kind->evaluate(a, b, t);
    return t;
}

std::string describeNumber(double v) { return significantDigits(v, 4); }

std::string describeRange(const DistanceRange& range) {
    return "range [" + describeNumber(range.min) + ", " + describeNumber(range.max) + "] m";
}

std::string describeTolerance(double toleranceDeg) { return "tolerance " + describeNumber(toleranceDeg) + " deg"; }

}  // namespace luxplan
