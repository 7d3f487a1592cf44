// The relational rules of Section 5.2 on world transforms: alignment (Eq. 4),
// distance (Eq. 5), focus (Eq. 7) and conversation (Eq. 8).
#pragma once

#include <vector>

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

// Front directions mapped by `frame` (entity frame -> another), as unit vectors in the
// xy plane; fronts that map to vertical are dropped.
std::vector<Vec2> frontsIn(const std::vector<Vec2>& fronts, const Transform& frame);

// Eq. 4's measured value: the smallest angle ([0, pi/2]) between the axes of a front
// in `a` and a front in `b` (unit xy vectors).
double axialAngle(const std::vector<Vec2>& a, const std::vector<Vec2>& b);
// Eq. 7's measured value: the smallest angle ([0, pi]) between a front and the
// horizontal direction from `from` to `to` (coincident: pi/2).
double facingAngle(const std::vector<Vec2>& fronts, const Vec3& from, const Vec3& to);

// Fronts of an entity in world space, unit vectors in the xy plane.
std::vector<Vec2> worldFronts(const Scene& scene, const std::vector<Transform>& world, int e);

// evaluateRelational applies axialAngle (b = room: the room axes) and facingAngle to
// the ends' fronts and centres, and Eq. 5 takes the distance between the centres: an
// end's own (entityCenter()), or a former group's (ConstraintSpec::groupA/B).

// Eq. 4 read in angle space: P(angle, 0, theta, theta/8, 2). Zero up to the
// tolerance theta, quadratic beyond, 1 at theta + theta/8.
double anglePenalty(double angleRad, double toleranceDeg);

// l_rej of a distance or conversation constraint: its `tolerance`, else 5% of
// max - min; with an infinite (or empty) range, 5% of the finite non-zero bound;
// else kMinDistanceElasticLimit.
double distanceElasticLimit(const ConstraintSpec& spec);

// Evaluates one alignment, distance, focus or conversation constraint.
PenaltyTerm evaluateRelational(const Scene& scene, const EntityInfo& info, const std::vector<Transform>& world,
                               int constraintIndex);

}  // namespace luxplan
