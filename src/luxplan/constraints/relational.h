// What the relational constraint types (constraint_type.h) share: their ends in
// world space, the angles and penalties of Section 5.2, and the evaluation of one
// constraint of a scene on world transforms.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include <luxplan/constraints/constraint_type.h>
#include <luxplan/constraints/entity_info.h>
#include <luxplan/constraints/terms.h>

namespace luxplan {

// The elastic limit of Eq. 4 as a fraction of the angular tolerance: rejection at
// theta + theta/8.
inline constexpr double kAlignmentRejectFraction = 1.0 / 8.0;
// Eq. 5: the default rejection bound l_rej is 5% of the valid distance range.
inline constexpr double kDistanceRejectFraction = 0.05;
// l_rej when the range gives no length to take 5% of (min = max = 0, or [0, inf)):
// one centimetre, half the default voxel edge.
inline constexpr double kMinDistanceElasticLimit = 0.01;

// Where a constraint end is and which way it faces (world frame): an entity's centre
// and fronts (entityEnd()), the room's axes, or what a kind's ends() makes of them.
struct ConstraintEnd {
    Vec3 center;
    std::vector<Vec2> fronts;  // unit vectors in the xy plane
};

// Front directions mapped by `frame` (entity frame -> another), as unit vectors in the
// xy plane; fronts that map to vertical are dropped.
std::vector<Vec2> frontsIn(const std::vector<Vec2>& fronts, const Transform& frame);

// Eq. 4's measured value: the smallest angle ([0, pi/2]) between the axes of a front
// in `a` and a front in `b` (unit xy vectors).
double axialAngle(const std::vector<Vec2>& a, const std::vector<Vec2>& b);
// Eq. 7's measured value: the smallest angle ([0, pi]) between a front and the
// horizontal direction from `from` to `to` (coincident: pi/2).
double facingAngle(const std::vector<Vec2>& fronts, const Vec3& from, const Vec3& to);
// The same from end `from`'s fronts towards end `to`'s centre.
double facingAngle(const ConstraintEnd& from, const ConstraintEnd& to);

// Fronts of an entity in world space, unit vectors in the xy plane.
std::vector<Vec2> worldFronts(const Scene& scene, const std::vector<Transform>& world, int e);
// An entity's end: its centre (entityCenter()) and world fronts; kRoomEntity: the
// room's axes at the origin.
ConstraintEnd entityEnd(const Scene& scene, const EntityInfo& info, const std::vector<Transform>& world, int e);

// Eq. 4 read in angle space: P(angle, 0, theta, theta/8, 2). Zero up to the
// tolerance theta, quadratic beyond, 1 at theta + theta/8.
double anglePenalty(double angleRad, double toleranceDeg);

// l_rej of a distance range: its `tolerance`, else 5% of max - min; with an infinite
// (or empty) range, 5% of the finite non-zero bound; else kMinDistanceElasticLimit.
double distanceElasticLimit(const DistanceRange& range);
// Eq. 5: P(d, min, max, l_rej, 2).
double distancePenalty(double distance, const DistanceRange& range);

// The keys the types share, read from `f`: "tolerance_deg" (alignment, focus,
// conversation; default 10) and "min", "max" (null: open above), "tolerance"
// (distance, conversation).
double readToleranceDeg(const json::Fields& f);
DistanceRange readDistanceRange(const json::Fields& f);

// What alignment (Eq. 4) and focus (Eq. 7) share: one angle held to a tolerance.
class AngleConstraint : public ConstraintKind {
public:
    explicit AngleConstraint(double toleranceDeg) : toleranceDeg_(toleranceDeg) {}
    bool measuresAngle() const override { return true; }
    std::optional<double> toleranceDeg() const override { return toleranceDeg_; }
    std::string describe() const override;
    std::string describe(const PenaltyTerm& t) const override;
    void report(const PenaltyTerm& t, nlohmann::ordered_json& j) const override;

protected:
    // The term of a measured angle: P = anglePenalty(angle, tolerance).
    void hold(double angleRad, PenaltyTerm& t) const;
    double toleranceDeg_;
};

// Evaluates constraint `constraintIndex` of the scene: its kind's ends, then its
// kind's Eq.
PenaltyTerm evaluateRelational(const Scene& scene, const EntityInfo& info, const std::vector<Transform>& world,
                               int constraintIndex);

// How the kinds write numbers in descriptions: "%.4g" (in report.json:
// json::numberOrNull).
std::string describeNumber(double v);
// "range [0.5, 3] m" and "tolerance 10 deg", as the kinds' describe() print them.
std::string describeRange(const DistanceRange& range);
std::string describeTolerance(double toleranceDeg);

}  // namespace luxplan
