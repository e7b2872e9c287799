#include "plot/ParetoFrontier.h"

#include <algorithm>
#include <cmath>

namespace vct::plot {

std::vector<std::size_t> ParetoFrontier::of(const std::vector<TimeError>& points)
{
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < points.size(); ++i)
        if (std::isfinite(points[i].time) && std::isfinite(points[i].error))
            order.push_back(i);
    // By time, then error; stable so the first of identical points leads.
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return points[a].time < points[b].time
            || (points[a].time == points[b].time && points[a].error < points[b].error);
    });
    // Walking from fastest to slowest, a point survives only if it is more accurate than every faster one.
    std::vector<std::size_t> frontier;
    for (std::size_t i : order)
        if (frontier.empty() || points[i].error < points[frontier.back()].error)
            frontier.push_back(i);
    return frontier;
}

} // namespace vct::plot
