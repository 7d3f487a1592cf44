#include "daylight_progress.h"

#include <chrono>
#include <cstdio>

#include <luxplan/optimizer/progress_line.h>

namespace luxplan::cli {

DaylightEnvironment bakeDaylight(const DaylightParams& params, const Site& site, bool quiet) {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    auto last = start;
    bool said = false;
    DaylightBakeOptions options;
    if (!quiet)
        options.onStep = [&](int baked, int total) {
            const auto now = Clock::now();
            if (baked >= total || now - last < std::chrono::seconds(2)) return;
            last = now;
            said = true;
            const double elapsed = std::chrono::duration<double>(now - start).count();
            std::fprintf(stderr, "  daylight: the sky of %d of %d time steps baked (%s left)\n", baked, total,
                         durationText(elapsed * (total - baked) / baked).c_str());
        };
    DaylightEnvironment environment = buildDaylight(params, site, options);
    if (said)
        std::fprintf(stderr, "  daylight: baked in %s\n",
                     durationText(std::chrono::duration<double>(Clock::now() - start).count()).c_str());
    return environment;
}

}  // namespace luxplan::cli
