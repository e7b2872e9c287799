#pragma once

#include "scene/Aabb.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace vct::render {

/** A run of a mesh's reordered index buffer whose triangles lie close together. */
struct MeshCluster {
    std::uint32_t firstIndex = 0;
    std::uint32_t indexCount = 0;
    Aabb bounds; ///< object space
};

/**
 * Splits a mesh's triangles into spatially compact clusters, so a draw can skip the clusters a view cannot
 * see (a shadow cube face sees about a sixth of a scene around its light) and draw the rest nearest first,
 * which lets early depth testing discard hidden fragments before they are shaded. Triangles are split at the
 * median of their centroids along the widest axis until a cluster holds at most @p maxTriangles.
 */
class MeshClusters {
public:
    static constexpr std::size_t kDefaultMaxTriangles = 512;

    MeshClusters(const std::vector<glm::vec3>& positions, const std::vector<std::uint32_t>& indices,
        std::size_t maxTriangles = kDefaultMaxTriangles);

    /** The same triangles as the input, reordered so each cluster's are contiguous. */
    const std::vector<std::uint32_t>& indices() const { return m_indices; }
    const std::vector<MeshCluster>& clusters() const { return m_clusters; }

private:
    std::vector<std::uint32_t> m_indices;
    std::vector<MeshCluster> m_clusters;
};

} // namespace vct::render
