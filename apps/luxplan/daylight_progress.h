// The daylight's bake with progress on stderr: a period of many time steps (a year at
// one-minute steps) takes a minute or more before anything else happens.
#pragma once

#include <luxplan/daylight/daylight.h>

namespace luxplan::cli {

// buildDaylight(), saying every two seconds, once it has taken that long, how many of the
// time steps are baked and the time left, and at the end how long it took. Quiet: silent.
DaylightEnvironment bakeDaylight(const DaylightParams& params, const Site& site, bool quiet = false);

}  // namespace luxplan::cli
