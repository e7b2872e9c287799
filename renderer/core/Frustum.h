#pragma once

#include "scene/Aabb.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <array>

namespace vct::render {

/**
 * The six clip planes of a view-projection, for culling boxes before they are drawn. Planes are kept relative
 * to an origin near the viewpoint so a scene far from the world origin (tests/hardcases, offset 1e5) is
 * classified as precisely as one at it.
 */
class Frustum {
public:
    /**
     * @p viewProjection maps world points minus @p origin to GL clip space (-w <= x, y, z <= w), as the
     * shadow pass's matrices do. Build it without the origin's translation (a view matrix looking from 0):
     * a world-space matrix times translate(origin) is the same map, but it has already lost precision.
     */
    Frustum(const glm::mat4& viewProjection, const glm::vec3& origin);
    /** The six faces of a box (not empty), for culling against a region of the grid. */
    static Frustum ofBox(const Aabb& box);

    /** False only when the box lies wholly outside one plane: conservative, a box across a corner passes. */
    bool mayContain(const Aabb& box) const;

private:
    std::array<glm::vec4, 6> m_planes; ///< xyz normal (not unit), w offset; inside where dot(n, p) + w >= 0
    glm::vec3 m_origin;
};

} // namespace vct::render
