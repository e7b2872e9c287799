#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>

namespace vct::render {

/** One triangle of the flattened scene, in world space (metres), with what shading needs at its corners. */
struct SceneTriangle {
    std::array<glm::vec3, 3> vertices; ///< Counter-clockwise seen from the front, as Mesh::indices.
    std::array<glm::vec3, 3> normals; ///< Unit shading normals; the geometric normal when the mesh has none.
    std::array<glm::vec2, 3> uvs; ///< Texture coordinates; zero when the mesh has none.
    glm::vec3 geometricNormal { 0.0f }; ///< Unit, pointing out of the front (emitting) face.
    float area = 0.0f; ///< m^2.
    int material = 0; ///< Index into EmbreeScene::materials().

    /** Interpolates corner values with Embree's barycentrics: value = (1-u-v) c0 + u c1 + v c2. */
    template <typename T> static T interpolate(const std::array<T, 3>& corners, float u, float v)
    {
        return (1.0f - u - v) * corners[0] + u * corners[1] + v * corners[2];
    }
};

} // namespace vct::render
