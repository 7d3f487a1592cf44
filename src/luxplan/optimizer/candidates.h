// The best few distinct layouts a run visited, by the search's own estimates: the
// candidates for its result. The lowest estimate over thousands of noisy ones is
// biased low (the winner's curse), so the run measures these again with random numbers
// the search never used and keeps the best of those measurements (Optimizer::run).
#pragma once

#include <optional>
#include <vector>

#include <luxplan/optimizer/evaluation.h>
#include <luxplan/scene/layout.h>

namespace luxplan {

struct Candidate {
    Layout layout;
    Evaluation search;                     // as the chain estimated it
    std::optional<Evaluation> independent; // measured with stream 1 (a confirmation, or the final selection)
    int iteration = 0;
};

// Two layouts are the same candidate when every movable entity stays in its region
// within `separation` metres and `separationDeg` degrees of the other's placement.
struct CandidateSeparation {
    double metres = 0.1;
    double degrees = 10;
};
bool sameCandidate(const Scene& scene, const Layout& a, const Layout& b, const CandidateSeparation& separation);

class Candidates {
public:
    Candidates(const Scene& scene, int capacity, CandidateSeparation separation);
    // A feasible layout the chain reached: kept if it beats the offered candidate it is
    // the same as, or, being new, the worst one (or there is room). Those kept by keep()
    // are never replaced.
    void offer(const Layout& layout, const Evaluation& evaluation, int iteration);
    // A candidate that must be kept whatever its rank (a measured confirmation: the run
    // may stop on it), beyond the capacity if need be; it takes the place of the one
    // from the same iteration, if any.
    void keep(Candidate candidate);
    // Best first by the search's estimate; ties keep the earlier.
    std::vector<Candidate>& all() { return kept_; }
    const std::vector<Candidate>& all() const { return kept_; }
    void clear() { kept_.clear(); }

private:
    const Scene* scene_;
    size_t capacity_;
    CandidateSeparation separation_;
    std::vector<Candidate> kept_;
};

}  // namespace luxplan
