#pragma once

#include <QColor>
#include <QString>

#include <cstddef>
#include <vector>

namespace vct::plot {

/** One data point; `label` (optional) is drawn next to it. */
struct ChartPoint {
    double x = 0.0;
    double y = 0.0;
    QString label;
};

/**
 * A named set of points drawn as markers and/or a polyline in data order. Points that cannot be placed
 * (not finite, or not positive on a log axis) are left out of the drawing.
 */
struct ChartSeries {
    QString name;
    std::vector<ChartPoint> points;
    bool markers = true;
    bool line = true;
    bool dashed = false;
    QColor color; ///< Invalid: the next colour of the chart's palette.
    /// Indices into `points` drawn again with bigger markers and joined by a step line in x order: a
    /// Pareto frontier of (time, error) points, for instance. Empty: nothing highlighted.
    std::vector<std::size_t> highlighted;
    QString highlightName; ///< Legend entry of the highlighted subset; empty: no entry.
};

} // namespace vct::plot
