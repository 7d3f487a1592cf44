// One evaluated term of the geometric cost G(x): which rule, between which
// entities, its measured value, its penalty (Eq. 2) and whether it rejects.
#pragma once

#include <string>
#include <vector>

#include <luxplan/scene/scene.h>

namespace luxplan {

// What an overlap term measures against.
enum class OverlapTarget { Entity, Static, Walls };

struct PenaltyTerm {
    const ConstraintKind* kind = nullptr;  // the relational constraint's type; nullptr: an overlap pair
    int constraint = -1;  // index into Scene::constraints; -1 for an overlap pair
    int a = -1;           // entity
    int b = -1;           // entity, kRoomEntity (alignment with the room), geometry index (overlap
                          // with static geometry) or -1 (overlap with the walls)
    OverlapTarget target = OverlapTarget::Entity;
    unsigned walls = 0;    // overlap with the walls: the room sides crossed (overlap.h: wallBit())
    double value = 0;      // angle (rad), distance (m) or overlap volume (m^3)
    double reference = 0;  // the bound it is held to: tolerance angle (rad), max distance (m), V_ref or
                           // the hard limit (m^3)
    double penalty = 0;    // P (Eq. 2); for conversation G_C of Eq. 8
    double weight = 1;
    bool rejects = false;  // a geometric penalty (or, for a term made of parts, one of them) above 1
    // A term made of parts (conversation, Eq. 8: G_F(a, b), G_F(b, a), G_D(a, b)):
    // each part rejects on its own; value is the distance.
    std::vector<double> parts;

    bool overlap() const { return kind == nullptr; }
    // Overlap with the walls or a static item: a hard limit, no part of G.
    bool hardOverlap() const { return overlap() && target != OverlapTarget::Entity; }
};

// The scene file's name of the term's rule: its constraint type, or "overlap".
const char* termName(const PenaltyTerm& term);

// e.g. `alignment "desk1" / room (/constraints/0): 14.2 deg, tolerance 10 deg, P = 1.47`.
std::string describe(const Scene& scene, const PenaltyTerm& term);

}  // namespace luxplan
