#pragma once

#include "scene/Scene.h"

namespace vct::cli {

/**
 * Scales a scene's triangle count without changing its shape, for the triangle-count curve of
 * `vct-bench perf`: splitting keeps every surface in place, so only the per-triangle cost grows.
 */
class SceneSubdivider {
public:
    /** Each triangle into four at its edge midpoints (winding kept; triangles sharing an edge share its
     * midpoint). */
    static render::Mesh splitInFour(const render::Mesh& mesh);
    /** Each triangle into two at the midpoint of its longest edge (object space). */
    static render::Mesh splitInTwo(const render::Mesh& mesh);
    /**
     * A copy of the scene with `factor` times the triangles in every mesh: factor must be a power of two
     * (4^k, then one split in two if it is odd); throws std::invalid_argument otherwise.
     */
    static render::Scene subdivide(const render::Scene& scene, int factor);
};

} // namespace vct::cli
