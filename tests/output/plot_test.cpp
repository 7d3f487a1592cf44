// The convergence plot draws both cost lines, skips infeasible points and survives
// an empty trace.
#include <gtest/gtest.h>

#include <luxplan/output/plot.h>
#include "support/pixels.h"

namespace luxplan {
namespace {

bool isBest(Rgb p) { return p == Rgb{30, 90, 200}; }
bool isCurrent(Rgb p) { return p == Rgb{150, 150, 150}; }

using test::countPixels;

std::vector<TracePoint> syntheticTrace(double scale) {
    std::vector<TracePoint> trace;
    double best = kInf;
    for (int i = 0; i <= 1000; i += 10) {
        TracePoint p;
        p.iteration = i;
        p.feasible = i >= 50;  // the start is infeasible
        p.current = p.feasible ? scale * (1 + std::sin(i * 0.05)) * std::exp(-i / 200.0) + 0.01 : 5;
        if (p.feasible) best = std::min(best, p.current);
        p.best = best;
        trace.push_back(p);
    }
    return trace;
}

TEST(Plot, DrawsCurrentAndBestCosts) {
    PlotOptions options;
    options.width = 600, options.height = 300;
    Image image = plotConvergence(syntheticTrace(1), options);
    EXPECT_EQ(image.width(), 600);
    EXPECT_EQ(image.height(), 300);
    EXPECT_GT(countPixels(image, isBest), 300);
    EXPECT_GT(countPixels(image, isCurrent), 300);
    // Nothing drawn left of the first feasible point (x = 70 + 50/1000 * 510 = 95.5),
    // apart from the key and the axes.
    for (int y = 60; y < 250; ++y)
        for (int x = 72; x < 94; ++x) EXPECT_FALSE(isBest(image.at(x, y)) || isCurrent(image.at(x, y))) << x << " " << y;
}

TEST(Plot, LogAxisWhenCostsSpanDecades) {
    PlotOptions log, linear;
    log.logY = true;
    linear.logY = false;
    // Costs from 0.01 to 2 (more than two decades): the automatic axis is logarithmic.
    auto wide = syntheticTrace(1);
    EXPECT_EQ(plotConvergence(wide).pixels(), plotConvergence(wide, log).pixels());
    EXPECT_NE(plotConvergence(wide).pixels(), plotConvergence(wide, linear).pixels());
    // Costs within one decade: linear.
    auto narrow = wide;
    for (TracePoint& p : narrow) p.current += 1, p.best += 1;
    EXPECT_EQ(plotConvergence(narrow).pixels(), plotConvergence(narrow, linear).pixels());
}

TEST(Plot, EmptyAndInfeasibleTracesStillDraw) {
    Image empty = plotConvergence({});
    EXPECT_EQ(countPixels(empty, isBest), 0);
    std::vector<TracePoint> infeasible(5);
    for (int i = 0; i < 5; ++i) infeasible[size_t(i)] = {i * 10, 3.0, kInf, false};
    Image none = plotConvergence(infeasible);
    EXPECT_EQ(countPixels(none, isBest), 0);
    // The "no data" note, in the current cost's grey at the plot box's centre (the box
    // from x 70 to width - 20, y 40 under the title to height - 50), and no other grey:
    // the same pixels as the note drawn alone.
    Image note(none.width(), none.height(), kWhite);
    note.drawText((70 + none.width() - 20) / 2.0, (40 + none.height() - 50) / 2.0, "no data", Rgb{150, 150, 150}, 2,
                  TextAlign::Center);
    ASSERT_GT(countPixels(note, isCurrent), 50);
    EXPECT_EQ(countPixels(none, isCurrent), countPixels(note, isCurrent));
    for (int y = 0; y < note.height(); ++y)
        for (int x = 0; x < note.width(); ++x) {
            if (isCurrent(note.at(x, y))) {
                EXPECT_TRUE(isCurrent(none.at(x, y))) << x << " " << y;
            }
        }
}

}  // namespace
}  // namespace luxplan
