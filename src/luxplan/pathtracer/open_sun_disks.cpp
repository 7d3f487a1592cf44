#include <luxplan/pathtracer/open_sun_disks.h>

#include <algorithm>
#include <cmath>

#include <luxplan/daylight/preetham.h>

namespace luxplan {

OpenSunDisks::OpenSunDisks(const DaylightEnvironment* daylight, const SunPatches& shell) : daylight_(daylight) {
    if (!daylight || !daylight->hasSun() || !shell.opaqueShell() || shell.shell().empty()) return;
    if (shell.entrances().size() > kMaxOpenings) return;
    shell_ = shell.shell();
    const std::vector<Entrance>& openings = shell.entrances();
    const std::vector<SunDisk>& disks = daylight->sunDisks();
    cumulative_.assign(disks.size() + 1, 0.0);
    for (size_t k = 0; k < disks.size(); ++k) cumulative_[k + 1] = cumulative_[k] + daylight->sunDiskProbability(k);
    // Consecutive disks (the sun's steps through the period) lie side by side in the sky.
    const size_t count = std::min(disks.size(), kMaxGroups);
    groupOf_.resize(disks.size());
    for (size_t g = 0; g < count; ++g) {
        Group group;
        group.first = disks.size() * g / count, group.last = disks.size() * (g + 1) / count;
        Vec3 sum;
        for (size_t k = group.first; k < group.last; ++k) {
            sum += disks[k].direction;
            group.probability += daylight->sunDiskProbability(k);
            groupOf_[k] = uint8_t(g);
        }
        // A lone disk's cone is the one the path tracer tested before (its own axis, its
        // radius with a hair to spare); a group's holds every disk's (acos, rounded up).
        double spread = 0;
        if (group.last - group.first == 1) {
            group.axis = disks[group.first].direction;
        } else {
            group.axis = normalize(sum);
            for (size_t k = group.first; k < group.last; ++k)
                spread = std::max(spread, std::acos(std::clamp(dot(group.axis, disks[k].direction), -1.0, 1.0)) + 1e-7);
        }
        group.halfAngle = (spread + kSunHalfAngle) * (1 + 1e-6) + 1e-9;
        groups_.push_back(group);
    }
    allGroups_ = groups_.size() == 32 ? ~uint32_t(0) : (uint32_t(1) << groups_.size()) - 1;
    std::vector<Entrance> facing;  // the openings some group's cone may pass through
    for (const Entrance& o : openings) {
        Terms t{};
        for (size_t g = 0; g < groups_.size(); ++g) {
            const Group& group = groups_[g];
            const double delta = group.halfAngle;  // |w - axis| <= delta: a chord is shorter than its arc
            const double nc = dot(o.outward, group.axis);
            const double least = nc - delta;  // n . w for every w in the cone
            if (nc + delta <= 0) {
                t.away |= uint32_t(1) << g;
            } else if (!(least > 1e-3)) {
                t.unsure |= uint32_t(1) << g;
            } else {
                // shadesCone's sums with the point's parts left out: where the axis from
                // q meets the plane (depth / nc along it), the cone's spread there,
                // (depth delta (1 + 1 / nc) + offset (least + 1)) / least, with a millionth
                // more, and 1e-7 (1 + |hit|) for rounding, |hit| <= |q| + depth / nc |axis|.
                const double overNc = 1 / nc;
                t.alongU[g] = dot(group.axis, o.unitU) * overNc;
                t.alongV[g] = dot(group.axis, o.unitV) * overNc;
                const double reach = (std::abs(group.axis.x) + std::abs(group.axis.y) + std::abs(group.axis.z)) * overNc;
                t.marginPerDepth[g] = delta * (1 + overNc) / least * (1 + 1e-6) + 1e-7 * reach;
                t.marginPerOffset[g] = (least + 1) / least * (1 + 1e-6);
                t.leastU = std::min(t.leastU, t.alongU[g]), t.mostU = std::max(t.mostU, t.alongU[g]);
                t.leastV = std::min(t.leastV, t.alongV[g]), t.mostV = std::max(t.mostV, t.alongV[g]);
                t.widestPerDepth = std::max(t.widestPerDepth, t.marginPerDepth[g]);
                t.widestPerOffset = std::max(t.widestPerOffset, t.marginPerOffset[g]);
            }
        }
        // An opening that faces away from every disk (the north windows, at noon) lets no
        // group through: it is left out of every point's tests.
        if (t.away == allGroups_) continue;
        facing.push_back(o);
        terms_.push_back(t);
    }
    openings_ = std::move(facing);
}

void OpenSunDisks::place(Origin& o, const Vec3& q, double within) const {
    const Bounds3& box = shell_;
    o.within = within;
    o.inside = true;
    for (int i = 0; i < 3; ++i)  // every point within `within` of q strictly inside the box
        if (!(q[i] - within > box.lo[i] && q[i] + within < box.hi[i])) o.inside = false;
    if (!o.inside) return;
    o.size = std::abs(q.x) + std::abs(q.y) + std::abs(q.z);
    const std::vector<Entrance>& openings = openings_;
    for (size_t i = 0; i < openings.size(); ++i) {
        const Entrance& e = openings[i];
        const Vec3 fromCorner = q - e.target.rect().corner;
        o.depth[i] = -dot(e.outward, fromCorner);  // q's distance to the opening's plane
        o.u[i] = dot(fromCorner, e.unitU);
        o.v[i] = dot(fromCorner, e.unitV);
    }
}

uint32_t OpenSunDisks::openFrom(const Origin& o) const {
    if (!o.inside) return allGroups_;
    const size_t n = groups_.size();
    uint32_t open = 0;
    for (size_t i = 0; i < openings_.size(); ++i) {
        const Terms& t = terms_[i];
        open |= t.unsure;
        const double depth = o.depth[i];
        if (!(depth > o.within)) {  // too near the opening's plane to bound
            open |= allGroups_ & ~t.away;
            continue;
        }
        // Where each cone's axis meets the plane, in the opening's frame, and how far the
        // cone's rays from any start within `within` meet it from there
        // (SunPatches::shadesCone): first for all of them at once.
        const double lengthU = openings_[i].lengthU, lengthV = openings_[i].lengthV;
        const double rounding = 1e-7 * (1 + o.size), u = o.u[i], v = o.v[i];
        const double widest = depth * t.widestPerDepth + o.within * t.widestPerOffset + rounding;
        if (u + depth * t.mostU < -widest || u + depth * t.leastU > lengthU + widest || v + depth * t.mostV < -widest ||
            v + depth * t.leastV > lengthV + widest)
            continue;  // every axis passes it wide
        uint32_t meets = 0;
        for (size_t g = 0; g < n; ++g) {
            const double a = u + depth * t.alongU[g], b = v + depth * t.alongV[g];
            const double margin = depth * t.marginPerDepth[g] + o.within * t.marginPerOffset[g] + rounding;
            // Unless it surely misses (a NaN meets it).
            const bool misses = (a < -margin) | (a > lengthU + margin) | (b < -margin) | (b > lengthV + margin);
            meets |= uint32_t(!misses) << g;
        }
        open |= meets & ~(t.away | t.unsure);
    }
    return open;
}

OpenSunDisks::Open OpenSunDisks::at(const Vec3& p, const Vec3* ng, double epsilon) const {
    if (!active()) return {};
    // Three origins at most: p itself (`epsilon` to spare), and p offset to either side.
    uint32_t from[3];
    bool asked[3] = {false, false, false};
    uint32_t groups = 0;
    for (size_t g = 0; g < groups_.size(); ++g) {
        const Group& group = groups_[g];
        int which = 0;
        if (ng) {
            const double c = dot(group.axis, *ng);
            if (std::abs(c) > group.halfAngle) which = c >= 0 ? 1 : 2;  // the cone on one side: spawn()'s origin
        }
        if (!asked[which]) {
            asked[which] = true;
            Origin origin;
            if (which == 0) place(origin, p, epsilon);
            else place(origin, p + *ng * (which == 1 ? epsilon : -epsilon), 0);
            from[which] = openFrom(origin);
        }
        groups |= from[which] & (uint32_t(1) << g);
    }
    Open open;
    if (groups == allGroups_) return open;
    open.all = false;
    open.groups = groups;
    open.share = 0;
    for (size_t g = 0; g < groups_.size(); ++g)
        if (groups >> g & 1) open.share += groups_[g].probability;
    return open;
}

size_t OpenSunDisks::choose(const Open& open, double u) const {
    if (open.all) return daylight_ ? daylight_->sunDiskOf(u) : kNone;
    if (open.groups == 0 || !(open.share > 0)) return kNone;
    const double target = u * open.share;
    double before = 0;  // the open groups' probability before the chosen one
    size_t chosen = kNone;
    for (size_t g = 0; g < groups_.size(); ++g) {
        if (!(open.groups >> g & 1) || !(groups_[g].probability > 0)) continue;
        if (chosen != kNone) before += groups_[chosen].probability;
        chosen = g;  // the last open group, should rounding carry the target past them all
        if (target < before + groups_[g].probability) break;
    }
    if (chosen == kNone) return kNone;
    const Group& group = groups_[chosen];
    if (group.last - group.first == 1) return group.first;
    // Within the group as the period's own choice would: its disks by their cumulative
    // probabilities (a disk of probability 0 is never chosen).
    const double at = cumulative_[group.first] + std::clamp(target - before, 0.0, group.probability);
    const auto begin = cumulative_.begin() + std::ptrdiff_t(group.first) + 1, end = cumulative_.begin() + std::ptrdiff_t(group.last) + 1;
    const size_t k = size_t(std::upper_bound(begin, end, at) - cumulative_.begin()) - 1;
    return std::min(k, group.last - 1);
}

}  // namespace luxplan
