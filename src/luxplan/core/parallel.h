// The one parallel loop of luxplan. It runs on TBB's default arena, whose size main()
// sets once from --threads (tbb::global_control), so no caller takes a thread count.
#pragma once

#include <cstddef>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace luxplan {

// Calls body(i) for every i in [0, count), in parallel with grain 1 (the indices are
// whole points, pixel rows or map rows, each costly enough to be a task). Results are
// deterministic, whatever the thread count, when body(i) writes only its own slot i.
template <class Body>
void parallelFor(size_t count, const Body& body) {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, count, 1), [&](const tbb::blocked_range<size_t>& range) {
        for (size_t i = range.begin(); i != range.end(); ++i) body(i);
    });
}

}  // namespace luxplan
