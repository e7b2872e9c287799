#pragma once

#include <glm/vec3.hpp>

namespace vct::render {

/**
 * The separating-axis test of core/TriangleBoxOverlap for one triangle against many unit cells of its own
 * bounds, each grown by a slack on every side: the boxes' own axes never separate a cell inside the bounds,
 * and what the other ten axes need of the triangle is found once (core/EnclosedSpace marks its cells with
 * it). The same test, arranged for a loop over cells, that errs towards "meets" as that one does: a zero axis
 * of a degenerate triangle never separates.
 */
class TriangleAxes {
public:
    TriangleAxes(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, double slack);

    /** Whether the triangle meets the cell [cell, cell + 1]^3 grown by the slack; it must lie in its bounds.
     */
    bool meetsCell(const glm::ivec3& cell) const;

private:
    static constexpr int kAxes
        = 10; ///< the plane (first: it rejects most cells of a large triangle), nine crosses
    glm::dvec3 m_axes[kAxes];
    double m_low[kAxes], m_high[kAxes], m_radius[kAxes];
};

} // namespace vct::render
