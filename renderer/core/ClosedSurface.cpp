#include "core/ClosedSurface.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>
#include <unordered_map>

namespace vct::render {

namespace {

struct PositionHash {
    std::size_t operator()(const glm::vec3& p) const
    {
        std::size_t h = 0;
        for (int i = 0; i < 3; ++i) {
            float f = p[i] == 0.0f ? 0.0f : p[i]; // -0 and +0 weld
            std::uint32_t bits;
            std::memcpy(&bits, &f, sizeof bits);
            h = h * 0x9E3779B97F4A7C15ull + bits;
        }
        return h;
    }
};

struct Edge {
    std::uint32_t from, to;
    bool operator==(const Edge& o) const { return from == o.from && to == o.to; }
};

struct EdgeHash {
    std::size_t operator()(const Edge& e) const { return (std::size_t(e.from) << 32) ^ e.to; }
};

std::uint32_t findRoot(std::vector<std::uint32_t>& parent, std::uint32_t i)
{
    while (parent[i] != i)
        i = parent[i] = parent[parent[i]];
    return i;
}

// Slab test of the ray origin + t dir, t > 0, against a box.
bool rayMeetsBox(const glm::dvec3& origin, const glm::dvec3& invDir, const Aabb& box)
{
    double near = 0.0, far = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
        // A hair of padding: a ray along a box face must still reach the triangles lying in it.
        const double pad = 1e-9 * (1.0 + std::abs(double(box.min[a])) + std::abs(double(box.max[a])));
        double t0 = (double(box.min[a]) - pad - origin[a]) * invDir[a];
        double t1 = (double(box.max[a]) + pad - origin[a]) * invDir[a];
        if (t0 > t1)
            std::swap(t0, t1);
        near = std::max(near, t0);
        far = std::min(far, t1);
        if (!(near <= far))
            return false;
    }
    return true;
}

} // namespace

ClosedSurface::ClosedSurface(const std::vector<glm::vec3>& positions,
    const std::vector<std::uint32_t>& indices, const std::vector<MeshCluster>& clusters)
    : m_indices(indices)
    , m_clusters(clusters)
{
    const std::size_t triangles = indices.size() / 3;
    if (triangles == 0)
        return;
    for (const std::uint32_t i : indices)
        if (i >= positions.size())
            return;
    for (const glm::vec3& p : positions)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            return;
    // Weld: meshes split vertices along creases and UV seams, but the surface is closed across them.
    std::unordered_map<glm::vec3, std::uint32_t, PositionHash> welded;
    std::vector<std::uint32_t> weldedIndex(positions.size());
    for (std::size_t i = 0; i < positions.size(); ++i) {
        const auto [it, added] = welded.try_emplace(positions[i], std::uint32_t(m_positions.size()));
        if (added)
            m_positions.emplace_back(positions[i]);
        weldedIndex[i] = it->second;
    }
    for (std::uint32_t& i : m_indices)
        i = weldedIndex[i];

    std::unordered_map<Edge, int, EdgeHash> edges;
    edges.reserve(triangles * 3);
    std::vector<std::uint32_t> parent(m_positions.size());
    std::iota(parent.begin(), parent.end(), 0u);
    for (std::size_t t = 0; t < triangles; ++t) {
        const std::uint32_t v[3] = { m_indices[3 * t], m_indices[3 * t + 1], m_indices[3 * t + 2] };
        if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0])
            return; // a degenerate triangle's edges pair with nothing sensible
        for (int k = 0; k < 3; ++k) {
            if (++edges[{ v[k], v[(k + 1) % 3] }] > 1)
                return; // the same directed edge twice: not a consistently oriented 2-manifold
            parent[findRoot(parent, v[k])] = findRoot(parent, v[(k + 1) % 3]);
        }
    }
    for (const auto& [edge, count] : edges)
        if (edges.find({ edge.to, edge.from }) == edges.end())
            return; // an open edge
    // Signed volume per connected part (divergence theorem): every part must enclose positive volume.
    std::unordered_map<std::uint32_t, double> volume;
    for (std::size_t t = 0; t < triangles; ++t) {
        const glm::dvec3& a = m_positions[m_indices[3 * t]];
        const glm::dvec3& b = m_positions[m_indices[3 * t + 1]];
        const glm::dvec3& c = m_positions[m_indices[3 * t + 2]];
        volume[findRoot(parent, m_indices[3 * t])] += glm::dot(a, glm::cross(b, c)) / 6.0;
    }
    for (const auto& [part, v] : volume)
        if (!(v > 0.0))
            return;
    m_solid = true;
}

std::optional<int> ClosedSurface::windingNumber(const glm::vec3& point) const
{
    if (!m_solid)
        return std::nullopt;
    // Directions no modelled surface is likely to line up with; a graze on one tries the next.
    static const glm::dvec3 kDirections[3] = { glm::normalize(glm::dvec3(0.5773, 0.6128, 0.5398)),
        glm::normalize(glm::dvec3(-0.3721, 0.8264, -0.4226)),
        glm::normalize(glm::dvec3(0.7071, -0.3162, -0.6325)) };
    const glm::dvec3 origin(point);
    for (const glm::dvec3& dir : kDirections) {
        const glm::dvec3 invDir = 1.0 / dir;
        int winding = 0;
        bool grazed = false;
        for (const MeshCluster& cluster : m_clusters) {
            if (grazed || !rayMeetsBox(origin, invDir, cluster.bounds))
                continue;
            for (std::uint32_t i = cluster.firstIndex; i + 2 < cluster.firstIndex + cluster.indexCount;
                 i += 3) {
                const glm::dvec3& a = m_positions[m_indices[i]];
                const glm::dvec3 e1 = m_positions[m_indices[i + 1]] - a,
                                 e2 = m_positions[m_indices[i + 2]] - a;
                // Moeller-Trumbore, in double precision.
                const glm::dvec3 p = glm::cross(dir, e2);
                const double det = glm::dot(e1, p);
                const double scale = glm::length(e1) * glm::length(e2);
                if (std::abs(det) <= 1e-12 * scale)
                    continue; // the ray runs along the triangle's plane: it does not cross it
                const glm::dvec3 s = origin - a;
                const double u = glm::dot(s, p) / det;
                const glm::dvec3 q = glm::cross(s, e1);
                const double v = glm::dot(dir, q) / det;
                const double t = glm::dot(e2, q) / det;
                constexpr double kEdge = 1e-9;
                if (u < -kEdge || v < -kEdge || u + v > 1.0 + kEdge || t < 0.0)
                    continue;
                if (u < kEdge || v < kEdge || u + v > 1.0 - kEdge || t < 1e-12 * std::sqrt(scale)) {
                    grazed = true; // through an edge or vertex, or starting on the surface: count again
                    break;
                }
                // Leaving through a face (the ray along its normal) means the point was inside that part.
                winding += glm::dot(glm::cross(e1, e2), dir) > 0.0 ? 1 : -1;
            }
        }
        if (!grazed)
            return winding;
    }
    return std::nullopt;
}

} // namespace vct::render
