#include <luxplan/incremental/entity_clusters.h>

#include <algorithm>
#include <map>

#include <luxplan/emitters/emitter_shape.h>

namespace luxplan {
namespace {

// A cluster's triangles are tested one by one once a segment crosses its box, up to
// this many (a larger cluster: its box alone decides).
constexpr size_t kMostTrianglesTested = 32;

// Boxes around clusters of triangles: median splits of the centroids along the widest
// axis, down to a dozen triangles (a box part's six faces become thin slabs), each with
// its triangles prepared for the proximity test.
void clusterBounds(const TriangleMesh& mesh, std::vector<uint32_t>& triangles, size_t begin, size_t end, int depth,
                   std::vector<Bounds3>& out, std::vector<BoxedTriangles>& outTriangles) {
    auto centroid = [&](uint32_t t) {
        const auto& tri = mesh.triangles[t];
        return (mesh.positions[tri[0]] + mesh.positions[tri[1]] + mesh.positions[tri[2]]) / 3.0;
    };
    if (end - begin <= 12 || depth == 5) {
        Bounds3 b;
        BoxedTriangles boxed;
        double area = 0;
        for (size_t k = begin; k < end; ++k) {
            const auto& tri = mesh.triangles[triangles[k]];
            const Vec3 &p0 = mesh.positions[tri[0]], &p1 = mesh.positions[tri[1]], &p2 = mesh.positions[tri[2]];
            b.extend(p0), b.extend(p1), b.extend(p2);
            area += 0.5 * length(cross(p1 - p0, p2 - p0));
            if (end - begin <= kMostTrianglesTested) boxed.triangles.emplace_back(p0, p1, p2);
        }
        const Vec3 size = b.size();
        boxed.coversBox = area >= 0.9 * 2 * (size.x * size.y + size.y * size.z + size.z * size.x);
        out.push_back(b);
        outTriangles.push_back(std::move(boxed));
        return;
    }
    Bounds3 c;
    for (size_t k = begin; k < end; ++k) c.extend(centroid(triangles[k]));
    const Vec3 size = c.size();
    const int axis = size.x >= size.y && size.x >= size.z ? 0 : (size.y >= size.z ? 1 : 2);
    const size_t mid = (begin + end) / 2;
    std::nth_element(triangles.begin() + long(begin), triangles.begin() + long(mid), triangles.begin() + long(end),
                     [&](uint32_t a, uint32_t b) { return centroid(a)[axis] < centroid(b)[axis]; });
    clusterBounds(mesh, triangles, begin, mid, depth + 1, out, outTriangles);
    clusterBounds(mesh, triangles, mid, end, depth + 1, out, outTriangles);
}

// An entity's mesh in clusters: first its parts (triangles joined by shared corners,
// such as a preset's boxes), whose boxes are tight where a median split would mix a desk
// top with its side panels; a part of more than a dozen triangles, or a mesh of too many
// parts, is split by clusterBounds.
void clusterParts(const TriangleMesh& mesh, std::vector<Bounds3>& out, std::vector<BoxedTriangles>& outTriangles) {
    constexpr size_t kMostParts = 32;
    const size_t n = mesh.triangles.size();
    std::vector<uint32_t> parent(n);
    for (size_t t = 0; t < n; ++t) parent[t] = uint32_t(t);
    auto root = [&](uint32_t t) {
        while (parent[t] != t) t = parent[t] = parent[parent[t]];
        return t;
    };
    std::map<std::array<double, 3>, uint32_t> firstAt;  // a corner's position: the first triangle there
    for (size_t t = 0; t < n; ++t)
        for (uint32_t v : mesh.triangles[t]) {
            const Vec3& p = mesh.positions[v];
            const auto [at, fresh] = firstAt.try_emplace({p.x, p.y, p.z}, uint32_t(t));
            if (!fresh) parent[root(uint32_t(t))] = root(at->second);
        }
    std::map<uint32_t, std::vector<uint32_t>> parts;
    for (size_t t = 0; t < n; ++t) parts[root(uint32_t(t))].push_back(uint32_t(t));
    if (parts.size() > kMostParts) {
        std::vector<uint32_t> all(n);
        for (size_t t = 0; t < n; ++t) all[t] = uint32_t(t);
        clusterBounds(mesh, all, 0, n, 0, out, outTriangles);
        return;
    }
    for (auto& [first, triangles] : parts) clusterBounds(mesh, triangles, 0, triangles.size(), 2, out, outTriangles);
}

bool sameTransform(const Transform& a, const Transform& b) {
    return a.m == b.m && a.t.x == b.t.x && a.t.y == b.t.y && a.t.z == b.t.z;
}

constexpr double kMargin = 1e-3, kRelativeMargin = 1e-6;

}  // namespace

Move EntityClusters::moveBetween(const Scene& scene, const std::vector<Transform>& before,
                                 const std::vector<Transform>& after) const {
    Move move;
    move.entityMoved.assign(after.size(), 0);
    if (before.size() != after.size()) return move;
    for (size_t i = 0; i < after.size(); ++i) {
        if (sameTransform(before[i], after[i])) continue;
        move.entityMoved[i] = 1;
        for (const Transform* world : {&before[i], &after[i]}) {
            if (boxes_[i].empty()) continue;
            PlacedBoxes b(*world, boxes_[i], kMargin, kRelativeMargin, &triangles_[i]);
            move.bounds.extend(b.worldBounds());
            move.boxes.push_back(std::move(b));
        }
        if (!scene.entities[i].emitters.empty()) move.emittersMoved = true;
    }
    return move;
}

EntityClusters::EntityClusters(const Scene& scene) : boxes_(scene.entities.size()), triangles_(scene.entities.size()) {
    for (size_t i = 0; i < scene.entities.size(); ++i) {
        const Entity& e = scene.entities[i];
        if (e.hasGeometry()) clusterParts(e.mesh, boxes_[i], triangles_[i]);
        for (int em : e.emitters) {
            const EmitterShape& shape = *scene.emitters[size_t(em)].shape;
            const double r = shape.reach();
            boxes_[i].push_back(Bounds3(shape.center() - Vec3(r, r, r), shape.center() + Vec3(r, r, r)));
            triangles_[i].emplace_back();  // a luminaire: its box decides
        }
    }
}

}  // namespace luxplan
