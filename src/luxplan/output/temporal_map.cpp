// The temporal map: a grid of days x hours filled from the series, axes, legend.
#include <luxplan/output/temporal_map.h>

#include <algorithm>
#include <cmath>

#include <luxplan/output/label_font.h>

namespace luxplan {
namespace {

constexpr Rgb kTemporalAxisColor{60, 60, 60};
constexpr const char* kMonthNames[12] = {"Jan", "Feb", "Mar", "Apr", "May", "Jun",
                                         "Jul", "Aug", "Sep", "Oct", "Nov", "Dec"};

bool isLeapYear(int year) { return daysInMonth(year, 2) == 29; }

}  // namespace

int dayOfYear(const DateTime& t) {
    int day = t.day;
    for (int m = 1; m < t.month; ++m) day += daysInMonth(t.year, m);
    return day;
}

FalseColor temporalMapColors(const AnnualSampler& s) {
    if (s.targetMin > 0 || (std::isfinite(s.targetMax) && s.targetMax > 0)) return targetFalseColor(s.targetMin, s.targetMax);
    return autoFalseColor(s.values, ColorScale::Log);
}

Image renderTemporalMap(const AnnualSampler& sampler, const std::vector<DateTime>& hours, const TemporalMapOptions& options,
                        TemporalMapFrame* frameOut) {
    TemporalMapFrame f;
    f.dayWidth = std::max(1, options.dayWidth);
    f.hourHeight = std::max(1, options.hourHeight);
    // The calendar of the series' first leap year if it has one (a typical year is one
    // calendar; a longer series folds onto it by day of the year).
    int calendarYear = hours.empty() ? 2001 : hours.front().year;
    for (const DateTime& t : hours)
        if (isLeapYear(t.year)) {
            calendarYear = t.year;
            break;
        }
    f.days = isLeapYear(calendarYear) ? 366 : 365;
    const int titleHeight = 28, legendWidth = 150, bottom = 40;
    f.left = 50;
    f.top = titleHeight + 8;
    const int plotW = f.days * f.dayWidth, plotH = 24 * f.hourHeight;
    Image image(f.left + plotW + legendWidth, f.top + plotH + bottom, kWhite);

    const size_t measured = std::min(hours.size(), sampler.values.size());
    const std::string title = options.title.empty() ? sampler.name + ", " + std::to_string(measured) + " hours" : options.title;
    LabelFont(18).draw(image, f.left, 4, title, kBlack);

    // Every cell grey, then each measured hour in its colour.
    image.fillRect(f.left, f.top, f.left + plotW, f.top + plotH, kUnmeasuredColor);
    const FalseColor colors = options.colors ? *options.colors : temporalMapColors(sampler);
    for (size_t i = 0; i < measured; ++i) {
        const double v = sampler.values[i];
        if (!std::isfinite(v)) continue;
        const int day = std::min(dayOfYear(hours[i]), f.days);
        const int hour = std::clamp(hours[i].hour, 0, 23);
        const double x0 = f.left + (day - 1) * f.dayWidth, y0 = f.top + (23 - hour) * f.hourHeight;
        image.fillRect(x0, y0, x0 + f.dayWidth, y0 + f.hourHeight, colors.color(v));
    }
    image.drawRect(f.left - 0.5, f.top - 0.5, f.left + plotW + 0.5, f.top + plotH + 0.5, kTemporalAxisColor, 1);

    // Hours of the day on the left (0 at the bottom), months underneath.
    for (int h = 0; h <= 24; h += 6) {
        const double y = f.top + (24 - h) * f.hourHeight;
        image.drawLine({double(f.left - 5), y}, {double(f.left), y}, kTemporalAxisColor, 1);
        image.drawText(f.left - 8, y - 3, std::to_string(h) + ":00", kBlack, 1, TextAlign::Right);
    }
    const double axisY = f.top + plotH;
    int firstDay = 1;
    for (int m = 1; m <= 12; ++m) {
        const int length = daysInMonth(calendarYear, m);
        const double x = f.left + (firstDay - 1) * f.dayWidth;
        image.drawLine({x, axisY}, {x, axisY + 6}, kTemporalAxisColor, 1);
        image.drawText(x + length * f.dayWidth / 2.0, axisY + 9, kMonthNames[m - 1], kBlack, 1, TextAlign::Center);
        firstDay += length;
    }
    image.drawLine({double(f.left + plotW), axisY}, {double(f.left + plotW), axisY + 6}, kTemporalAxisColor, 1);
    image.drawText(f.left + plotW / 2.0, axisY + 22, "day of the year", kBlack, 1, TextAlign::Center);

    drawLegend(image, colors, f.left + plotW + 62, f.top, 16, plotH, options.unit);
    if (frameOut) *frameOut = f;
    return image;
}

}  // namespace luxplan
