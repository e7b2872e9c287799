#pragma once

#include "cli/PerfResult.h"
#include "plot/Chart.h"

#include <QString>

#include <string>
#include <vector>

namespace vct::cli {

/** A chart and the file name (without extension) it is written under. */
struct NamedChart {
    QString baseName;
    plot::Chart chart;
};

/**
 * Turns `vct-bench perf` results into files: results.csv (one row per configuration, mode and pass),
 * efficiency.csv, memory.csv (bytes per 3D texture level), perf.md (Markdown tables) and the scaling charts.
 */
class PerfReport {
public:
    /** `scene` names the input (e.g. builtin:atrium); `header` is the command line and GL context, for
     * perf.md. */
    PerfReport(std::string scene, std::string header, std::vector<PerfResult> results);

    std::string resultsCsv() const;
    std::string efficiencyCsv() const;
    std::string memoryCsv() const;
    std::string markdown() const;
    /** The headline figures for stdout: whole-frame times, cone efficiency, memory per grid. */
    std::string summary() const;
    /** GPU ms against output pixels, grid resolution and triangle count (those with at least two points). */
    std::vector<NamedChart> charts() const;

private:
    std::string wholeFrameTable() const;
    std::string passTable(bool cameraOnly) const;
    std::string efficiencyTable() const;
    std::string memoryTables() const;
    std::vector<std::string> passNames() const;

    std::string m_scene;
    std::string m_header;
    std::vector<PerfResult> m_results;
};

} // namespace vct::cli
