#pragma once

#include "cli/AccuracyRow.h"

#include <vector>

namespace vct::cli {

/** How the path tracer's time at some error was found. */
struct PathTracerTime {
    enum class Kind {
        None, ///< no curve, or the error is not finite
        Interpolated, ///< between two measured points (log-log)
        AtMost, ///< the fewest measured samples already reach the error: it takes `ms` or less
        Beyond, ///< no measured point reaches the error: it takes more than `ms`
    };
    Kind kind = Kind::None;
    double ms = 0.0; ///< wall-clock
    double cpuMs = 0.0; ///< CPU time of all threads (NaN when the curve has none)
    double spp = 0.0; ///< samples per pixel at that time (interpolated like the time)
};

/**
 * The path tracer's error against wall-clock time at increasing samples per pixel (the rows of kind
 * "reference"), for questions like "how long does the path tracer take to be as accurate as this VCT
 * setting".
 */
class PathTracerCurve {
public:
    explicit PathTracerCurve(const std::vector<AccuracyRow>& rows);

    /** The curve's points, by samples per pixel. */
    const std::vector<AccuracyRow>& points() const { return m_points; }
    bool empty() const { return m_points.empty(); }

    /**
     * The time of the first crossing of @p relMse, walking up in spp: log time against log error interpolated
     * between the last point above the error and the first at or below it. Monte Carlo noise makes the
     * curve only roughly monotonic; the first crossing is the cautious reading.
     */
    PathTracerTime timeToReach(double relMse) const;

private:
    std::vector<AccuracyRow> m_points;
};

} // namespace vct::cli
