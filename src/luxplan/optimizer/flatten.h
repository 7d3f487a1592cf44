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
// same C in both scenes; the two searches differ only in how they move.
#pragma once

#include <vector>

#include <luxplan/scene/layout.h>

namespace luxplan {

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
// the group's centre and fronts (ConstraintSpec::groupA/B), so it measures the same.
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
