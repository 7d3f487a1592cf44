#include <luxplan/scene/room.h>

#include <algorithm>
#include <set>

namespace luxplan {

WallFrame wallFrame(const Bounds3& r, Wall wall) {
    Vec3 s = r.size();
    switch (wall) {
        case Wall::South: return {{r.lo.x, r.lo.y, r.lo.z}, {1, 0, 0}, {0, 0, 1}, s.x, s.z, {0, 1, 0}};
        case Wall::North: return {{r.lo.x, r.hi.y, r.lo.z}, {1, 0, 0}, {0, 0, 1}, s.x, s.z, {0, -1, 0}};
        case Wall::West: return {{r.lo.x, r.lo.y, r.lo.z}, {0, 1, 0}, {0, 0, 1}, s.y, s.z, {1, 0, 0}};
        case Wall::East: return {{r.hi.x, r.lo.y, r.lo.z}, {0, 1, 0}, {0, 0, 1}, s.y, s.z, {-1, 0, 0}};
        case Wall::Ceiling: return {{r.lo.x, r.lo.y, r.hi.z}, {1, 0, 0}, {0, 1, 0}, s.x, s.y, {0, 0, -1}};
    }
    return {};
}

std::array<double, 4> openingRect(const Bounds3& room, const Opening& o) {
    if (o.wall == Wall::Ceiling) {
        double cx = o.center.x - room.lo.x, cy = o.center.y - room.lo.y;
        return {cx - o.size.x / 2, cy - o.size.y / 2, cx + o.size.x / 2, cy + o.size.y / 2};
    }
    return {o.offset, o.sill, o.offset + o.width, o.sill + o.height};
}

Rect3 openingQuad(const Bounds3& room, const Opening& o) {
    const WallFrame f = wallFrame(room, o.wall);
    const auto r = openingRect(room, o);
    return {f.origin + f.u * r[0] + f.v * r[1], f.u * (r[2] - r[0]), f.v * (r[3] - r[1])};
}

namespace {

void addOrientedQuad(TriangleMesh& mesh, const WallFrame& f, double u0, double v0, double u1, double v1,
                     uint32_t material) {
    auto at = [&](double u, double v) { return f.origin + f.u * u + f.v * v; };
    Vec3 a = at(u0, v0), b = at(u1, v0), c = at(u1, v1), d = at(u0, v1);
    if (dot(cross(f.u, f.v), f.inward) > 0)
        addQuad(mesh, a, b, c, d, material);
    else
        addQuad(mesh, a, d, c, b, material);
}

// The wall rectangle minus the holes, as the cells of the grid their edges make.
void addWallWithHoles(TriangleMesh& mesh, const WallFrame& f, const std::vector<std::array<double, 4>>& holes,
                      uint32_t material) {
    std::set<double> us{0.0, f.length}, vs{0.0, f.height};
    for (const auto& h : holes) {
        us.insert(std::clamp(h[0], 0.0, f.length)), us.insert(std::clamp(h[2], 0.0, f.length));
        vs.insert(std::clamp(h[1], 0.0, f.height)), vs.insert(std::clamp(h[3], 0.0, f.height));
    }
    std::vector<double> u(us.begin(), us.end()), v(vs.begin(), vs.end());
    for (size_t j = 0; j + 1 < v.size(); ++j)
        for (size_t i = 0; i + 1 < u.size(); ++i) {
            double cu = 0.5 * (u[i] + u[i + 1]), cv = 0.5 * (v[j] + v[j + 1]);
            bool inHole = std::any_of(holes.begin(), holes.end(), [&](const auto& h) {
                return cu > h[0] && cu < h[2] && cv > h[1] && cv < h[3];
            });
            if (!inHole) addOrientedQuad(mesh, f, u[i], v[j], u[i + 1], v[j + 1], material);
        }
}

}  // namespace

TriangleMesh buildRoomShell(const RoomShell& room) {
    TriangleMesh mesh;
    const Bounds3& r = room.box;
    // Floor, facing up.
    addQuad(mesh, {r.lo.x, r.lo.y, r.lo.z}, {r.hi.x, r.lo.y, r.lo.z}, {r.hi.x, r.hi.y, r.lo.z}, {r.lo.x, r.hi.y, r.lo.z},
            room.floorMaterial);
    for (Wall wall : {Wall::North, Wall::South, Wall::East, Wall::West, Wall::Ceiling}) {
        WallFrame f = wallFrame(r, wall);
        std::vector<std::array<double, 4>> holes;
        for (const Opening& o : room.openings)
            if (o.wall == wall) holes.push_back(openingRect(r, o));
        addWallWithHoles(mesh, f, holes, wall == Wall::Ceiling ? room.ceilingMaterial : room.wallMaterial);
        for (const Opening& o : room.openings)
            if (o.wall == wall && o.material) {
                auto h = openingRect(r, o);
                addOrientedQuad(mesh, f, h[0], h[1], h[2], h[3], *o.material);
            }
        for (const Opening& o : room.openings)
            if (o.wall == wall && o.blindMaterial && o.blindDeployed) {
                WallFrame inside = f;
                inside.origin = f.origin + f.inward * kBlindInset;
                auto h = openingRect(r, o);
                addOrientedQuad(mesh, inside, h[0], h[1], h[2], h[3], *o.blindMaterial);
            }
    }
    return mesh;
}

}  // namespace luxplan
