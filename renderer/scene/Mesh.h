#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace vct::render {

/** An indexed triangle mesh with one material. Positions are in object space, metres. */
struct Mesh {
    std::string name;
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals; ///< Per vertex, unit length; same count as positions.
    std::vector<glm::vec2> uvs; ///< Empty, or one per vertex.
    std::vector<std::uint32_t> indices; ///< Three per triangle, counter-clockwise front faces.
    int material = 0; ///< Index into Scene::materials.
    glm::mat4 transform { 1.0f }; ///< Object to world.
    bool dynamic = false; ///< Re-voxelized when it moves; kept out of the static voxels.
    /// Hidden meshes stay uploaded (showing one again costs no upload) but are drawn, voxelized, lit and
    /// counted nowhere: every reader of Scene::meshes skips them.
    bool visible = true;

    std::size_t triangleCount() const { return indices.size() / 3; }
};

} // namespace vct::render
