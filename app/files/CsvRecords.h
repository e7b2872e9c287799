#pragma once

#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace vct::files {

/**
 * CSV text as records of fields (RFC 4180: quoted fields may hold commas, doubled quotes and line breaks;
 * CRLF or LF line ends; blank lines skipped), the one CSV reader behind every results.csv that is read back:
 * `vct-bench accuracy --merge` and the editor's Accuracy chart.
 */
class CsvRecords {
public:
    static std::vector<std::vector<std::string>> parse(std::string_view text);
    /**
     * The index in @p header of the first of @p names present, compared without case and surrounding spaces;
     * -1 when none is.
     */
    static int column(const std::vector<std::string>& header, std::initializer_list<std::string_view> names);
};

} // namespace vct::files
