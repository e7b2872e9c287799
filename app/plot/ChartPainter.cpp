#include "plot/ChartPainter.h"

#include "plot/AxisTicks.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vct::plot {

namespace {

constexpr double kTitleSize = 17.0;
constexpr double kAxisLabelSize = 14.0;
constexpr double kTickSize = 12.0;
constexpr double kLegendSize = 12.0;
constexpr double kPointLabelSize = 11.0;
constexpr double kMarkerRadius = 4.0;
constexpr double kHighlightRadius = 6.5;
constexpr double kLegendRow = 19.0;
constexpr double kLegendSample = 26.0; // width of the line sample before each legend label

const QColor kInk(0x33, 0x33, 0x33);

bool placeable(double v, AxisScale scale)
{
    return std::isfinite(v) && (scale == AxisScale::Linear || v > 0.0);
}

/** Data to pixels along one axis. */
struct AxisMap {
    AxisRange range;
    AxisScale scale;
    double from, to; // pixel positions of range.min and range.max

    double operator()(double v) const
    {
        const auto t = [this](double x) { return scale == AxisScale::Log10 ? std::log10(x) : x; };
        const double span = t(range.max) - t(range.min);
        const double f = span > 0.0 ? (t(v) - t(range.min)) / span : 0.5;
        return from + f * (to - from);
    }
};

struct LegendEntry {
    QString text;
    QColor color;
    MarkerShape shape;
    bool line, markers, dashed, highlight;
};

MarkerShape shapeOf(std::size_t index)
{
    static const MarkerShape kShapes[]
        = { MarkerShape::Circle, MarkerShape::Square, MarkerShape::Triangle, MarkerShape::Diamond };
    return kShapes[index % 4];
}

} // namespace

QColor ChartPainter::paletteColor(std::size_t index)
{
    // Tableau 10: distinct hues that stay apart for the common forms of colour blindness.
    static const QRgb kPalette[] = { 0x1f77b4, 0xff7f0e, 0x2ca02c, 0xd62728, 0x9467bd, 0x8c564b, 0xe377c2,
        0x7f7f7f, 0xbcbd22, 0x17becf };
    return QColor(kPalette[index % 10]);
}

