#include "core/MeshClusters.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace vct::render {

namespace {

struct Splitter {
    const std::vector<glm::vec3>& positions;
    const std::vector<std::uint32_t>& indices;
    const std::vector<glm::vec3>& centroids;
    std::size_t maxTriangles;
    std::vector<std::uint32_t>& out;
    std::vector<MeshCluster>& clusters;

    void split(std::vector<std::uint32_t>::iterator first, std::vector<std::uint32_t>::iterator last)
    {
        const std::size_t count = std::size_t(last - first);
        Aabb spread;
        for (auto it = first; it != last; ++it)
            spread.extend(centroids[*it]);
        const glm::vec3 size = spread.size();
        if (count > maxTriangles && (size.x > 0.0f || size.y > 0.0f || size.z > 0.0f)) {
            const int axis = size.x >= size.y && size.x >= size.z ? 0 : (size.y >= size.z ? 1 : 2);
            const auto middle = first + std::ptrdiff_t(count / 2);
            std::nth_element(first, middle, last,
                [&](std::uint32_t a, std::uint32_t b) { return centroids[a][axis] < centroids[b][axis]; });
            split(first, middle);
            split(middle, last);
            return;
        }
        // Small enough, or every centroid in one point (no split can help): cut into runs of maxTriangles.
        for (auto runStart = first; runStart != last;) {
            const auto runEnd = runStart
                + std::ptrdiff_t(std::min<std::size_t>(maxTriangles, std::size_t(last - runStart)));
            MeshCluster cluster;
            cluster.firstIndex = std::uint32_t(out.size());
            for (auto it = runStart; it != runEnd; ++it)
                for (int corner = 0; corner < 3; ++corner) {
                    const std::uint32_t vertex = indices[std::size_t(*it) * 3 + std::size_t(corner)];
                    out.push_back(vertex);
                    if (vertex < positions.size())
                        cluster.bounds.extend(positions[vertex]);
                }
            cluster.indexCount = std::uint32_t(out.size()) - cluster.firstIndex;
            clusters.push_back(cluster);
            runStart = runEnd;
        }
    }
};

} // namespace

MeshClusters::MeshClusters(const std::vector<glm::vec3>& positions, const std::vector<std::uint32_t>& indices,
    std::size_t maxTriangles)
{
    const std::size_t triangles = indices.size() / 3;
    std::vector<glm::vec3> centroids(triangles, glm::vec3(0.0f));
    for (std::size_t t = 0; t < triangles; ++t)
        for (int corner = 0; corner < 3; ++corner) {
            const std::uint32_t vertex = indices[t * 3 + std::size_t(corner)];
            if (vertex < positions.size())
                centroids[t] += positions[vertex] / 3.0f;
        }
    // A non-finite centroid would break the median's ordering; such triangles may go in any cluster.
    for (glm::vec3& c : centroids)
        if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z))
            c = glm::vec3(0.0f);
    std::vector<std::uint32_t> order(triangles);
    std::iota(order.begin(), order.end(), 0u);
    m_indices.reserve(triangles * 3);
    Splitter splitter { positions, indices, centroids, std::max<std::size_t>(maxTriangles, 1), m_indices,
        m_clusters };
    splitter.split(order.begin(), order.end());
}

} // namespace vct::render
