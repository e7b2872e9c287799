#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace vct::render {

/**
 * Whether triangle (@p a, @p b, @p c) meets the closed axis-aligned box [@p boxLo, @p boxHi]: the separating
 * axis test of Akenine-Möller ("Fast 3D Triangle-Box Overlap Testing", 2001), in doubles. It errs only
 * towards "meets": every corner is projected on every axis, so an axis that rounding has tilted, or that a
 * degenerate triangle (a segment, a point) leaves zero, can fail to separate but never separates what
 * touches. The brick pool and the enclosed-space map both rest on that: a cell wrongly left out loses light.
 */
bool triangleOverlapsBox(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
    const glm::dvec3& boxLo, const glm::dvec3& boxHi);

/** Whether every coordinate of @p p is finite: the grids built from triangles skip those with a corner that
 * is not, and count them. */
inline bool isFinitePoint(const glm::vec3& p)
{
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

/**
 * Calls @p onTriangle(a, b, c) for each triangle of a mesh, its @p positions taken to grid space by the
 * affine
 * @p toGrid; @p indices three per triangle, a trailing one or two ignored (as the renderer's draws ignore
 * them). Returns how many triangles were skipped for naming a vertex that does not exist.
 */
template <class OnTriangle>
std::size_t forEachGridTriangle(const std::vector<glm::vec3>& positions,
    const std::vector<std::uint32_t>& indices, const glm::mat4& toGrid, OnTriangle&& onTriangle)
{
    std::vector<glm::vec3> grid;
    grid.reserve(positions.size());
    for (const glm::vec3& p : positions)
        grid.emplace_back(toGrid * glm::vec4(p, 1.0f));
    std::size_t skipped = 0;
    for (std::size_t i = 0; i + 2 < indices.size(); i += 3) {
        const std::uint32_t i0 = indices[i], i1 = indices[i + 1], i2 = indices[i + 2];
        if (i0 >= grid.size() || i1 >= grid.size() || i2 >= grid.size())
            ++skipped;
        else
            onTriangle(grid[i0], grid[i1], grid[i2]);
    }
    return skipped;
}

} // namespace vct::render