void ChartPainter::paint(const Chart& chart, ChartCanvas& canvas, QSizeF size)
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    double xlo = nan, xhi = nan, ylo = nan, yhi = nan;
    for (const ChartSeries& s : chart.series)
        for (const ChartPoint& p : s.points)
            if (placeable(p.x, chart.x.scale) && placeable(p.y, chart.y.scale)) {
                xlo = std::isnan(xlo) ? p.x : std::min(xlo, p.x);
                xhi = std::isnan(xhi) ? p.x : std::max(xhi, p.x);
                ylo = std::isnan(ylo) ? p.y : std::min(ylo, p.y);
                yhi = std::isnan(yhi) ? p.y : std::max(yhi, p.y);
            }
    const AxisRange xr = AxisTicks::forAxis(chart.x, xlo, xhi);
    const AxisRange yr = AxisTicks::forAxis(chart.y, ylo, yhi);

    std::vector<LegendEntry> legend;
    std::vector<QColor> colors;
    for (std::size_t i = 0; i < chart.series.size(); ++i) {
        const ChartSeries& s = chart.series[i];
        colors.push_back(s.color.isValid() ? s.color : paletteColor(i));
        if (!chart.legend)
            continue;
        legend.push_back({ s.name, colors.back(), shapeOf(i), s.line, s.markers, s.dashed, false });
        if (!s.highlighted.empty() && !s.highlightName.isEmpty())
            legend.push_back({ s.highlightName, colors.back(), shapeOf(i), true, true, false, true });
    }
    double legendWidth = 0.0;
    for (const LegendEntry& e : legend)
        legendWidth = std::max(legendWidth, kLegendSample + 8.0 + canvas.textWidth(e.text, kLegendSize));
    const double legendGap = legend.empty() ? 0.0 : 18.0;

    double yTickWidth = 0.0;
    for (double t : yr.ticks)
        yTickWidth = std::max(yTickWidth, canvas.textWidth(AxisTicks::label(t), kTickSize));
    const double left = 14.0 + (chart.y.label.isEmpty() ? 0.0 : kAxisLabelSize + 10.0) + yTickWidth + 10.0;
    const double top = chart.title.isEmpty() ? 18.0 : 22.0 + kTitleSize + 12.0;
    const double bottom = 14.0 + kTickSize + 8.0 + (chart.x.label.isEmpty() ? 0.0 : kAxisLabelSize + 12.0);
    const double right = 18.0 + legendGap + legendWidth;
    const QRectF plot(
        left, top, std::max(10.0, size.width() - left - right), std::max(10.0, size.height() - top - bottom));
    const AxisMap mapX { xr, chart.x.scale, plot.left(), plot.right() };
    const AxisMap mapY { yr, chart.y.scale, plot.bottom(), plot.top() };
    const auto at = [&](const ChartPoint& p) { return QPointF(mapX(p.x), mapY(p.y)); };

    canvas.rect(QRectF(QPointF(0, 0), size), Qt::white, QColor(), "background");
    canvas.rect(plot, QColor(0xfb, 0xfb, 0xfb), QColor(), "plot-area");
    const QColor gridColor(0xe0, 0xe0, 0xe0);
    for (double t : xr.ticks) {
        const double x = mapX(t);
        canvas.line({ x, plot.top() }, { x, plot.bottom() }, gridColor, 1.0, "grid");
        canvas.line({ x, plot.bottom() }, { x, plot.bottom() + 5.0 }, kInk, 1.0, "tick");
        canvas.text({ x, plot.bottom() + 8.0 + kTickSize }, AxisTicks::label(t), kTickSize,
            TextAnchor::Middle, kInk, "tick-label");
    }
    for (double t : yr.ticks) {
        const double y = mapY(t);
        canvas.line({ plot.left(), y }, { plot.right(), y }, gridColor, 1.0, "grid");
        canvas.line({ plot.left() - 5.0, y }, { plot.left(), y }, kInk, 1.0, "tick");
        canvas.text({ plot.left() - 8.0, y + 0.35 * kTickSize }, AxisTicks::label(t), kTickSize,
            TextAnchor::End, kInk, "tick-label");
    }
    canvas.rect(plot, QColor(), QColor(0x55, 0x55, 0x55), "frame");
    if (!chart.x.label.isEmpty())
        canvas.text({ plot.center().x(), size.height() - 14.0 }, chart.x.label, kAxisLabelSize,
            TextAnchor::Middle, kInk, "axis-label");
    if (!chart.y.label.isEmpty())
        canvas.text({ 14.0 + kAxisLabelSize, plot.center().y() }, chart.y.label, kAxisLabelSize,
            TextAnchor::Middle, kInk, "axis-label", -90.0);
    if (!chart.title.isEmpty())
        canvas.text({ size.width() / 2.0, 22.0 + kTitleSize * 0.8 }, chart.title, kTitleSize,
            TextAnchor::Middle, kInk, "title", 0.0, true);

    const auto valid
        = [&](const ChartPoint& p) { return placeable(p.x, chart.x.scale) && placeable(p.y, chart.y.scale); };
    for (std::size_t i = 0; i < chart.series.size(); ++i) {
        const ChartSeries& s = chart.series[i];
        if (!s.line)
            continue;
        std::vector<QPointF> line;
        for (const ChartPoint& p : s.points)
            if (valid(p))
                line.push_back(at(p));
        canvas.polyline(line, colors[i], 2.0, s.dashed, "series-line");
    }
    // Frontiers as staircases: each point holds until the next better one is reached.
    std::vector<std::vector<std::size_t>> highlighted(chart.series.size());
    for (std::size_t i = 0; i < chart.series.size(); ++i) {
        const ChartSeries& s = chart.series[i];
        for (std::size_t index : s.highlighted)
            if (index < s.points.size() && valid(s.points[index]))
                highlighted[i].push_back(index);
        std::stable_sort(highlighted[i].begin(), highlighted[i].end(),
            [&](std::size_t a, std::size_t b) { return s.points[a].x < s.points[b].x; });
        std::vector<QPointF> steps;
        for (std::size_t index : highlighted[i]) {
            const QPointF p = at(s.points[index]);
            if (!steps.empty())
                steps.emplace_back(p.x(), steps.back().y());
            steps.push_back(p);
        }
        canvas.polyline(steps, colors[i], 2.5, false, "frontier");
    }
    for (std::size_t i = 0; i < chart.series.size(); ++i)
        if (chart.series[i].markers)
            for (const ChartPoint& p : chart.series[i].points)
                if (valid(p))
                    canvas.marker(
                        at(p), kMarkerRadius, shapeOf(i), colors[i], colors[i].darker(140), "marker");
    for (std::size_t i = 0; i < chart.series.size(); ++i)
        for (std::size_t index : highlighted[i])
            canvas.marker(at(chart.series[i].points[index]), kHighlightRadius, shapeOf(i), colors[i],
                Qt::black, "highlight");
    for (const ChartSeries& s : chart.series)
        for (const ChartPoint& p : s.points) {
            if (p.label.isEmpty() || !valid(p))
                continue;
            const QPointF c = at(p);
            const bool fitsRight = c.x() + 7.0 + canvas.textWidth(p.label, kPointLabelSize) < plot.right();
            canvas.text({ c.x() + (fitsRight ? 7.0 : -7.0), c.y() - 7.0 }, p.label, kPointLabelSize,
                fitsRight ? TextAnchor::Start : TextAnchor::End, kInk, "point-label");
        }

    double y = plot.top() + 6.0;
    const double x = plot.right() + legendGap;
    for (const LegendEntry& e : legend) {
        const double mid = y + kLegendRow * 0.5;
        if (e.line)
            canvas.polyline({ { x, mid }, { x + kLegendSample, mid } }, e.color, e.highlight ? 2.5 : 2.0,
                e.dashed, "legend-line");
        if (e.markers)
            canvas.marker({ x + kLegendSample * 0.5, mid }, e.highlight ? kHighlightRadius : kMarkerRadius,
                e.shape, e.color, e.highlight ? QColor(Qt::black) : e.color.darker(140), "legend-marker");
        canvas.text({ x + kLegendSample + 8.0, mid + 0.35 * kLegendSize }, e.text, kLegendSize,
            TextAnchor::Start, kInk, "legend-label");
        y += kLegendRow;
    }
}

} // namespace vct::plot
