// The flat baseline of Figure 6: groups replaced by world-frame regions and
// cohesion constraints.
#include <luxplan/optimizer/flatten.h>

#include <algorithm>
#include <cmath>
#include <set>

#include <luxplan/constraints/entity_info.h>
#include <luxplan/constraints/relational.h>
#include <luxplan/emitters/emitter_shape.h>
#include <luxplan/lightsamplers/sampler_type.h>
#include <luxplan/optimizer/placement.h>

namespace luxplan {
namespace {

constexpr double kDistanceSlack = 0.05;      // m beyond the range the hierarchy allows
constexpr double kDistanceElasticLimit = 0.25;  // m: a cohesion distance rejects at this much outside
constexpr double kAngleSlackDeg = 10;
constexpr double kFocusAtMostDeg = 60;      // facing the anchor: a focus rule
constexpr double kAlignmentAtMostDeg = 35;  // else parallel fronts: an alignment rule

double rotationDegrees(const Transform& t) { return wrapDegrees(degrees(std::atan2(t.m[3], t.m[0]))); }

Region pointRegion(Vec2 xy, double rotationDeg) {
    Region r;
    r.lo = r.hi = xy;
    r.rotationsDeg = {rotationDeg};
    return r;
}

// Placements of an entity in its parent's frame that stand for its regions: a 5 x 5
// grid over each box times its rotations (an interval: 13 steps); a fixed entity:
// its one placement.
std::vector<Transform> samplePlacements(const Entity& e) {
    if (!e.movable()) return {Transform::placement(e.position, e.rotationDeg)};
    std::vector<Transform> out;
    constexpr int kGrid = 5, kTurns = 13;
    for (const Region& r : e.regions) {
        std::vector<double> turns;
        if (r.continuousRotation) {
            double span = std::min(r.rotationMaxDeg - r.rotationMinDeg, 360.0);
            for (int k = 0; k < kTurns; ++k) turns.push_back(r.rotationMinDeg + span * k / (kTurns - 1));
        } else {
            turns = distinctRotations(r);
        }
        for (int i = 0; i < kGrid; ++i)
            for (int j = 0; j < kGrid; ++j) {
                Vec3 p(r.lo.x + (r.hi.x - r.lo.x) * i / (kGrid - 1), r.lo.y + (r.hi.y - r.lo.y) * j / (kGrid - 1),
                       e.position.z);
                for (double t : turns) out.push_back(Transform::placement(p, t));
            }
    }
    return out;
}

// The flat entity's centre in its own frame (what entityCenter() gives for an entity
// without children).
Vec3 ownCenter(const Entity& e) { return e.hasGeometry() ? e.mesh.bounds().center() : Vec3(); }



Placement placementOf(const Entity& e, const Transform& parentFromEntity) {
    Placement p;
    p.position = parentFromEntity.t;
    p.rotationDeg = rotationDegrees(parentFromEntity);
    if (!e.movable()) return p;
    p.region = findRegion(e.regions, {p.position.x, p.position.y}, p.rotationDeg);
    if (p.region >= 0) p.rotationDeg = normalizeRotation(e.regions[size_t(p.region)], p.rotationDeg);
    return p;
}

}  // namespace

FlatConstraint::FlatConstraint(std::shared_ptr<const ConstraintKind> kind, std::optional<GroupEnd> a,
                               std::optional<GroupEnd> b, bool cohesion)
    : kind_(std::move(kind)), groupA_(std::move(a)), groupB_(std::move(b)), cohesion_(cohesion) {}

void FlatConstraint::evaluate(const ConstraintEnd& a, const ConstraintEnd& b, PenaltyTerm& t) const {
    kind_->evaluate(a, b, t);
}

std::array<ConstraintEnd, 2> FlatConstraint::ends(const Scene& scene, const EntityInfo& info,
                                                  const std::vector<Transform>& world, int a, int b) const {
    auto end = [&](int e, const std::optional<GroupEnd>& group) -> ConstraintEnd {
        if (!group) return entityEnd(scene, info, world, e);
        const Transform worldFromGroup = world[e] * group->entityFromGroup;
        const Transform groupFromWorld = worldFromGroup.inverse();
        Bounds3 box;
        for (int m : group->members) box.extend((groupFromWorld * world[m]).apply(info.localBounds(m)));
        return {group->members.empty() ? worldFromGroup.t : worldFromGroup.applyPoint(box.center()),
                frontsIn(group->fronts, worldFromGroup)};
    };
    return {end(a, groupA_), end(b, groupB_)};
}

FlatScene flattenScene(const Scene& scene) {
    const auto& entities = scene.entities;
    const size_t n = entities.size();
    FlatScene flat;
    flat.flatOf.assign(n, -1);
    flat.representative.assign(n, -1);
    flat.entityFromRepresentative.assign(n, Transform());

    for (size_t e = 0; e < n; ++e)
        if (entities[e].hasGeometry() || !entities[e].isGroup()) {
            flat.flatOf[e] = int(flat.originalOf.size());
            flat.originalOf.push_back(int(e));
        }
    // Representatives bottom up (children come after their parent).
    for (size_t k = n; k-- > 0;) {
        const Entity& e = entities[k];
        if (flat.flatOf[k] >= 0) {
            flat.representative[k] = flat.flatOf[k];
            continue;
        }
        auto repHasGeometry = [&](int c) { return entities[size_t(flat.originalOf[size_t(flat.representative[c])])].hasGeometry(); };
        int anchor = -1;
        for (int c : e.children)
            if (anchor < 0 && !entities[c].movable() && repHasGeometry(c)) anchor = c;
        for (int c : e.children)
            if (anchor < 0 && repHasGeometry(c)) anchor = c;
        if (anchor < 0) anchor = e.children.front();
        flat.representative[k] = flat.representative[anchor];
        flat.entityFromRepresentative[k] =
            Transform::placement(entities[anchor].position, entities[anchor].rotationDeg) * flat.entityFromRepresentative[anchor];
    }

    // World-frame regions, parents first.
    std::vector<std::vector<Region>> worldRegions(n);
    std::vector<bool> canMove(n);
    for (size_t k = 0; k < n; ++k) {
        const Entity& e = entities[k];
        std::vector<Region> local =
            e.movable() ? e.regions : std::vector<Region>{pointRegion({e.position.x, e.position.y}, e.rotationDeg)};
        canMove[k] = e.movable() || (e.parent >= 0 && canMove[size_t(e.parent)]);
        if (e.parent < 0) {
            worldRegions[k] = local;
            continue;
        }
        for (const Region& p : worldRegions[size_t(e.parent)])
            for (const Region& c : local)
                for (Region& r : composeRegions(p, c)) worldRegions[k].push_back(std::move(r));
    }

    Scene& out = flat.scene;
    out = scene;
    out.entities.clear();
    out.optimizer.flat = true;
    const std::vector<Transform> initialWorld = worldTransforms(scene, initialLayout(scene));
    for (int k : flat.originalOf) {
        Entity f = entities[size_t(k)];
        f.name = f.path;
        f.parent = -1;
        f.children.clear();
        f.position = initialWorld[size_t(k)].t;
        f.rotationDeg = rotationDegrees(initialWorld[size_t(k)]);
        f.regions = canMove[size_t(k)] ? worldRegions[size_t(k)] : std::vector<Region>{};
        out.entities.push_back(std::move(f));
    }
    // Samplers and emitters of partless groups go to the representative, in its frame.
    for (size_t k = 0; k < n; ++k) {
        if (flat.flatOf[k] >= 0) continue;
        Entity& rep = out.entities[size_t(flat.representative[k])];
        Transform repFromGroup = flat.entityFromRepresentative[k].inverse();
        for (int s : entities[k].samplers) {
            out.samplers[size_t(s)].type = out.samplers[size_t(s)].type->transformed(repFromGroup);
            rep.samplers.push_back(s);
        }
        for (int m : entities[k].emitters) {
            out.emitters[size_t(m)].shape = out.emitters[size_t(m)].shape->transformed(repFromGroup);
            rep.emitters.push_back(m);
        }
    }
    for (auto& s : out.samplers)
        if (s.entity >= 0) s.entity = flat.representative[size_t(s.entity)];
    for (auto& m : out.emitters)
        if (m.entity >= 0) m.entity = flat.representative[size_t(m.entity)];
    // Constraints on a group keep the group's centre and fronts (GroupEnd).
    const EntityInfo info(scene);
    auto groupEnd = [&](int e) -> std::optional<GroupEnd> {
        if (e < 0 || !entities[size_t(e)].isGroup()) return std::nullopt;
        GroupEnd g;
        for (int m : info.geometrySubtree(e)) g.members.push_back(flat.flatOf[size_t(m)]);
        g.entityFromGroup = flat.entityFromRepresentative[size_t(e)].inverse();
        g.fronts = entities[size_t(e)].fronts;
        g.path = entities[size_t(e)].path;
        return g;
    };
    for (auto& c : out.constraints) {
        std::optional<GroupEnd> groupA = groupEnd(c.a), groupB = groupEnd(c.b);
        if (groupA || groupB) c.kind = std::make_shared<FlatConstraint>(c.kind, std::move(groupA), std::move(groupB), false);
        if (c.a >= 0) c.a = flat.representative[size_t(c.a)];
        if (c.b >= 0) c.b = flat.representative[size_t(c.b)];
    }

    // Overlap keeps skipping former parent-child pairs.
    for (size_t k = 0; k < n; ++k) {
        if (flat.flatOf[k] < 0) continue;
        for (int p = entities[k].parent; p >= 0; p = entities[size_t(p)].parent)
            if (flat.flatOf[size_t(p)] >= 0) out.overlap.exempt.emplace_back(flat.flatOf[size_t(p)], flat.flatOf[k]);
    }

    // Cohesion: every member of a group towards the group's anchor.
    std::set<std::pair<int, int>> bound;
    for (size_t k = 0; k < n; ++k) {
        const Entity& member = entities[k];
        if (member.parent < 0) continue;
        const size_t group = size_t(member.parent);
        int a = flat.representative[k], b = flat.representative[group];
        if (a == b || !bound.insert({a, b}).second) continue;
        const Entity& fa = out.entities[size_t(a)];
        const Entity& fb = out.entities[size_t(b)];
        const Transform bInGroup = flat.entityFromRepresentative[group];
        const Vec3 cb = bInGroup.applyPoint(ownCenter(fb));
        const std::vector<Vec2> frontsB = frontsIn(fb.fronts, bInGroup);
        double dMin = kInf, dMax = 0, focusMax = 0, alignMax = 0;
        for (const Transform& placement : samplePlacements(member)) {
            Transform aInGroup = placement * flat.entityFromRepresentative[k];
            Vec3 ca = aInGroup.applyPoint(ownCenter(fa));
            double d = length(ca - cb);
            dMin = std::min(dMin, d), dMax = std::max(dMax, d);
            const std::vector<Vec2> frontsA = frontsIn(fa.fronts, aInGroup);
            focusMax = std::max(focusMax, facingAngle(frontsA, ca, cb));
            alignMax = std::max(alignMax, axialAngle(frontsA, frontsB));
        }
        ConstraintSpec c;
        c.jsonPath = member.jsonPath + " (cohesion with " + fb.path + ")";
        c.a = a, c.b = b;
        auto cohesion = [&](std::shared_ptr<const ConstraintKind> kind) {
            c.kind = std::make_shared<FlatConstraint>(std::move(kind), std::nullopt, std::nullopt, true);
            out.constraints.push_back(c);
            ++flat.cohesionConstraints;
        };
        cohesion(distanceConstraint({std::max(0.0, dMin - kDistanceSlack), dMax + kDistanceSlack, kDistanceElasticLimit}));
        if (degrees(focusMax) <= kFocusAtMostDeg) cohesion(focusConstraint(degrees(focusMax) + kAngleSlackDeg));
        else if (degrees(alignMax) <= kAlignmentAtMostDeg) cohesion(alignmentConstraint(degrees(alignMax) + kAngleSlackDeg));
        // else it turns freely relative to the anchor: nothing to keep
    }
    return flat;
}

Layout flatLayoutOf(const Scene& original, const FlatScene& flat, const Layout& layout) {
    std::vector<Transform> world = worldTransforms(original, layout);
    Layout out;
    for (size_t f = 0; f < flat.scene.entities.size(); ++f)
        out.placements.push_back(placementOf(flat.scene.entities[f], world[size_t(flat.originalOf[f])]));
    return out;
}

Layout hierarchicalLayoutOf(const Scene& original, const FlatScene& flat, const Layout& flatLayout) {
    const size_t n = original.entities.size();
    const std::vector<Transform> initialWorld = worldTransforms(original, initialLayout(original));
    std::vector<Transform> world(n);
    std::vector<char> moves(n, 0);  // movable, or inside a movable group (parents come first)
    for (size_t k = 0; k < n; ++k) {
        const Entity& e = original.entities[k];
        moves[k] = e.movable() || (e.parent >= 0 && moves[size_t(e.parent)]);
        // An entity fixed in the world (a partless wrapper of movable groups) stays where
        // the scene puts it: its anchor is a member that moves.
        if (!moves[k]) {
            world[k] = initialWorld[k];
            continue;
        }
        Transform rep = localTransform(flatLayout.placements[size_t(flat.representative[k])]);
        world[k] = rep * flat.entityFromRepresentative[k].inverse();
    }
    Layout out = initialLayout(original);
    for (size_t k = 0; k < n; ++k) {
        const Entity& e = original.entities[k];
        if (!e.movable()) continue;
        Transform local = e.parent < 0 ? world[k] : world[size_t(e.parent)].inverse() * world[k];
        out.placements[k] = placementOf(e, local);
        out.placements[k].position.z = e.position.z;
    }
    return out;
}

}  // namespace luxplan
