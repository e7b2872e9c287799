#pragma once

#include "plot/Chart.h"
#include "plot/ChartCanvas.h"

#include <QSizeF>

namespace vct::plot {

/**
 * Lays a Chart out (margins from the tick labels and the legend, axis ranges from AxisTicks) and draws it
 * on a ChartCanvas, the same way for SVG and PNG. Drawing order: frame and grid, series lines, highlighted
 * step lines, markers, highlighted markers, point labels, legend.
 */
class ChartPainter {
public:
    static void paint(const Chart& chart, ChartCanvas& canvas, QSizeF size);
    /** The colour series `index` gets when it sets none. */
    static QColor paletteColor(std::size_t index);
};

} // namespace vct::plot
