#include <luxplan/optimizer/candidates.h>

#include <algorithm>
#include <cmath>

#include <luxplan/scene/region.h>

namespace luxplan {

bool sameCandidate(const Scene& scene, const Layout& a, const Layout& b, const CandidateSeparation& separation) {
    for (size_t i = 0; i < scene.entities.size(); ++i) {
        if (!scene.entities[i].movable()) continue;
        const Placement &p = a.placements[i], &q = b.placements[i];
        if (p.region != q.region) return false;
        const Vec3 d = p.position - q.position;
        if (std::hypot(d.x, d.y) > separation.metres) return false;
        double turn = std::fmod(std::abs(p.rotationDeg - q.rotationDeg), 360.0);
        if (std::min(turn, 360 - turn) > separation.degrees) return false;
    }
    return true;
}

Candidates::Candidates(const Scene& scene, int capacity, CandidateSeparation separation)
    : scene_(&scene), capacity_(size_t(std::max(1, capacity))), separation_(separation) {}

void Candidates::offer(const Layout& layout, const Evaluation& evaluation, int iteration) {
    if (evaluation.rejected) return;
    auto byCost = [](const Candidate& c, double cost) { return c.search.cost <= cost; };
    for (auto it = kept_.begin(); it != kept_.end(); ++it) {
        // One kept by keep() stays whatever comes: its measurement is what it is kept for.
        if (it->independent || !sameCandidate(*scene_, it->layout, layout, separation_)) continue;
        if (evaluation.cost >= it->search.cost) return;
        kept_.erase(it);
        break;
    }
    // The capacity bounds the candidates offered; those kept by keep() come on top.
    auto offered = [](const Candidate& c) { return !c.independent; };
    if (size_t(std::count_if(kept_.begin(), kept_.end(), offered)) >= capacity_) {
        auto worst = std::find_if(kept_.rbegin(), kept_.rend(), offered);
        if (evaluation.cost >= worst->search.cost) return;
        kept_.erase(std::next(worst).base());
    }
    // After every candidate of a lower or equal cost: ties keep the earlier first.
    auto at = std::partition_point(kept_.begin(), kept_.end(), [&](const Candidate& c) { return byCost(c, evaluation.cost); });
    kept_.insert(at, Candidate{layout, evaluation, std::nullopt, iteration});
}

void Candidates::keep(Candidate candidate) {
    for (auto it = kept_.begin(); it != kept_.end(); ++it)
        if (it->iteration == candidate.iteration) {
            kept_.erase(it);
            break;
        }
    const double cost = candidate.search.cost;
    auto at = std::partition_point(kept_.begin(), kept_.end(), [&](const Candidate& c) { return c.search.cost <= cost; });
    kept_.insert(at, std::move(candidate));
}

}  // namespace luxplan
