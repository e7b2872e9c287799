#pragma once

#include "plot/ChartAxis.h"
#include "plot/ChartSeries.h"

#include <QString>

#include <vector>

namespace vct::plot {

/** A 2D chart as plain data: drawn by ChartPainter, written to SVG and PNG by ChartWriter. */
struct Chart {
    QString title;
    ChartAxis x;
    ChartAxis y;
    std::vector<ChartSeries> series;
    bool legend = true; ///< Drawn right of the plot area, one entry per series (and per highlighted subset).

    /** Appends an empty series and returns it (the reference lasts until the next addSeries). */
    ChartSeries& addSeries(const QString& name)
    {
        series.push_back(ChartSeries {});
        series.back().name = name;
        return series.back();
    }
};

} // namespace vct::plot
