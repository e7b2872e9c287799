#pragma once

#include <QString>
#include <QStringList>

#include <vector>

namespace vct::ui {

/**
 * The rows of an accuracy sweep's results.csv (written by `vct-bench accuracy`) that a chart of error against
 * time needs. Columns are found by their header names, so extra columns and any column order are fine:
 * `label`, error in `rel_mse`, optionally `kind` (`vct` or `reference`; rows without it count as VCT), and
 * the time as vct-bench plots it: `gpu_ms` for VCT rows, `wall_ms` for reference rows, each falling back to
 * the other (then `time_ms`, then `seconds`) when empty. Fields may be quoted as in RFC 4180
 * (files::CsvRecords, the reader `vct-bench accuracy --merge` uses too).
 */
class SweepResults {
public:
    struct Point {
        QString label;
        double timeMs = 0.0;
        double relativeMse = 0.0;
        bool reference = false; ///< A path-tracer row rather than a cone-traced one.
    };

    /** Reads and parses @p path; on failure returns false and names the file and problem in @p error. */
    bool load(const QString& path, QString* error);
    /** Parses CSV text; returns false, with @p error set, when a needed column is missing. */
    bool parse(const QString& text, QString* error);

    const std::vector<Point>& points() const { return m_points; }
    /** Rows left out: unparsable numbers, or values a log-log chart cannot show (<= 0, NaN, inf). */
    int skippedRows() const { return m_skipped; }
    int count(bool reference) const;

private:
    std::vector<Point> m_points;
    int m_skipped = 0;
};

} // namespace vct::ui
