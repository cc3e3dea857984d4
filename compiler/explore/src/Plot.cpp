#include "voxc/explore/Plot.h"

#include "Canvas.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <optional>

namespace voxc::explore {

namespace {

constexpr Rgb kWhite{255, 255, 255};
constexpr Rgb kInk{30, 30, 30};
constexpr Rgb kGridLine{225, 225, 225};
constexpr int kTextScale = 2;
constexpr int kPanelWidth = 440;
constexpr int kPanelHeight = 340;
constexpr int kTitleHeight = 44;
constexpr int kFooterHeight = 36;
constexpr int kPlotLeft = 100;  // from the panel's left edge: room for the value labels
constexpr int kPlotRight = 24;  // from the panel's right edge
constexpr int kPlotWidth = kPanelWidth - kPlotLeft - kPlotRight;
constexpr int kGlyphGap = 12;   // one character at kTextScale

struct Series {
    std::string name;
    Rgb color;
    bool fraction = false;                        // values in [0, 1]: the axis is fixed to [0, 1]
    std::vector<std::optional<MeanDeviation>> points; // one per swept value
    std::string missing;                          // shown instead when there are no points
};

// An axis from lo to hi with ticks every `step`, labelled with `decimals` digits (after dividing
// by `unit`, 1 or 1000 with a K suffix).
struct Axis {
    double lo = 0.0, hi = 1.0, step = 0.2;
    int decimals = 1;
    double unit = 1.0;

