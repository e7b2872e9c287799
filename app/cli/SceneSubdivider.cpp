#include "cli/SceneSubdivider.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace vct::cli {

namespace {

/** Adds the midpoints of edges to a mesh, once per edge. */
class MidpointCache {
public:
    explicit MidpointCache(render::Mesh& mesh)
        : m_mesh(mesh)
    {
    }

    std::uint32_t midpoint(std::uint32_t a, std::uint32_t b)
    {
        const std::uint64_t key = a < b ? (std::uint64_t(a) << 32 | b) : (std::uint64_t(b) << 32 | a);
        if (const auto it = m_cache.find(key); it != m_cache.end())
            return it->second;
        const auto index = std::uint32_t(m_mesh.positions.size());
        m_mesh.positions.push_back(0.5f * (m_mesh.positions[a] + m_mesh.positions[b]));
        if (m_mesh.normals.size() > std::max(a, b)) {
            const glm::vec3 sum = m_mesh.normals[a] + m_mesh.normals[b];
            // Opposite normals (a crease folded back) average to nothing: keep one side's.
            m_mesh.normals.push_back(glm::dot(sum, sum) > 1e-12f ? glm::normalize(sum) : m_mesh.normals[a]);
        }
        if (m_mesh.uvs.size() > std::max(a, b))
            m_mesh.uvs.push_back(0.5f * (m_mesh.uvs[a] + m_mesh.uvs[b]));
        m_cache.emplace(key, index);
        return index;
    }

private:
    render::Mesh& m_mesh;
    std::unordered_map<std::uint64_t, std::uint32_t> m_cache;
};

float squaredLength(const glm::vec3& v)
{
    return glm::dot(v, v);
}

} // namespace

render::Mesh SceneSubdivider::splitInFour(const render::Mesh& mesh)
{
    render::Mesh out = mesh;
    out.indices.clear();
    out.indices.reserve(mesh.indices.size() * 4);
    MidpointCache midpoints(out);
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const std::uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
        const std::uint32_t ab = midpoints.midpoint(a, b), bc = midpoints.midpoint(b, c),
                            ca = midpoints.midpoint(c, a);
        for (std::uint32_t i : { a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca })
            out.indices.push_back(i);
    }
    return out;
}

render::Mesh SceneSubdivider::splitInTwo(const render::Mesh& mesh)
{
    render::Mesh out = mesh;
    out.indices.clear();
    out.indices.reserve(mesh.indices.size() * 2);
    MidpointCache midpoints(out);
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        std::uint32_t v[3] = { mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2] };
        // Rotate (keeping the winding) so the longest edge runs from v[0] to v[1].
        const float lengths[3] = { squaredLength(mesh.positions[v[1]] - mesh.positions[v[0]]),
            squaredLength(mesh.positions[v[2]] - mesh.positions[v[1]]),
            squaredLength(mesh.positions[v[0]] - mesh.positions[v[2]]) };
        const int longest = lengths[0] >= lengths[1] && lengths[0] >= lengths[2] ? 0
            : lengths[1] >= lengths[2]                                           ? 1
                                                                                 : 2;
        const std::uint32_t a = v[longest], b = v[(longest + 1) % 3], c = v[(longest + 2) % 3];
        const std::uint32_t m = midpoints.midpoint(a, b);
        for (std::uint32_t i : { a, m, c, m, b, c })
            out.indices.push_back(i);
    }
    return out;
}

render::Scene SceneSubdivider::subdivide(const render::Scene& scene, int factor)
{
    if (factor < 1 || (factor & (factor - 1)) != 0)
        throw std::invalid_argument("triangle factor " + std::to_string(factor) + " is not a power of two");
    render::Scene out = scene;
    for (render::Mesh& mesh : out.meshes) {
        int remaining = factor;
        for (; remaining >= 4; remaining /= 4)
            mesh = splitInFour(mesh);
        if (remaining == 2)
            mesh = splitInTwo(mesh);
    }
    return out;
}

} // namespace vct::cli
