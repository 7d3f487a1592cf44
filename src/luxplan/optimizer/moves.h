// The mutations of the paper's Section 6 (translation, rotation, position swap,
// interval jump) and the move set of one hierarchy level, built so that every
// proposal is symmetric or carries its Hastings factor.
#pragma once

#include <array>
#include <vector>

#include <luxplan/core/rng.h>
#include <luxplan/scene/layout.h>

namespace luxplan {
class LightMap;
}

namespace luxplan {

// Snap (the polish only): the rotation to the nearest quarter turn of the room, when the
// region allows it. Guided: a new placement drawn from the entity's light map
// (optimizer/light_map.h), where its own targets held in the layouts lit so far.
enum class MoveType { Translate, Rotate, Swap, Jump, Snap, Guided };
inline constexpr int kMoveTypeCount = 6;
inline constexpr std::array<MoveType, kMoveTypeCount> kMoveTypes{MoveType::Translate, MoveType::Rotate, MoveType::Swap,
                                                                  MoveType::Jump, MoveType::Snap, MoveType::Guided};
const char* moveName(MoveType type);

// The paper's sigma_i: 25% of the interval's size.
inline constexpr double kDefaultSigmaFraction = 0.25;

// Standard normal deviate (Box-Muller, one draw per call).
double sampleStandardNormal(Rng& rng);

// Each move edits placements in place and returns false when the proposal leaves the
// valid regions; the chain then stays where it is (the caller keeps the old state).

// Translation: x, y each from N(current, sigma = f * region extent), kept in the
// current region. A proposal outside is rejected, not redrawn: resampling until
// inside would make the proposal density depend on the distance to the border
// (asymmetric); rejecting keeps q(x -> x') = q(x' -> x). An axis of zero extent stays.
bool translateMove(const Entity& entity, Placement& placement, double sigmaFraction, Rng& rng);

// Rotation within the current region. Discrete: uniform among the region's other
// rotations (symmetric: 1/(n-1) both ways). Interval: N(current, sigma = f * span),
// rejected outside the interval; a full turn wraps around instead. False when the
// region allows one rotation only.
bool rotateMove(const Entity& entity, Placement& placement, double sigmaFraction, Rng& rng);

// Position swap (orientations kept, each entity keeps its own z). Each entity keeps
// its region when that region holds the new position, else takes the first region
// that does; false when one of them has none.
bool swapMove(const Entity& a, Placement& pa, const Entity& b, Placement& pb);

// Interval jump: to a uniformly chosen other region, with position and rotation
// uniform there. Returns log q(x' -> x)/q(x -> x') = log(measure(new) / measure(old))
// (regionMeasure()), the Hastings factor that makes the jump exact when regions differ
// in size. The entity needs two regions or more.
double jumpMove(const Entity& entity, Placement& placement, Rng& rng);

// Step sizes of translate and rotate: each proposal draws its sigma uniformly from
// sigmaFraction x each scale. A mixture of symmetric kernels is symmetric, so no
// Hastings factor is needed; the coarse scale (the paper's 25%) crosses the room, the
// fine ones place the last centimetres and degrees a coarse step almost never hits.
inline constexpr std::array<double, 3> kDefaultStepScales{1.0, 0.2, 0.04};

// Snap: the rotation to the nearest quarter turn of the room (its world rotation a
// multiple of 90 degrees, `parentWorldDeg` being its ancestors' turn), if the region
// allows that rotation; false when it is on one already or the region does not.
bool snapMove(const Entity& entity, Placement& placement, double parentWorldDeg);

struct MoveOptions {
    double sigmaFraction = kDefaultSigmaFraction;
    std::vector<double> stepScales{kDefaultStepScales.begin(), kDefaultStepScales.end()};
    bool jumpHastings = true;  // false: the paper's plain symmetric treatment of jumps (and of guided draws)
    // The polish's moves (Optimizer::polish): translate and rotate only, at the fine
    // scales, plus a snap of the rotation to the nearest quarter turn of the room.
    bool polish = false;
};

// The sigma fraction of one translate or rotate proposal: sigmaFraction times a scale
// drawn uniformly from stepScales (one draw of the stream only when there are two or more).
double stepFraction(const MoveOptions& options, Rng& rng);

// What a proposal did.
struct Proposal {
    MoveType type = MoveType::Translate;
    int entity = -1;
    int partner = -1;        // the other entity of a swap
    bool valid = false;      // false: left the regions (or a null move); the chain stays
    double logHastings = 0;  // log of the proposal ratio q(x' -> x) / q(x -> x')
};

// The moves of one hierarchy level over a fixed set of movable entities. A proposal
// picks a move type uniformly among the applicable ones, then an entity uniformly
// among those the type applies to, and for a swap a partner uniformly among its
// siblings (same parent) in the set. Applicability depends on the entities' regions
// only, never on the state, so the selection probabilities are the same forwards and
// backwards:
//   translate: some region has a positive extent;  rotate: some region allows two
//   rotations or more;  swap: a sibling in the set;  jump: two regions or more.
class MoveSet {
public:
    // `lightMap`, when given, adds the guided move for the entities it maps (not in a
    // polish); it must outlive the set.
    MoveSet(const Scene& scene, std::vector<int> entities, MoveOptions options = {}, const LightMap* lightMap = nullptr);

    bool empty() const { return types_.empty(); }
    const std::vector<int>& entities() const { return entities_; }
    const std::vector<MoveType>& types() const { return types_; }
    const std::vector<int>& candidates(MoveType type) const { return candidates_[int(type)]; }

    // Draws one proposal and applies it to `layout` (the caller keeps the current
    // state to return to).
    Proposal propose(Layout& layout, Rng& rng) const;
    // Applies a move of the given type to the given entity (tests, diagnostics).
    Proposal apply(MoveType type, int entity, Layout& layout, Rng& rng) const;

private:
    const Scene* scene_;
    std::vector<int> entities_;
    MoveOptions options_;
    std::vector<MoveType> types_;
    std::array<std::vector<int>, kMoveTypeCount> candidates_;
    std::vector<std::vector<int>> siblings_;  // per entity index: swap partners in the set
    const LightMap* lightMap_ = nullptr;
};

}  // namespace luxplan
