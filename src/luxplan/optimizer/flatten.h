// The paper's flat baseline (Figure 6): the same furniture with its groups taken
// away, so that a single-level search has to keep each functional group together
// "solely relying on constraints". flattenScene() rewrites a scene that way:
//   - every entity with parts becomes a top-level object; its regions are its
//     group's regions composed with its own (world frame, a superset of where the
//     hierarchy could put it), so it moves, turns, jumps and swaps on its own;
//   - a group without parts is represented by its anchor (below) and dropped;
//   - each object that was inside a group gets cohesion constraints towards the
//     group's anchor: a distance range and, where it faced the anchor, a focus
//     rule (else an alignment rule), with ranges taken from where the hierarchy
//     allowed it to be, so any layout the hierarchy can reach pays nothing for them;
//   - overlap keeps ignoring the pairs that were parent and child.
// G's normalizer leaves cohesion terms out, so a layout the hierarchy allows has the
// same C in both scenes; the two searches differ only in how they move. What the flat
// scene's constraints need beyond the scene model (ends that stand for groups, being
// left out of the normalizer) their kind carries: FlatConstraint.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include <luxplan/constraints/constraint_type.h>
#include <luxplan/scene/layout.h>

namespace luxplan {

// A constraint end that stands for a former group: it keeps the group's centre (Eqs.
// 5, 7: the box of the members' geometry in the group's frame) and the group's fronts,
// carried by the entity that represents the group.
struct GroupEnd {
    std::vector<int> members;   // flat entities whose own geometry the box holds
    Transform entityFromGroup;  // the group's frame in the representative's
    std::vector<Vec2> fronts;   // the group's fronts, group frame
    std::string path;           // the former group's path, which reports name the end by
};

// The kind of a constraint flattening wrote: the kind it wraps (the scene's, or a
// cohesion rule's distance, focus or alignment), measured between ends that may stand
// for former groups; a cohesion rule is left out of G's normalizer. It reads, reports
// and describes itself as the kind it wraps.
class FlatConstraint final : public ConstraintKind {
public:
    FlatConstraint(std::shared_ptr<const ConstraintKind> kind, std::optional<GroupEnd> a, std::optional<GroupEnd> b,
                   bool cohesion);
    const std::optional<GroupEnd>& groupA() const { return groupA_; }
    const std::optional<GroupEnd>& groupB() const { return groupB_; }
    bool cohesion() const { return cohesion_; }

    const char* name() const override { return kind_->name(); }
    bool acceptsRoom() const override { return kind_->acceptsRoom(); }
    void evaluate(const ConstraintEnd& a, const ConstraintEnd& b, PenaltyTerm& t) const override;
    std::array<ConstraintEnd, 2> ends(const Scene& scene, const EntityInfo& info, const std::vector<Transform>& world,
                                      int a, int b) const override;
    bool countsInNormalizer() const override { return !cohesion_; }
    bool measuresAngle() const override { return kind_->measuresAngle(); }
    std::optional<double> toleranceDeg() const override { return kind_->toleranceDeg(); }
    std::optional<DistanceRange> distanceRange() const override { return kind_->distanceRange(); }
    std::string describe() const override { return kind_->describe(); }
    std::string describe(const PenaltyTerm& t) const override { return kind_->describe(t); }
    void report(const PenaltyTerm& t, nlohmann::ordered_json& j) const override { kind_->report(t, j); }

private:
    std::shared_ptr<const ConstraintKind> kind_;
    std::optional<GroupEnd> groupA_, groupB_;
    bool cohesion_;
};

struct FlatScene {
    Scene scene;                     // every entity top level, world-frame regions
    std::vector<int> flatOf;         // original entity -> its flat entity (-1: a group without parts)
    std::vector<int> originalOf;     // flat entity -> original entity
    std::vector<int> representative; // original entity -> the flat entity that stands for it
                                     // (itself, or a partless group's anchor)
    std::vector<Transform> entityFromRepresentative;  // the representative's frame in the
                                                      // entity's, at the initial placement
    int cohesionConstraints = 0;     // how many constraints flattening added
};

// A group's anchor: the group itself when it has parts; else (recursively) the
// anchor of its first child that is fixed inside the group and has geometry, else
// of its first child with geometry, else of its first child. Constraints and
// samplers on a partless group move to its anchor; a constraint on any group keeps
// the group's centre and fronts (a FlatConstraint's GroupEnd), so it measures the same.
FlatScene flattenScene(const Scene& scene);

// A layout of the original scene in the flat scene (the same world transforms;
// region: the first flat region holding the placement, else -1).
Layout flatLayoutOf(const Scene& original, const FlatScene& flat, const Layout& layout);

// A flat layout in the original scene's hierarchy: a partless group is placed so
// that its anchor keeps its initial place in the group; every entity's placement is
// its world transform seen from its parent. region: the first holding it, else -1
// (a flat search may leave a group's objects where no group placement puts them).
Layout hierarchicalLayoutOf(const Scene& original, const FlatScene& flat, const Layout& flatLayout);

}  // namespace luxplan
