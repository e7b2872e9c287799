#pragma once

#include <cstddef>
#include <vector>

namespace vct::plot {

/** A measured configuration's cost and quality: lower is better in both. */
struct TimeError {
    double time = 0.0;
    double error = 0.0;
};

/** The configurations no other one beats on both time and error (accuracy-against-time sweeps). */
class ParetoFrontier {
public:
    /**
     * Indices of the non-dominated points, sorted by time. A point is dominated when another is no slower and
     * no less accurate and better in one of the two. Of identical points only the first index is kept; points
     * with a non-finite time or error are ignored.
     */
    static std::vector<std::size_t> of(const std::vector<TimeError>& points);
};

} // namespace vct::plot
