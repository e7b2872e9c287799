#pragma once

#include "core/MeshClusters.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <optional>
#include <vector>

namespace vct::render {

/**
 * Whether a mesh bounds solids, and on which side of them a point lies, so a view from outside can skip the
 * faces turned away from it: depth testing would hide every one of them behind a face turned towards it.
 *
 * A mesh counts as solid when, with vertices welded by position, every edge is shared by exactly two
 * triangles that run along it in opposite directions (closed and consistently oriented), and every connected
 * part encloses positive volume (normals outward). From a point outside every part (winding number 0), a ray
 * that first meets the surface enters a part: it meets a front face first. Inside one (a camera within a
 * wall), nothing may be culled, since overlapping parts are entered and left in any order.
 */
class ClosedSurface {
public:
    ClosedSurface(const std::vector<glm::vec3>& positions, const std::vector<std::uint32_t>& indices,
        const std::vector<MeshCluster>& clusters);

    bool isSolid() const { return m_solid; }
    /**
     * The winding number at @p point (object space): 0 outside, the number of parts around it inside. Counted
     * along a ray, testing only the clusters it passes; nothing when every ray tried grazes an edge or a
     * vertex too closely to count, or the mesh is not solid.
     */
    std::optional<int> windingNumber(const glm::vec3& point) const;

private:
    bool m_solid = false;
    std::vector<glm::dvec3> m_positions;
    std::vector<std::uint32_t> m_indices; ///< in cluster order, as the clusters' index ranges
    std::vector<MeshCluster> m_clusters;
};

} // namespace vct::render
