#pragma once

#include "cli/AccuracyRow.h"
#include "cli/PathTracerCurve.h"
#include "plot/Chart.h"

#include <cstddef>
#include <string>
#include <vector>

namespace vct::cli {

/**
 * The merged results of `vct-bench accuracy`: the Pareto frontier of the VCT settings (GPU ms against
 * relative MSE), the path tracer's curve, where the two cross, and the files made from them (results.csv,
 * results.md, the accuracy chart).
 */
class AccuracyReport {
public:
    /**
     * @p rows of both kinds in any order (sorted here by point index); @p header is Markdown put under the
     * title (how the study was run); @p missing lists job indices that produced no results.
     */
    AccuracyReport(
        std::string scene, std::string header, std::vector<AccuracyRow> rows, std::vector<int> missing = {});

    const std::vector<AccuracyRow>& rows() const { return m_rows; }
    /** Indices into rows() of the VCT points no other VCT point beats on both GPU time and error, by time. */
    const std::vector<std::size_t>& frontier() const { return m_frontier; }
    const PathTracerCurve& pathTracer() const { return m_curve; }

    /** x: time per image (log), y: relative MSE (log); VCT points labelled, frontier as a step line. */
    plot::Chart chart() const;
    /**
     * The VCT points alone, y linear: settings often differ by a few percent in error, which a log axis
     * shared with the path tracer's decades squeezes into one crowded band.
     */
    plot::Chart vctChart() const;
    std::string markdown() const;
    /** A few lines for the terminal: the frontier and the crossing. */
    std::string summary() const;

private:
    /**
     * Where the path tracer starts to beat the best VCT setting of equal or lower time, VCT timed by
     * @p vctTime (full or camera-only frames, or CPU time) and the path tracer by @p tracerTime; a sentence
     * or two.
     */
    std::string equalTimeCrossing(double AccuracyRow::*vctTime, double AccuracyRow::*tracerTime) const;

    std::string m_scene;
    std::string m_header;
    std::vector<AccuracyRow> m_rows;
    std::vector<int> m_missing;
    std::vector<std::size_t> m_frontier;
    PathTracerCurve m_curve;
};

} // namespace vct::cli
