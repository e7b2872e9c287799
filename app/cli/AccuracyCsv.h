#pragma once

#include "cli/AccuracyRow.h"

#include <string>
#include <vector>

namespace vct::cli {

/**
 * results.csv of `vct-bench accuracy` and the per-job files it merges: RFC 4180 CSV with a header line, one
 * AccuracyRow per line. Columns are found by name on reading, so files with extra or reordered columns
 * still merge; numbers are written with enough digits to read back what was measured.
 */
class AccuracyCsv {
public:
    /** The header line's column names, in the order write() uses. */
    static const std::vector<std::string>& columns();
    static std::string write(const std::vector<AccuracyRow>& rows);
    /**
     * Appends the rows of @p text to @p rows. Returns false and sets @p error (naming @p sourceName and the
     * line) when the header lacks a column this needs or a field cannot be read.
     */
    static bool read(const std::string& text, const std::string& sourceName, std::vector<AccuracyRow>& rows,
        std::string* error);
};

} // namespace vct::cli
