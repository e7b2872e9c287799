#pragma once

#include <glm/vec3.hpp>

#include <cmath>

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

} // namespace vct::render
