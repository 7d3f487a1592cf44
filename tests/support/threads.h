// Runs a test's work on exactly N TBB threads, for the tests that check a result does not
// depend on the thread count (the library takes none; luxplan's main() sets it once).
#pragma once

#include <utility>

#include <tbb/task_arena.h>

namespace luxplan::test {

// fn() inside an arena of `threads` slots; returns what fn returns.
template <class Fn>
auto withThreads(int threads, Fn&& fn) {
    return tbb::task_arena(threads).execute(std::forward<Fn>(fn));
}

}  // namespace luxplan::test
