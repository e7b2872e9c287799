#pragma once

#include "scene/Mesh.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace vct::doc {

/**
 * Accumulates triangles for procedural geometry (metres). Every helper emits counter-clockwise front faces
 * whose vertex normals point to the front side, so callers only say which way a surface faces.
 */
class MeshBuilder {
public:
    /** A parametric surface over (u, v) in [0,1]^2; its front is the side cross(dP/du, dP/dv) points to. */
    using SurfaceFunction = std::function<glm::vec3(float u, float v)>;

    std::uint32_t addVertex(
        const glm::vec3& position, const glm::vec3& normal, const glm::vec2& uv = glm::vec2(0.0f));
    /** Indices of addVertex, counter-clockwise seen from the front. */
    void addTriangle(std::uint32_t a, std::uint32_t b, std::uint32_t c);
    /** A flat quad given by its corners in order around the boundary (either direction); its front faces
     * `facing`. */
    void addQuad(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2, const glm::vec3& p3,
        const glm::vec3& facing);
    /** Like the flat addQuad, with one normal per corner (smooth surfaces); the front faces their sum. */
    void addQuad(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2, const glm::vec3& p3,
        const glm::vec3& n0, const glm::vec3& n1, const glm::vec3& n2, const glm::vec3& n3);
    /** A grid of segmentsU x segmentsV cells over `position`, with smooth normals taken from its derivatives.
     */
    void addSurface(int segmentsU, int segmentsV, const SurfaceFunction& position);
    /** The parallelogram origin + s*u + t*v, s,t in [0,1], facing cross(u, v), split into cells. */
    void addGrid(
        const glm::vec3& origin, const glm::vec3& u, const glm::vec3& v, int segmentsU, int segmentsV);
    /** An axis-aligned box with outward faces, each split into cells no longer than `maxCell` metres per
     * side. */
    void addBox(const glm::vec3& min, const glm::vec3& max, float maxCell);
    /**
     * The open side of a cone frustum around +Y: radius `bottomRadius` at `baseCenter`, `topRadius` at
     * `height` metres above, `segments` around and `rings` up; outward normals. No caps.
     */
    void addFrustum(const glm::vec3& baseCenter, float bottomRadius, float topRadius, float height,
        int segments, int rings);

    std::size_t triangleCount() const { return m_indices.size() / 3; }
    bool isEmpty() const { return m_indices.empty(); }
    /** The accumulated triangles as a mesh with identity transform. */
    render::Mesh build(const std::string& name, int material) const;

private:
    std::vector<glm::vec3> m_positions;
    std::vector<glm::vec3> m_normals;
    std::vector<glm::vec2> m_uvs;
    std::vector<std::uint32_t> m_indices;
};

} // namespace vct::doc
