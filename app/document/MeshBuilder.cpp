#include "MeshBuilder.h"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace vct::doc {

namespace {

int cellsAlong(float length, float maxCell)
{
    return std::max(1, int(std::ceil(length / maxCell - 1e-4f)));
}

} // namespace

std::uint32_t MeshBuilder::addVertex(const glm::vec3& position, const glm::vec3& normal, const glm::vec2& uv)
{
    m_positions.push_back(position);
    m_normals.push_back(glm::normalize(normal));
    m_uvs.push_back(uv);
    return std::uint32_t(m_positions.size() - 1);
}

void MeshBuilder::addTriangle(std::uint32_t a, std::uint32_t b, std::uint32_t c)
{
    m_indices.insert(m_indices.end(), { a, b, c });
}

void MeshBuilder::addQuad(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2, const glm::vec3& p3,
    const glm::vec3& facing)
{
    addQuad(p0, p1, p2, p3, facing, facing, facing, facing);
}

void MeshBuilder::addQuad(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2, const glm::vec3& p3,
    const glm::vec3& n0, const glm::vec3& n1, const glm::vec3& n2, const glm::vec3& n3)
{
    const glm::vec3 n = n0 + n1 + n2 + n3;
    const std::uint32_t a = addVertex(p0, n0, { 0.0f, 0.0f });
    const std::uint32_t b = addVertex(p1, n1, { 1.0f, 0.0f });
    const std::uint32_t c = addVertex(p2, n2, { 1.0f, 1.0f });
    const std::uint32_t d = addVertex(p3, n3, { 0.0f, 1.0f });
    // The diagonals' cross product is twice the quad's vector area, whatever the corner order.
    if (glm::dot(glm::cross(p2 - p0, p3 - p1), n) >= 0.0f) {
        addTriangle(a, b, c);
        addTriangle(a, c, d);
    } else {
        addTriangle(a, c, b);
        addTriangle(a, d, c);
    }
}

void MeshBuilder::addSurface(int segmentsU, int segmentsV, const SurfaceFunction& position)
{
    // Central differences reach slightly outside [0,1]; every surface here extends smoothly past its edges.
    constexpr float kStep = 1e-3f;
    const std::uint32_t first = std::uint32_t(m_positions.size());
    for (int j = 0; j <= segmentsV; ++j) {
        const float v = float(j) / float(segmentsV);
        for (int i = 0; i <= segmentsU; ++i) {
            const float u = float(i) / float(segmentsU);
            const glm::vec3 du = position(u + kStep, v) - position(u - kStep, v);
            const glm::vec3 dv = position(u, v + kStep) - position(u, v - kStep);
            glm::vec3 normal = glm::cross(du, dv);
            if (!(glm::length(normal) > 0.0f))
                normal = glm::vec3(0.0f, 1.0f, 0.0f);
            addVertex(position(u, v), normal, { u, v });
        }
    }
    const std::uint32_t row = std::uint32_t(segmentsU + 1);
    for (int j = 0; j < segmentsV; ++j) {
        for (int i = 0; i < segmentsU; ++i) {
            const std::uint32_t i00 = first + std::uint32_t(j) * row + std::uint32_t(i);
            const std::uint32_t i10 = i00 + 1;
            const std::uint32_t i01 = i00 + row;
            const std::uint32_t i11 = i01 + 1;
            addTriangle(i00, i10, i11);
            addTriangle(i00, i11, i01);
        }
    }
}

void MeshBuilder::addGrid(
    const glm::vec3& origin, const glm::vec3& u, const glm::vec3& v, int segmentsU, int segmentsV)
{
    addSurface(segmentsU, segmentsV, [&](float s, float t) { return origin + s * u + t * v; });
}

void MeshBuilder::addBox(const glm::vec3& min, const glm::vec3& max, float maxCell)
{
    const glm::vec3 size = max - min;
    const glm::vec3 x(size.x, 0.0f, 0.0f);
    const glm::vec3 y(0.0f, size.y, 0.0f);
    const glm::vec3 z(0.0f, 0.0f, size.z);
    const int nx = cellsAlong(size.x, maxCell);
    const int ny = cellsAlong(size.y, maxCell);
    const int nz = cellsAlong(size.z, maxCell);
    // Each face's (u, v) is ordered so that cross(u, v) points out of the box.
    addGrid({ max.x, min.y, min.z }, y, z, ny, nz); // +X
    addGrid(min, z, y, nz, ny); // -X
    addGrid({ min.x, max.y, min.z }, z, x, nz, nx); // +Y
    addGrid(min, x, z, nx, nz); // -Y
    addGrid({ min.x, min.y, max.z }, x, y, nx, ny); // +Z
    addGrid(min, y, x, ny, nx); // -Z
}

void MeshBuilder::addFrustum(
    const glm::vec3& baseCenter, float bottomRadius, float topRadius, float height, int segments, int rings)
{
    // u runs up, v around: cross(up, tangent) points outward.
    addSurface(rings, segments, [=](float u, float v) {
        const float angle = glm::two_pi<float>() * v;
        const float radius = glm::mix(bottomRadius, topRadius, u);
        return baseCenter + glm::vec3(radius * std::cos(angle), height * u, radius * std::sin(angle));
    });
}

render::Mesh MeshBuilder::build(const std::string& name, int material) const
{
    render::Mesh mesh;
    mesh.name = name;
    mesh.positions = m_positions;
    mesh.normals = m_normals;
    mesh.uvs = m_uvs;
    mesh.indices = m_indices;
    mesh.material = material;
    return mesh;
}

} // namespace vct::doc
