// The sun disks a vertex's sun sample may come from. A sun sample chooses one of the
// period's disks (a morning at half-hourly steps has seven) and a direction in it; in a
// room, from most points most disks lie behind a wall. In the morning office 2.5% of the
// sun samples at surfaces that face the sun got out, and a point of a sunlit patch, lit
// by one or two of the period's suns, read its sunlight as a rare sample worth several
// times its mean: the largest part of the search's noise (docs/performance.md, "Which
// light the noise comes from").
//
// Here the disks are grouped (each disk alone when there are at most kMaxGroups), each
// group's cone is tested against the room's shell once per vertex (the test of
// SunPatches::shadesCone, its per-opening terms computed once), and the disk is chosen
// among the groups the shell may let through, in proportion to the disks' own
// probabilities. The density of a sun direction that can get out is then the period's
// (DaylightEnvironment::sunPdf) over the open groups' share of it. Unbiased: a group
// left out is one whose every direction the shell blocks from that vertex, whose light
// is exactly 0; every direction that can get out keeps a density, and the MIS weights of
// the paths that reach the sun another way read the same one (path_tracer.cpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <luxplan/daylight/environment.h>
#include <luxplan/pathtracer/sun_patches.h>

namespace luxplan {

class OpenSunDisks {
public:
    static constexpr size_t kMaxGroups = 32;
    // A room with more openings that let the sun through keeps the period's own choice.
    static constexpr size_t kMaxOpenings = 16;
    static constexpr size_t kNone = size_t(-1);

    // What the shell lets through from one vertex.
    struct Open {
        uint32_t groups = 0;  // bit g: group g may get through (unset when `all`)
        double share = 1;     // the open groups' probability; exactly 1 when `all`
        bool all = true;      // no group is blocked: the period's own choice
    };

    OpenSunDisks() = default;
    // Inactive (every disk open from everywhere) without a sun, a room or an opaque
    // shell, or with more than kMaxOpenings openings.
    OpenSunDisks(const DaylightEnvironment* daylight, const SunPatches& shell);
    bool active() const { return !groups_.empty(); }

    // The groups a shadow ray from the vertex at p may leave the room through: at a
    // surface of unit normal ng (on the side the path is on), from p offset by `epsilon`
    // along ng towards the group, as the ray leaves (where the group's cone lies on one
    // side of the surface), else from anywhere within `epsilon` of p; at a sensor (ng
    // null) from within `epsilon` of p.
    Open at(const Vec3& p, const Vec3* ng, double epsilon) const;
    // The disk u chooses among the open groups' disks in proportion to their
    // probabilities: DaylightEnvironment::sunDiskOf(u) when all are open, kNone when none
    // is (or without a daylight).
    size_t choose(const Open& open, double u) const;
    // Whether the disk shares its group with others: at() then did not test its own cone.
    bool grouped(size_t disk) const {
        return active() && groups_[groupOf_[disk]].last - groups_[groupOf_[disk]].first > 1;
    }
    // The groups, each a cone round its disks (its axis and half-angle, conservative).
    size_t groupCount() const { return groups_.size(); }
    size_t groupOf(size_t disk) const { return groupOf_[disk]; }
    Vec3 groupAxis(size_t g) const { return groups_[g].axis; }
    double groupHalfAngle(size_t g) const { return groups_[g].halfAngle; }

private:
    using Entrance = SunPatches::Entrance;
    struct Group {
        size_t first = 0, last = 0;  // disks [first, last)
        double probability = 0;
        Vec3 axis;
        double halfAngle = 0;
    };
    // SunPatches::shadesCone's terms that do not depend on the point, for one opening,
    // each an array over the groups (laid out so that one loop tests every group).
    struct Terms {
        uint32_t away = 0, unsure = 0;  // per group: the cone never meets the opening's plane / cannot be bounded
        // Where the axis from q meets the plane, per unit depth (q's distance to it) in
        // the opening's frame, and the margin the cone's spread and rounding need there,
        // per unit depth and per unit of the start's freedom.
        double alongU[kMaxGroups], alongV[kMaxGroups], marginPerDepth[kMaxGroups], marginPerOffset[kMaxGroups];
        // Their bounds over the groups that are tested: a point whose every axis passes
        // the opening by more than the widest margin tests none.
        double leastU = kInf, mostU = -kInf, leastV = kInf, mostV = -kInf, widestPerDepth = 0, widestPerOffset = 0;
    };
    // The point's terms for each opening, from one origin.
    struct Origin {
        bool inside = false;  // strictly inside the shell, `within` to spare
        double within = 0, size = 0;
        double depth[kMaxOpenings], u[kMaxOpenings], v[kMaxOpenings];
    };
    void place(Origin& o, const Vec3& q, double within) const;
    // The groups whose cones the shell may let through from the origin (a bit each).
    uint32_t openFrom(const Origin& o) const;

    const DaylightEnvironment* daylight_ = nullptr;
    std::vector<Entrance> openings_;
    Bounds3 shell_;
    std::vector<Group> groups_;
    std::vector<uint8_t> groupOf_;  // per disk
    std::vector<double> cumulative_;  // per disk and one more: the disks' probabilities summed
    std::vector<Terms> terms_;  // per opening
    uint32_t allGroups_ = 0;
};

}  // namespace luxplan
