#include "core/TriangleBoxOverlap.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <array>

namespace vct::render {

namespace {

using Corners = std::array<glm::dvec3, 3>;

bool apartAlong(const glm::dvec3& axis, const Corners& v, const glm::dvec3& half)
{
    const double p0 = glm::dot(axis, v[0]);
    const double p1 = glm::dot(axis, v[1]);
    const double p2 = glm::dot(axis, v[2]);
    const double radius = glm::dot(glm::abs(axis), half);
    return std::min({ p0, p1, p2 }) > radius || std::max({ p0, p1, p2 }) < -radius;
}

} // namespace

bool triangleOverlapsBox(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
    const glm::dvec3& boxLo, const glm::dvec3& boxHi)
{
    const glm::dvec3 centre = 0.5 * (boxLo + boxHi);
    const glm::dvec3 half = 0.5 * (boxHi - boxLo);
    const Corners v = { a - centre, b - centre, c - centre };
    static const glm::dvec3 boxAxes[3] = { { 1.0, 0.0, 0.0 }, { 0.0, 1.0, 0.0 }, { 0.0, 0.0, 1.0 } };
    for (const glm::dvec3& axis : boxAxes)
        if (apartAlong(axis, v, half))
            return false;
    const glm::dvec3 edges[3] = { v[1] - v[0], v[2] - v[1], v[0] - v[2] };
    // The plane first: of the boxes in a large slanted triangle's bounds, it rejects most. For a triangle
    // collapsed to a segment the normal and some crosses are zero and never separate; the box's axes and the
    // crosses of the segment with them are then the whole test for a segment, and the box's axes for a point.
    if (apartAlong(glm::cross(edges[0], edges[1]), v, half))
        return false;
    for (const glm::dvec3& edge : edges)
        for (const glm::dvec3& axis : boxAxes)
            if (apartAlong(glm::cross(edge, axis), v, half))
                return false;
    return true;
}

} // namespace vct::render
