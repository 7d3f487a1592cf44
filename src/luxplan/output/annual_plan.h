// The annual pictures: the plan of each planar sampler point's share of hours in its
// target band over the series (Ladybug's annual daylight plan), and a temporal map per
// sampler (temporal_map.h). docs/outputs.md, "Annual pictures".
#pragma once

#include <filesystem>
#include <vector>

#include <luxplan/annual/annual_series.h>
#include <luxplan/output/plan.h>
#include <luxplan/scene/layout.h>

namespace luxplan {

// The cells of the annual plan: each point of each planar sampler of the scene that the
// series names (by LightSamplerSpec::name) as the quad of its grid cell, coloured by the
// share of its hours in range, 0-100 % on a linear scale; covered points hatched.
PlanCells annualPlanCells(const Scene& scene, const Layout& layout, const AnnualSeries& series);

// The plan (renderPlan) with those cells, titled with the number of hours.
Image renderAnnualPlan(const Scene& scene, const Layout& layout, const AnnualSeries& series, const PlanOptions& options = {});

// Writes into `folder` (created if missing) annual_plan.png when the series has a
// planar sampler the scene holds, and temporal_map_<sampler>.png per sampler (the name
// with characters other than letters, digits, '-', '_' and '.' as '_'), each file
// atomically; returns the paths written in that order. Throws IoError when a file
// cannot be written.
std::vector<std::filesystem::path> writeAnnualPictures(const std::filesystem::path& folder, const Scene& scene,
                                                       const Layout& layout, const AnnualSeries& series);

}  // namespace luxplan
