#pragma once

#include <algorithm>
#include <vector>

namespace vct::cli {

/** The median, robust to the odd slow frame on a shared machine; 0 for no values. */
inline double median(std::vector<double> values)
{
    if (values.empty())
        return 0.0;
    std::sort(values.begin(), values.end());
    const std::size_t mid = values.size() / 2;
    return values.size() % 2 ? values[mid] : 0.5 * (values[mid - 1] + values[mid]);
}

} // namespace vct::cli