    std::vector<double> ticks() const {
        std::vector<double> result;
        for (double i = std::ceil(lo / step - 1e-9); i * step <= hi + step * 1e-9; i += 1.0) result.push_back(i * step);
        return result;
    }
    std::string label(double value) const {
        std::string text = fmt::format("{:.{}f}", value / unit, decimals);
        const bool zero = text.find_first_not_of("-0.") == std::string::npos;
        if (zero && text.front() == '-') text.erase(0, 1); // no "-0.0"
        return unit > 1.0 && !zero ? text + "K" : text;   // no "0K"
    }
};

// Ticks at 1, 2 or 5 times a power of ten, about `target` of them over [lo, hi].
Axis niceAxis(double lo, double hi, int target) {
    Axis axis;
    const double rough = (hi - lo) / target;
    const double power = std::pow(10.0, std::floor(std::log10(rough)));
    const double fraction = rough / power;
    axis.step = (fraction < 1.5 ? 1.0 : fraction < 3.5 ? 2.0 : fraction < 7.5 ? 5.0 : 10.0) * power;
    axis.lo = lo;
    axis.hi = hi;
    axis.unit = std::max(std::abs(lo), std::abs(hi)) >= 10000.0 ? 1000.0 : 1.0;
    axis.decimals = std::max(0, -int(std::floor(std::log10(axis.step / axis.unit) + 1e-9)));
    return axis;
}

struct Frame {
    int left, top, right, bottom; // the plot area in pixels
    Axis x, y;
    int px(double v) const { return left + int(std::lround((v - x.lo) / (x.hi - x.lo) * (right - left))); }
    int py(double v) const {
        const double clamped = std::clamp(v, y.lo, y.hi);
        return bottom - int(std::lround((clamped - y.lo) / (y.hi - y.lo) * (bottom - top)));
    }
};

Axis valueAxis(const Series& series) {
    if (series.fraction) return niceAxis(0.0, 1.0, 5);
    double top = 0.0;
    for (const auto& point : series.points)
        if (point) top = std::max(top, point->mean + point->stddev);
    if (top <= 0.0) return niceAxis(0.0, 1.0, 5);
    Axis axis = niceAxis(0.0, top, 5);
    axis.hi = std::ceil(top / axis.step) * axis.step; // end on a tick
    return axis;
}

void drawAxes(Image& image, const Frame& frame, std::string_view xName) {
    for (double tick : frame.y.ticks()) {
        const int y = frame.py(tick);
        drawLine(image, frame.left, y, frame.right, y, kGridLine);
        drawLine(image, frame.left - 6, y, frame.left, y, kInk);
        drawText(image, frame.left - 10, y - textHeight(kTextScale) / 2, frame.y.label(tick), kInk, kTextScale,
                 Align::Right);
    }
    for (double tick : frame.x.ticks()) {
        const int x = frame.px(tick);
        drawLine(image, x, frame.top, x, frame.bottom, kGridLine);
        drawLine(image, x, frame.bottom, x, frame.bottom + 6, kInk);
        drawText(image, x, frame.bottom + 12, frame.x.label(tick), kInk, kTextScale, Align::Center);
    }
    drawLine(image, frame.left, frame.top, frame.left, frame.bottom, kInk, 2);
    drawLine(image, frame.left, frame.bottom, frame.right, frame.bottom, kInk, 2);
    drawText(image, (frame.left + frame.right) / 2, frame.bottom + 40, xName, kInk, kTextScale, Align::Center);
}

void drawSeries(Image& image, const Frame& frame, const std::vector<double>& xs, const Series& series) {
    const Rgb band = blend(kWhite, series.color, 0.25);
    // The band, column by column, interpolating the bounds between neighbouring values.
    for (size_t i = 0; i + 1 < xs.size(); ++i) {
        if (!series.points[i] || !series.points[i + 1]) continue;
        const MeanDeviation& a = *series.points[i];
        const MeanDeviation& b = *series.points[i + 1];
        const int x0 = frame.px(xs[i]), x1 = frame.px(xs[i + 1]);
        for (int x = x0; x <= x1; ++x) {
            const double t = x1 == x0 ? 0.0 : double(x - x0) / double(x1 - x0);
            const double mean = a.mean + (b.mean - a.mean) * t;
            const double deviation = a.stddev + (b.stddev - a.stddev) * t;
            fillRect(image, x, frame.py(mean + deviation), x, frame.py(mean - deviation), band);
        }
    }
    for (size_t i = 0; i < xs.size(); ++i) {
        if (!series.points[i]) continue;
        const MeanDeviation& p = *series.points[i];
        const int x = frame.px(xs[i]);
        // Whiskers as well, so a single value or a lone point still shows its spread.
        drawLine(image, x, frame.py(p.mean + p.stddev), x, frame.py(p.mean - p.stddev), series.color);
        drawLine(image, x - 4, frame.py(p.mean + p.stddev), x + 4, frame.py(p.mean + p.stddev), series.color);
        drawLine(image, x - 4, frame.py(p.mean - p.stddev), x + 4, frame.py(p.mean - p.stddev), series.color);
        if (i + 1 < xs.size() && series.points[i + 1])
            drawLine(image, x, frame.py(p.mean), frame.px(xs[i + 1]), frame.py(series.points[i + 1]->mean),
                     series.color, 3);
    }
    for (size_t i = 0; i < xs.size(); ++i) {
        if (!series.points[i]) continue;
        const int x = frame.px(xs[i]), y = frame.py(series.points[i]->mean);
        fillRect(image, x - 4, y - 4, x + 4, y + 4, series.color);
        fillRect(image, x - 2, y - 2, x + 2, y + 2, kWhite);
    }
}

void drawPanel(Image& image, int originX, int originY, const Axis& xAxis, const std::vector<double>& xs,
               const Series& series, std::string_view xName) {
    const Frame frame{originX + kPlotLeft, originY + 40, originX + kPanelWidth - kPlotRight, originY + kPanelHeight - 64,
                      xAxis, valueAxis(series)};
    drawText(image, (frame.left + frame.right) / 2, originY + 12, series.name, kInk, kTextScale, Align::Center);
    drawAxes(image, frame, xName);
    const bool any = std::any_of(series.points.begin(), series.points.end(), [](const auto& p) { return p.has_value(); });
    if (any)
        drawSeries(image, frame, xs, series);
    else
        drawText(image, (frame.left + frame.right) / 2, (frame.top + frame.bottom) / 2, series.missing, kInk,
                 kTextScale, Align::Center);
}

// As many ticks as fit: labels at least a few characters apart.
Axis parameterAxis(const std::vector<double>& xs) {
    double lo = xs.front(), hi = xs.back();
    if (hi <= lo) {
        const double pad = std::max(std::abs(lo) * 0.1, 0.5);
        lo -= pad;
        hi += pad;
    }
    const double margin = (hi - lo) * 0.05; // keep the end markers off the frame
    Axis axis;
    for (int target = 6; target >= 1; --target) {
        axis = niceAxis(lo, hi, target);
        axis.lo = lo - margin;
        axis.hi = hi + margin;
        int widest = 0;
        for (double tick : axis.ticks()) widest = std::max(widest, textWidth(axis.label(tick), kTextScale));
        const double spacing = axis.step / (axis.hi - axis.lo) * kPlotWidth;
        if (spacing >= widest + 3 * kGlyphGap) break;
    }
    return axis;
}

} // namespace

Image plotExploration(const ExploreResult& result, std::string_view title) {
    std::vector<double> xs;
    Series fraction{"SOLID FRACTION", {31, 119, 180}, true, {}, ""};
    Series area{"SURFACE AREA (VOXEL FACES)", {230, 110, 10}, false, {}, ""};
    Series iou{"MEAN PAIRWISE IOU", {44, 150, 44}, true, {}, "NEEDS --RUNS 2 OR MORE"};
    for (const ValueSummary& summary : result.values) {
        xs.push_back(summary.value);
        fraction.points.push_back(summary.solidFraction);
        area.points.push_back(summary.surfaceArea);
        iou.points.push_back(summary.iou);
    }
    Image image(3 * kPanelWidth + 20, kTitleHeight + kPanelHeight + kFooterHeight, kWhite);
    drawText(image, image.width / 2, 14, title, kInk, kTextScale, Align::Center);
    if (xs.empty()) return image;
    const Axis xAxis = parameterAxis(xs);
    int originX = 10;
    for (const Series* series : {&fraction, &area, &iou}) {
        drawPanel(image, originX, kTitleHeight, xAxis, xs, *series, result.parameter);
        originX += kPanelWidth;
    }
    const size_t runs = result.values.front().runs.size();
    const std::string footer =
        fmt::format("LINE: MEAN OVER {} RUN{}   BAND: +/- 1 STDDEV   SOLID: DENSITY >= {}   GRID {}X{}X{}", runs,
                    runs == 1 ? "" : "S", result.iso, result.size.x, result.size.y, result.size.z);
    drawText(image, image.width / 2, image.height - kFooterHeight + 8, footer, kInk, kTextScale, Align::Center);
    return image;
}

} // namespace voxc::explore
