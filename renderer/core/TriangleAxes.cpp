#include "core/TriangleAxes.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>

namespace vct::render {

TriangleAxes::TriangleAxes(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, double slack)
{
    const glm::dvec3 corners[3] = { a, b, c };
    const glm::dvec3 edges[3] = { b - a, c - b, a - c };
    m_axes[0] = glm::cross(edges[0], edges[1]);
    int k = 1;
    for (const glm::dvec3& edge : edges) {
        m_axes[k++] = { 0.0, -edge.z, edge.y }; // edge x (1, 0, 0)
        m_axes[k++] = { edge.z, 0.0, -edge.x }; // edge x (0, 1, 0)
        m_axes[k++] = { -edge.y, edge.x, 0.0 }; // edge x (0, 0, 1)
    }
    for (int i = 0; i < kAxes; ++i) {
        const double p0 = glm::dot(m_axes[i], corners[0]), p1 = glm::dot(m_axes[i], corners[1]),
                     p2 = glm::dot(m_axes[i], corners[2]);
        m_low[i] = std::min({ p0, p1, p2 });
        m_high[i] = std::max({ p0, p1, p2 });
        m_radius[i] = glm::dot(glm::abs(m_axes[i]), glm::dvec3(0.5 + slack));
    }
}

bool TriangleAxes::meetsCell(const glm::ivec3& cell) const
{
    const glm::dvec3 centre = glm::dvec3(cell) + 0.5;
    for (int i = 0; i < kAxes; ++i) {
        const double at = glm::dot(m_axes[i], centre);
        if (m_low[i] - at > m_radius[i] || m_high[i] - at < -m_radius[i])
            return false;
    }
    return true;
}

} // namespace vct::render
