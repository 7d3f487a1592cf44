// Entities a swap cannot tell apart. Two siblings are interchangeable when they are the
// same in everything the cost sees: parts, fronts, regions (and what they bound, and
// whether the room holds their footprint), samplers (type, target,
// weight), luminaires, identical fixed children, and rules that map onto themselves
// when the two trade places. Swapping them (positions only, rotations stay) gives the
// same layout up to names when their rotations agree, and a pair of rotations
// otherwise: a null move or a rotate move, so the search does not propose it
// (MoveSet). The test is static, so the proposal stays symmetric.
#pragma once

#include <luxplan/scene/scene.h>

namespace luxplan {

bool interchangeable(const Scene& scene, int a, int b);

}  // namespace luxplan
