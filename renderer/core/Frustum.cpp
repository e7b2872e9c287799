#include "core/Frustum.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

namespace vct::render {

Frustum::Frustum(const glm::mat4& viewProjection, const glm::vec3& origin)
    : m_origin(origin)
{
    // Gribb and Hartmann: each plane is row 3 plus or minus row 0, 1 or 2 of the matrix.
    const glm::mat4 rows = glm::transpose(viewProjection);
    for (int axis = 0; axis < 3; ++axis) {
        m_planes[std::size_t(2 * axis)] = rows[3] + rows[axis];
        m_planes[std::size_t(2 * axis + 1)] = rows[3] - rows[axis];
    }
}

Frustum Frustum::ofBox(const Aabb& box)
{
    // Maps [0, size] on each axis, relative to the box's min corner, to the clip range [-1, 1].
    const glm::vec3 size = glm::max(box.max - box.min, glm::vec3(1e-30f));
    glm::mat4 toClip(1.0f);
    for (int axis = 0; axis < 3; ++axis) {
        toClip[axis][axis] = 2.0f / size[axis];
        toClip[3][axis] = -1.0f;
    }
    return Frustum(toClip, box.min);
}

bool Frustum::mayContain(const Aabb& box) const
{
    if (box.isEmpty())
        return false;
    const glm::vec3 lo = box.min - m_origin, hi = box.max - m_origin;
    // Rounding must never drop a box that touches the frustum: grow it by a hair of its own size.
    const glm::vec3 pad = (hi - lo) * 1e-4f + glm::max(glm::abs(lo), glm::abs(hi)) * 1e-6f;
    for (const glm::vec4& plane : m_planes) {
        // The box corner furthest along the plane normal.
        const glm::vec3 far(plane.x >= 0.0f ? hi.x + pad.x : lo.x - pad.x,
            plane.y >= 0.0f ? hi.y + pad.y : lo.y - pad.y, plane.z >= 0.0f ? hi.z + pad.z : lo.z - pad.z);
        if (glm::dot(glm::vec3(plane), far) + plane.w < 0.0f)
            return false;
    }
    return true;
}

} // namespace vct::render
