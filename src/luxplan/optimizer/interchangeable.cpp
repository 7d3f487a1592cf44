#include <luxplan/optimizer/interchangeable.h>

#include <algorithm>
#include <map>
#include <tuple>

#include <luxplan/constraints/constraint_type.h>
#include <luxplan/emitters/emitter_shape.h>
#include <luxplan/lightsamplers/sampler_type.h>

namespace luxplan {
namespace {

bool sameRegions(const std::vector<Region>& a, const std::vector<Region>& b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i) {
        const Region &x = a[i], &y = b[i];
        if (!(x.lo == y.lo) || !(x.hi == y.hi) || x.rotationsDeg != y.rotationsDeg || x.continuousRotation != y.continuousRotation ||
            x.rotationMinDeg != y.rotationMinDeg || x.rotationMaxDeg != y.rotationMaxDeg || x.bound != y.bound)
            return false;
    }
    return true;
}

bool sameMesh(const TriangleMesh& a, const TriangleMesh& b) {
    if (a.positions.size() != b.positions.size() || a.triangles != b.triangles || a.materials != b.materials ||
        a.normals.size() != b.normals.size())
        return false;
    for (size_t i = 0; i < a.positions.size(); ++i)
        if (!(a.positions[i] == b.positions[i])) return false;
    for (size_t i = 0; i < a.normals.size(); ++i)
        if (!(a.normals[i] == b.normals[i])) return false;
    return true;
}

bool sameGoal(const StatisticGoal& a, const StatisticGoal& b) {
    return a.statistic == b.statistic && a.targetMin == b.targetMin && a.targetMax == b.targetMax && a.tolerance == b.tolerance;
}

bool sameSampler(const LightSamplerSpec& a, const LightSamplerSpec& b) {
    return a.type->describe() == b.type->describe() && a.targetMin == b.targetMin && a.targetMax == b.targetMax &&
           a.tolerance == b.tolerance && a.weight == b.weight &&
           std::equal(a.statistics.begin(), a.statistics.end(), b.statistics.begin(), b.statistics.end(), sameGoal);
}

bool sameEmitter(const Emitter& a, const Emitter& b) {
    return a.shape->describe() == b.shape->describe() && a.fluxLm == b.fluxLm && a.cctK == b.cctK;
}

// The same entity but for its name, with its subtree matched child by child into
// `map` (a's descendants to b's). Children must be fixed in their parent: a movable
// child's placement is part of the state, so a swap of parents trades it.
bool sameSubtree(const Scene& s, int a, int b, bool top, std::map<int, int>& map) {
    const Entity &x = s.entities[size_t(a)], &y = s.entities[size_t(b)];
    if (!top && (x.movable() || y.movable() || !(x.position == y.position) || x.rotationDeg != y.rotationDeg)) return false;
    if (top && (!sameRegions(x.regions, y.regions) || x.inRoom != y.inRoom)) return false;
    if (!sameMesh(x.mesh, y.mesh) || x.fronts.size() != y.fronts.size() || x.samplers.size() != y.samplers.size() ||
        x.emitters.size() != y.emitters.size() || x.children.size() != y.children.size())
        return false;
    for (size_t i = 0; i < x.fronts.size(); ++i)
        if (!(x.fronts[i] == y.fronts[i])) return false;
    for (size_t i = 0; i < x.samplers.size(); ++i)
        if (!sameSampler(s.samplers[size_t(x.samplers[i])], s.samplers[size_t(y.samplers[i])])) return false;
    for (size_t i = 0; i < x.emitters.size(); ++i)
        if (!sameEmitter(s.emitters[size_t(x.emitters[i])], s.emitters[size_t(y.emitters[i])])) return false;
    map[a] = b, map[b] = a;
    for (size_t i = 0; i < x.children.size(); ++i)
        if (!sameSubtree(s, x.children[i], y.children[i], false, map)) return false;
    return true;
}

}  // namespace

bool interchangeable(const Scene& scene, int a, int b) {
    if (a == b || scene.entities[size_t(a)].parent != scene.entities[size_t(b)].parent) return false;
    std::map<int, int> swap;
    if (!sameSubtree(scene, a, b, true, swap)) return false;
    auto mapped = [&](int e) {
        auto it = swap.find(e);
        return it == swap.end() ? e : it->second;
    };
    // The rules, as (what the rule is, its ends), must be the same multiset after the trade.
    using Key = std::tuple<std::string, double, int, int>;
    std::vector<Key> before, after;
    auto key = [](const ConstraintSpec& c, int x, int y) {
        if (c.kind->symmetric() && x > y) std::swap(x, y);  // either order measures the same
        return Key(std::string(c.kind->name()) + ": " + c.kind->describe(), c.weight, x, y);
    };
    for (const ConstraintSpec& c : scene.constraints) {
        before.push_back(key(c, c.a, c.b));
        after.push_back(key(c, mapped(c.a), mapped(c.b)));
    }
    std::sort(before.begin(), before.end());
    std::sort(after.begin(), after.end());
    if (before != after) return false;
    std::vector<std::pair<int, int>> exempt = scene.overlap.exempt, exemptAfter;
    for (auto [x, y] : exempt) exemptAfter.emplace_back(std::min(mapped(x), mapped(y)), std::max(mapped(x), mapped(y)));
    for (auto& [x, y] : exempt)
        if (x > y) std::swap(x, y);
    std::sort(exempt.begin(), exempt.end());
    std::sort(exemptAfter.begin(), exemptAfter.end());
    return exempt == exemptAfter;
}

}  // namespace luxplan
