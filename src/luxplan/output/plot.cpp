// The convergence plot: axes, ticks and grid, the current cost where feasible and the
// best cost so far, on a linear or logarithmic y axis.
#include <luxplan/output/plot.h>


#include <luxplan/output/false_color.h>
#include <luxplan/core/format.h>

namespace luxplan {
namespace {

constexpr Rgb kGridColor{225, 225, 225};
constexpr Rgb kCurrentColor{150, 150, 150};
constexpr Rgb kBestColor{30, 90, 200};

// A round tick step (1, 2, 2.5 or 5 x 10^k) giving about `count` intervals over `range`.
double tickStep(double range, int count) { return niceCeil(range / std::max(1, count)); }

}  // namespace

Image plotConvergence(const std::vector<TracePoint>& trace, const PlotOptions& options) {
    const int width = std::max(200, options.width), height = std::max(150, options.height);
    Image image(width, height, kWhite);
    const int left = 70, right = 20, top = options.title.empty() ? 20 : 40, bottom = 50;
    const double x0 = left, x1 = width - right, y0 = top, y1 = height - bottom;  // pixel box, y1 at the bottom
    if (!options.title.empty()) image.drawText(width / 2.0, 12, options.title, kBlack, 2, TextAlign::Center);

    // Ranges.
    double itMin = kInf, itMax = -kInf, costMax = 0, positiveMin = kInf;
    for (const TracePoint& p : trace) {
        itMin = std::min(itMin, double(p.iteration));
        itMax = std::max(itMax, double(p.iteration));
        for (double c : {p.feasible ? p.current : kInf, p.best})
            if (std::isfinite(c)) {
                costMax = std::max(costMax, c);
                if (c > 0) positiveMin = std::min(positiveMin, c);
            }
    }
    const bool hasData = std::isfinite(itMin) && (costMax > 0 || std::isfinite(positiveMin));
    if (!std::isfinite(itMin)) itMin = 0, itMax = 1;
    if (itMax <= itMin) itMax = itMin + 1;
    const bool logY = options.logY.value_or(std::isfinite(positiveMin) && costMax / positiveMin > 100);

    double yLo = 0, yHi = niceCeil(costMax > 0 ? costMax : 1);
    if (logY) {
        double lo = std::isfinite(positiveMin) ? positiveMin : 1e-3, hi = costMax > 0 ? costMax : 1;
        yLo = std::floor(std::log10(lo));
        yHi = std::max(yLo + 1, std::ceil(std::log10(hi)));
    }
    auto px = [&](double it) { return x0 + (it - itMin) / (itMax - itMin) * (x1 - x0); };
    auto py = [&](double cost) {
        double t = logY ? (cost > 0 ? (std::log10(cost) - yLo) / (yHi - yLo) : 0.0) : cost / yHi;
        return y1 - std::clamp(t, 0.0, 1.0) * (y1 - y0);
    };

    // Grid and ticks.
    double xStep = tickStep(itMax - itMin, 6);
    for (double it = std::ceil(itMin / xStep) * xStep; it <= itMax + 1e-9; it += xStep) {
        double x = px(it);
        image.drawLine({x, y0}, {x, y1}, kGridColor, 1);
        image.drawLine({x, y1}, {x, y1 + 4}, kBlack, 1);
        image.drawText(x, y1 + 8, compactNumber(it), kBlack, 1, TextAlign::Center);
    }
    std::vector<double> yTicks;
    if (logY) {
        for (double e = yLo; e <= yHi + 1e-9; e += 1) yTicks.push_back(std::pow(10.0, e));
    } else {
        double step = tickStep(yHi, 5);
        for (double v = 0; v <= yHi * (1 + 1e-9); v += step) yTicks.push_back(v);
    }
    for (double v : yTicks) {
        double y = py(v);
        image.drawLine({x0, y}, {x1, y}, kGridColor, 1);
        image.drawLine({x0 - 4, y}, {x0, y}, kBlack, 1);
        image.drawText(x0 - 7, y - 3, compactNumber(v), kBlack, 1, TextAlign::Right);
    }
    image.drawLine({x0, y0}, {x0, y1}, kBlack, 1);
    image.drawLine({x0, y1}, {x1, y1}, kBlack, 1);
    image.drawText((x0 + x1) / 2, height - 16, "iteration", kBlack, 1, TextAlign::Center);
    image.drawText(8, y0 - 14 + (options.title.empty() ? 6 : 0), logY ? "cost (log)" : "cost", kBlack, 1);

    if (!hasData) {
        image.drawText((x0 + x1) / 2, (y0 + y1) / 2, "no data", kCurrentColor, 2, TextAlign::Center);
        return image;
    }

    // Current cost: a thin line broken at infeasible points.
    bool open = false;
    Vec2 last;
    for (const TracePoint& p : trace) {
        if (!p.feasible || !std::isfinite(p.current)) {
            open = false;
            continue;
        }
        Vec2 q{px(p.iteration), py(p.current)};
        if (open) image.drawLine(last, q, kCurrentColor, 1);
        else image.blendPixel(int(q.x), int(q.y), kCurrentColor);
        last = q, open = true;
    }
    // Best so far: a thick step line (it only changes when a better layout is found).
    open = false;
    for (const TracePoint& p : trace) {
        if (!std::isfinite(p.best)) continue;
        Vec2 q{px(p.iteration), py(p.best)};
        if (open) {
            image.drawLine(last, {q.x, last.y}, kBestColor, 2.5);
            image.drawLine({q.x, last.y}, q, kBestColor, 2.5);
        }
        last = q, open = true;
    }

    // Key.
    const double kx = x1 - 110, ky = y0 + 8;
    image.fillRect(kx - 6, ky - 6, x1 - 6, ky + 28, kWhite, 0.85);
    image.drawLine({kx, ky + 3}, {kx + 24, ky + 3}, kCurrentColor, 1);
    image.drawText(kx + 30, ky, "current", kBlack);
    image.drawLine({kx, ky + 17}, {kx + 24, ky + 17}, kBestColor, 2.5);
    image.drawText(kx + 30, ky + 14, "best", kBlack);
    return image;
}

}  // namespace luxplan
