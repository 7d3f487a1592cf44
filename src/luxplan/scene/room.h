// The room shell as triangles: floor, ceiling and four walls facing inwards,
// with rectangular holes for the openings and a pane in each glazed one.
#pragma once

#include <luxplan/core/spherical_rect.h>
#include <luxplan/scene/mesh.h>
#include <luxplan/scene/scene.h>

namespace luxplan {

// A wall or ceiling as a rectangle in its own (u, v) coordinates.
struct WallFrame {
    Vec3 origin;  // (u, v) = (0, 0)
    Vec3 u, v;    // unit axes
    double length = 0, height = 0;
    Vec3 inward;  // unit normal pointing into the room
};

WallFrame wallFrame(const Bounds3& room, Wall wall);

// The opening's rectangle in its wall's (u, v) coordinates: {u0, v0, u1, v1}.
std::array<double, 4> openingRect(const Bounds3& room, const Opening& opening);
// The same rectangle in the world: the pane buildRoomShell puts in a glazed opening.
Rect3 openingQuad(const Bounds3& room, const Opening& opening);

TriangleMesh buildRoomShell(const RoomShell& room);

}  // namespace luxplan
