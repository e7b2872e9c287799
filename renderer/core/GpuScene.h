#pragma once

#include "gl/Buffer.h"
#include "gl/Program.h"
#include "gl/Texture.h"
#include "gl/VertexArray.h"
#include "scene/Scene.h"

#include <functional>
#include <vector>

namespace vct::render {

/** Texture unit of the material table in the passes that read the g-buffer (MATERIAL_TABLE_UNIT). */
constexpr GLuint kMaterialTableUnit = 3;

/** Which meshes a draw covers: the voxelizer draws static and dynamic meshes into separate layers. */
enum class MeshFilter { All, Static, Dynamic };

/** A further choice of meshes by their material, so a pass can draw each kind with its own shader variant. */
using MaterialFilter = std::function<bool(const Material&)>;

/** The scene's meshes, materials and textures on the GPU. Created with a current context. */
class GpuScene {
public:
    explicit GpuScene(const Scene& scene);

    /**
     * Draws every mesh passing the filter with `program` bound, setting the per-mesh uniforms the shaders in
     * shaders/common/Material.glsl read (uModel, uNormalMatrix, material fields) and binding the albedo texture
     * at unit `albedoUnit`.
     */
    void draw(const gl::Program& program, MeshFilter filter, GLuint albedoUnit, const MaterialFilter& materials = {}) const;
    /**
     * Binds the material table (shaders/common/MaterialTable.glsl) to texture unit `unit`: the per-material
     * values the g-buffer does not store per pixel, found through the material index it does.
     */
    void bindMaterialTable(GLuint unit) const;
    void setTransform(std::size_t mesh, const glm::mat4& transform);
    void setMaterial(std::size_t index, const Material& material);
    void setLights(const std::vector<PointLight>& points, const std::vector<DirectionalLight>& directionals);
    const Scene& scene() const { return m_scene; }
    std::size_t meshCount() const { return m_meshes.size(); }
    bool hasDynamicMeshes() const;

private:
    struct GpuMesh {
        gl::Buffer vertices;
        gl::Buffer indices;
        gl::VertexArray vao;
        GLsizei indexCount = 0;
    };
    void uploadMaterialTable();

    Scene m_scene; // a copy: transforms and materials change through setters, meshes never
    std::vector<GpuMesh> m_meshes;
    std::vector<gl::Texture> m_textures;
    gl::Texture m_whiteTexture;
    gl::Buffer m_materialTable; // one entry per material, then the fallback for meshes without a valid one
    gl::Texture m_materialTableView; // rgba32f buffer texture over m_materialTable
    std::size_t m_materialTableBytes = 0;
};

} // namespace vct::render
