#pragma once

#include <QString>

#include <vector>

namespace vct::plot {

enum class AxisScale { Linear, Log10 };

/** One axis of a Chart: its label, its scale, and optionally the exact tick values to show. */
struct ChartAxis {
    QString label;
    AxisScale scale = AxisScale::Linear;
    /// Empty: nice ticks (1-2-5 steps, or decades on a log axis) around the data. Otherwise exactly these
    /// ticks, e.g. grid resolutions 32, 64, 128, 256; the axis spans them and the data.
    std::vector<double> fixedTicks;
};

} // namespace vct::plot
