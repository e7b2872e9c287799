#pragma once

#include "plot/ChartAxis.h"

#include <QString>

#include <vector>

namespace vct::plot {

/** The span an axis shows and the tick values on it, in data units (not log10 of them). */
struct AxisRange {
    double min = 0.0;
    double max = 1.0;
    std::vector<double> ticks; ///< Ascending, all within [min, max].
};

/**
 * Tick values that read well. Linear axes step by 1, 2 or 5 times a power of ten; log axes put ticks on
 * decades, and on 2 and 5 times them when the data spans two decades or less. The range is widened to the
 * ticks just outside the data so the outermost points sit on a tick or inside.
 */
class AxisTicks {
public:
    /** Range and ticks for data in [lo, hi]; about `targetCount` ticks. An empty or single value range is
     * widened. */
    static AxisRange linear(double lo, double hi, int targetCount = 6);
    /** Range and ticks for positive data in [lo, hi]; non-positive input falls back to [1, 10]. */
    static AxisRange log10(double lo, double hi);
    /** Exactly `ticks` (sorted), the range spanning them and the data [lo, hi]. */
    static AxisRange fixed(std::vector<double> ticks, double lo, double hi);
    /** Range and ticks for an axis of a chart whose data spans [lo, hi]. */
    static AxisRange forAxis(const ChartAxis& axis, double lo, double hi);
    /** A short label: "0.25", "40", "1.5k", "2M"; thousands and up with SI suffixes. */
    static QString label(double value);
};

} // namespace vct::plot
