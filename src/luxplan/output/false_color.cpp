// The false-colour scale: palette, linear/log mapping, automatic maximum and the
// legend bar with its tick labels.
#include <luxplan/output/false_color.h>

#include <luxplan/core/format.h>

namespace luxplan {
namespace {

struct Stop {
    double t;
    Rgb color;
};

// Hue order of Radiance's falsecolor: dark blue, blue, cyan, green, yellow, orange, red.
constexpr Stop kRamp[] = {
    {0.00, {30, 0, 90}},   {0.15, {40, 50, 210}},  {0.30, {0, 160, 230}}, {0.45, {40, 190, 90}},
    {0.60, {190, 220, 40}}, {0.72, {255, 205, 0}}, {0.86, {250, 115, 20}}, {1.00, {215, 20, 30}},
};

// autoFalseColor's maximum is at most this multiple of the median, so that sun patches
// covering more than (1 - percentile) of a room do not push the rest into the first colour.
constexpr double kMedianCap = 5;

}  // namespace

Rgb falseColorRamp(double t) {
    if (!(t > 0)) return kRamp[0].color;
    for (size_t i = 1; i < std::size(kRamp); ++i)
        if (t <= kRamp[i].t)
            return mix(kRamp[i - 1].color, kRamp[i].color, (t - kRamp[i - 1].t) / (kRamp[i].t - kRamp[i - 1].t));
    return kRamp[std::size(kRamp) - 1].color;
}

double FalseColor::minValue() const {
    return scale == ColorScale::Log ? maxValue * std::pow(10.0, -std::max(0.1, decades)) : 0.0;
}

double FalseColor::fraction(double v) const {
    if (!(v == v)) return 0;
    if (scale == ColorScale::Log) {
        double lo = minValue();
        if (v <= lo) return 0;
        return std::clamp(std::log10(v / lo) / std::max(0.1, decades), 0.0, 1.0);
    }
    return maxValue > 0 ? std::clamp(v / maxValue, 0.0, 1.0) : 0.0;
}

Rgb FalseColor::color(double v) const { return falseColorRamp(fraction(v)); }

double niceCeil(double x) {
    if (!(x > 0) || !std::isfinite(x)) return 1;
    double p = std::pow(10.0, std::floor(std::log10(x)));
    for (double m : {1.0, 2.0, 2.5, 5.0, 10.0})
        if (m * p >= x * (1 - 1e-12)) return m * p;
    return 10 * p;
}

FalseColor autoFalseColor(const std::vector<double>& values, ColorScale scale, double percentile) {
    std::vector<double> finite;
    for (double v : values)
        if (std::isfinite(v)) finite.push_back(v);
    FalseColor f;
    f.scale = scale;
    f.maxValue = 1;
    if (finite.empty()) return f;
    std::sort(finite.begin(), finite.end());
    size_t rank = size_t(std::ceil(std::clamp(percentile, 0.0, 1.0) * double(finite.size())));
    double q = finite[std::min(finite.size() - 1, rank > 0 ? rank - 1 : 0)];
    double median = finite[(finite.size() - 1) / 2];
    if (median > 0) q = std::min(q, kMedianCap * median);
    if (!(q > 0)) q = finite.back();
    if (q > 0) f.maxValue = niceCeil(q);
    return f;
}

FalseColor targetFalseColor(double targetMin, double targetMax) {
    FalseColor f;
    f.scale = ColorScale::Log;
    double bottom = 1, top = 1000;
    if (targetMin > 0 && std::isfinite(targetMin) && targetMax < 100 * targetMin) {
        bottom = targetMin / 10, top = 10 * targetMax;  // a band
        f.band = std::array<double, 2>{targetMin, targetMax};
    } else if (targetMin > 0 && std::isfinite(targetMin)) {
        bottom = targetMin / 10, top = 100 * targetMin;  // at least targetMin
        f.band = std::array<double, 2>{targetMin, top};
    } else if (targetMax > 0 && std::isfinite(targetMax)) {
        bottom = targetMax / 100, top = 10 * targetMax;  // at most targetMax
        f.band = std::array<double, 2>{bottom, targetMax};
    }
    f.maxValue = top;
    f.decades = std::log10(top / bottom);
    return f;
}

std::vector<double> legendTicks(const FalseColor& scale, int ticks) {
    std::vector<double> out;
    if (scale.scale == ColorScale::Log) {
        const double lo = scale.minValue(), hi = scale.maxValue;
        out.push_back(lo);
        for (double p = std::pow(10.0, std::floor(std::log10(lo))); p <= hi; p *= 10)
            for (double m : {1.0, 2.0, 5.0}) {
                double v = m * p;
                if (v > lo * 1.15 && v < hi / 1.15) out.push_back(v);
            }
        out.push_back(hi);
        return out;
    }
    ticks = std::max(1, ticks);
    for (int k = 0; k <= ticks; ++k) out.push_back(scale.maxValue * k / ticks);
    return out;
}

int drawLegend(Image& image, const FalseColor& scale, int x, int y, int width, int height, const std::string& unit,
               int ticks) {
    height = std::max(height, 2);
    image.drawText(x, y - 12, unit, kBlack, 1, TextAlign::Left);
    for (int r = 0; r < height; ++r)
        image.fillRect(x, y + r, x + width, y + r + 1, falseColorRamp(1 - (r + 0.5) / height));
    image.drawRect(x - 0.5, y - 0.5, x + width + 0.5, y + height + 0.5, kBlack, 1);

    int widest = 0;
    for (double v : legendTicks(scale, ticks)) {
        double py = y + (1 - scale.fraction(v)) * height;
        image.drawLine({double(x + width), py}, {double(x + width + 4), py}, kBlack, 1);
        std::string label = compactNumber(v);
        image.drawText(x + width + 7, py - 3, label, kBlack, 1, TextAlign::Left);
        widest = std::max(widest, textWidth(label));
    }
    if (scale.band) {
        // A bracket left of the bar from the band's top to its bottom, "target" beside it.
        double top = y + (1 - scale.fraction((*scale.band)[1])) * height;
        double bottom = y + (1 - scale.fraction((*scale.band)[0])) * height;
        double bx = x - 5;
        image.drawLine({bx, top}, {bx, bottom}, kBlack, 2);
        image.drawLine({bx, top}, {double(x), top}, kBlack, 2);
        image.drawLine({bx, bottom}, {double(x), bottom}, kBlack, 2);
        image.drawText(bx - 3, (top + bottom) / 2 - 3, "target", kBlack, 1, TextAlign::Right);
    }
    return width + 7 + widest;
}

}  // namespace luxplan
