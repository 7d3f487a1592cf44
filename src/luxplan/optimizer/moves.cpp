// Translation, rotation, swap and jump proposals, and their selection per level.
#include <luxplan/optimizer/moves.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <luxplan/optimizer/interchangeable.h>
#include <luxplan/optimizer/light_map.h>
#include <luxplan/optimizer/placement.h>

namespace luxplan {

const char* moveName(MoveType type) {
    switch (type) {
        case MoveType::Translate: return "translate";
        case MoveType::Rotate: return "rotate";
        case MoveType::Swap: return "swap";
        case MoveType::Jump: return "jump";
        case MoveType::Snap: return "snap";
        case MoveType::Guided: return "guided";
    }
    return "?";
}

double sampleStandardNormal(Rng& rng) {
    double u1 = rng.uniform(), u2 = rng.uniform();
    return std::sqrt(-2.0 * std::log(1.0 - u1)) * std::cos(2 * kPi * u2);
}

double stepFraction(const MoveOptions& options, Rng& rng) {
    const auto& scales = options.stepScales;
    if (scales.empty()) return options.sigmaFraction;
    if (scales.size() == 1) return options.sigmaFraction * scales[0];
    return options.sigmaFraction * scales[rng.uniformInt(uint32_t(scales.size()))];
}

// The entity's rotation in the world: its own plus every ancestor's (entities turn
// about z only).
static double worldRotationOfParent(const Scene& scene, const Layout& layout, int entity) {
    double r = 0;
    for (int a = scene.entities[size_t(entity)].parent; a >= 0; a = scene.entities[size_t(a)].parent)
        r += layout.placements[size_t(a)].rotationDeg;
    return r;
}

bool snapMove(const Entity& entity, Placement& p, double parentWorldDeg) {
    const Region& r = entity.regions.at(size_t(p.region));
    const double world = parentWorldDeg + p.rotationDeg;
    const double snapped = 90.0 * std::round(world / 90.0) - parentWorldDeg;
    if (std::abs(snapped - p.rotationDeg) < 1e-9) return false;  // already on a quarter turn
    if (!r.continuousRotation) {
        for (double a : distinctRotations(r))
            if (sameRotation(a, snapped)) {
                p.rotationDeg = a;
                return true;
            }
        return false;
    }
    const double a = fullTurn(r) ? normalizeRotation(r, snapped) : snapped;
    if (!fullTurn(r) && (a < r.rotationMinDeg - 1e-9 || a > r.rotationMaxDeg + 1e-9)) return false;
    p.rotationDeg = std::clamp(a, r.rotationMinDeg, r.rotationMaxDeg);
    return true;
}

bool translateMove(const Entity& entity, Placement& p, double sigmaFraction, Rng& rng) {
    const Region& r = entity.regions.at(size_t(p.region));
    double ex = r.hi.x - r.lo.x, ey = r.hi.y - r.lo.y;
    if (!(ex > 0) && !(ey > 0)) return false;
    double x = p.position.x, y = p.position.y;
    if (ex > 0) x += sigmaFraction * ex * sampleStandardNormal(rng);
    if (ey > 0) y += sigmaFraction * ey * sampleStandardNormal(rng);
    if (x < r.lo.x || x > r.hi.x || y < r.lo.y || y > r.hi.y) return false;
    p.position.x = x, p.position.y = y;
    return true;
}

bool rotateMove(const Entity& entity, Placement& p, double sigmaFraction, Rng& rng) {
    const Region& r = entity.regions.at(size_t(p.region));
    if (!r.continuousRotation) {
        std::vector<double> others;
        for (double a : distinctRotations(r))
            if (!sameRotation(a, p.rotationDeg)) others.push_back(a);
        if (others.empty()) return false;
        p.rotationDeg = others[rng.uniformInt(uint32_t(others.size()))];
        return true;
    }
    double span = r.rotationMaxDeg - r.rotationMinDeg;
    if (!(span > 0)) return false;
    if (fullTurn(r)) {
        double a = normalizeRotation(r, p.rotationDeg) + sigmaFraction * 360.0 * sampleStandardNormal(rng);
        p.rotationDeg = normalizeRotation(r, a);
        return true;
    }
    double a = normalizeRotation(r, p.rotationDeg) + sigmaFraction * span * sampleStandardNormal(rng);
    if (a < r.rotationMinDeg || a > r.rotationMaxDeg) return false;
    p.rotationDeg = a;
    return true;
}

// The region for a placement moved to `xy`: its own when that still holds it.
static int regionFor(const Entity& e, const Placement& p, Vec2 xy) {
    if (p.region >= 0 && regionContains(e.regions[size_t(p.region)], xy, p.rotationDeg)) return p.region;
    for (size_t i = 0; i < e.regions.size(); ++i)
        if (regionContains(e.regions[i], xy, p.rotationDeg)) return int(i);
    return -1;
}

bool swapMove(const Entity& a, Placement& pa, const Entity& b, Placement& pb) {
    Vec2 xa(pa.position.x, pa.position.y), xb(pb.position.x, pb.position.y);
    int ra = regionFor(a, pa, xb), rb = regionFor(b, pb, xa);
    if (ra < 0 || rb < 0) return false;
    pa.region = ra, pb.region = rb;
    pa.position.x = xb.x, pa.position.y = xb.y;
    pb.position.x = xa.x, pb.position.y = xa.y;
    return true;
}

double jumpMove(const Entity& entity, Placement& p, Rng& rng) {
    int m = int(entity.regions.size());
    if (m < 2) throw std::invalid_argument("jumpMove: entity \"" + entity.path + "\" has fewer than two regions");
    int from = p.region;
    if (from < 0 || from >= m) throw std::invalid_argument("jumpMove: entity \"" + entity.path + "\" is in no region");
    int to = int(rng.uniformInt(uint32_t(m - 1)));
    if (to >= from) ++to;  // uniform among the other regions
    p = sampleInRegion(entity, to, p.position.z, rng);
    return std::log(regionMeasure(entity.regions[size_t(to)])) - std::log(regionMeasure(entity.regions[size_t(from)]));
}

MoveSet::MoveSet(const Scene& scene, std::vector<int> entities, MoveOptions options, const LightMap* lightMap)
    : scene_(&scene), entities_(std::move(entities)), options_(options), siblings_(scene.entities.size()), lightMap_(lightMap) {
    for (int e : entities_) {
        const Entity& entity = scene.entities.at(size_t(e));
        if (!entity.movable()) throw std::invalid_argument("MoveSet: entity \"" + entity.path + "\" is fixed");
        bool translates = false, rotates = false;
        for (const Region& r : entity.regions) {
            translates = translates || r.hi.x > r.lo.x || r.hi.y > r.lo.y;
            rotates = rotates || (r.continuousRotation ? r.rotationMaxDeg > r.rotationMinDeg : distinctRotations(r).size() > 1);
        }
        // Swap partners: siblings, but not the ones a swap cannot tell apart
        // (interchangeable.h: the swap would be a null move).
        for (int o : entities_)
            if (o != e && scene.entities[size_t(o)].parent == entity.parent && !interchangeable(scene, e, o))
                siblings_[size_t(e)].push_back(o);
        if (translates) candidates_[int(MoveType::Translate)].push_back(e);
        if (rotates) candidates_[int(MoveType::Rotate)].push_back(e);
        if (options_.polish) {
            if (rotates) candidates_[int(MoveType::Snap)].push_back(e);
            continue;
        }
        if (!siblings_[size_t(e)].empty()) candidates_[int(MoveType::Swap)].push_back(e);
        if (entity.regions.size() > 1) candidates_[int(MoveType::Jump)].push_back(e);
        if (lightMap_ && lightMap_->covers(e)) candidates_[int(MoveType::Guided)].push_back(e);
    }
    for (MoveType t : kMoveTypes)
        if (!candidates_[int(t)].empty()) types_.push_back(t);
}

Proposal MoveSet::propose(Layout& layout, Rng& rng) const {
    if (types_.empty()) throw std::logic_error("MoveSet::propose: no applicable move");
    MoveType type = types_[rng.uniformInt(uint32_t(types_.size()))];
    const auto& candidates = candidates_[int(type)];
    int entity = candidates[rng.uniformInt(uint32_t(candidates.size()))];
    return apply(type, entity, layout, rng);
}

Proposal MoveSet::apply(MoveType type, int entity, Layout& layout, Rng& rng) const {
    Proposal p;
    p.type = type;
    p.entity = entity;
    const Entity& e = scene_->entities[size_t(entity)];
    Placement& placement = layout.placements[size_t(entity)];
    switch (type) {
        case MoveType::Translate: p.valid = translateMove(e, placement, stepFraction(options_, rng), rng); break;
        case MoveType::Rotate: p.valid = rotateMove(e, placement, stepFraction(options_, rng), rng); break;
        case MoveType::Snap: p.valid = snapMove(e, placement, worldRotationOfParent(*scene_, layout, entity)); break;
        case MoveType::Swap: {
            const auto& partners = siblings_[size_t(entity)];
            if (partners.empty()) break;
            p.partner = partners[rng.uniformInt(uint32_t(partners.size()))];
            Placement a = placement, b = layout.placements[size_t(p.partner)];
            p.valid = swapMove(e, a, scene_->entities[size_t(p.partner)], b);
            if (p.valid) placement = a, layout.placements[size_t(p.partner)] = b;
            break;
        }
        case MoveType::Guided:
            if (!lightMap_ || !lightMap_->covers(entity)) break;
            p.logHastings = lightMap_->propose(entity, placement, rng);
            if (!options_.jumpHastings) p.logHastings = 0;
            p.valid = true;
            break;
        case MoveType::Jump:
            if (e.regions.size() < 2) break;
            p.logHastings = jumpMove(e, placement, rng);
            if (!options_.jumpHastings) p.logHastings = 0;
            p.valid = true;
            break;
    }
    return p;
}

}  // namespace luxplan
