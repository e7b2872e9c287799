#include "core/GpuScene.h"

#include <glm/gtc/matrix_inverse.hpp>

#include <cstring>

namespace vct::render {

namespace {

struct Vertex {
    glm::vec3 position;
    glm::vec3 normal;
    glm::vec2 uv;
};

} // namespace

GpuScene::GpuScene(const Scene& scene)
    : m_scene(scene)
{
    for (const Mesh& mesh : m_scene.meshes) {
        std::vector<Vertex> vertices(mesh.positions.size());
        for (std::size_t i = 0; i < vertices.size(); ++i) {
            vertices[i].position = mesh.positions[i];
            vertices[i].normal = i < mesh.normals.size() ? mesh.normals[i] : glm::vec3(0, 0, 1);
            vertices[i].uv = i < mesh.uvs.size() ? mesh.uvs[i] : glm::vec2(0.0f);
        }
        GpuMesh gpu;
        gpu.vertices = gl::Buffer(vertices.size() * sizeof(Vertex), vertices.data(), 0);
        gpu.indices = gl::Buffer(mesh.indices.size() * sizeof(std::uint32_t), mesh.indices.data(), 0);
        gpu.vao = gl::VertexArray::create();
        gpu.vao.setAttribute(0, gpu.vertices.id(), 3, sizeof(Vertex), offsetof(Vertex, position));
        gpu.vao.setAttribute(1, gpu.vertices.id(), 3, sizeof(Vertex), offsetof(Vertex, normal));
        gpu.vao.setAttribute(2, gpu.vertices.id(), 2, sizeof(Vertex), offsetof(Vertex, uv));
        gpu.vao.setIndexBuffer(gpu.indices.id());
        gpu.indexCount = GLsizei(mesh.indices.size());
        m_meshes.push_back(std::move(gpu));
    }
    for (const TextureImage& image : m_scene.textures) {
        int levels = 1;
        for (int s = std::max(image.width, image.height); s > 1; s /= 2)
            ++levels;
        gl::Texture texture = gl::Texture::create2D(GL_SRGB8_ALPHA8, std::max(1, image.width), std::max(1, image.height), levels);
        if (image.width > 0 && image.height > 0 && image.rgba.size() >= std::size_t(image.width) * image.height * 4) {
            // TextureImage rows run top to bottom and the importer flips V (aiProcess_FlipUVs): row 0 is t = 0.
            glTextureSubImage2D(texture.id(), 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
            glGenerateTextureMipmap(texture.id());
        }
        texture.setWrap(GL_REPEAT);
        m_textures.push_back(std::move(texture));
    }
    m_whiteTexture = gl::Texture::create2D(GL_SRGB8_ALPHA8, 1, 1);
    const unsigned char white[4] = {255, 255, 255, 255};
    glTextureSubImage2D(m_whiteTexture.id(), 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, white);
    uploadMaterialTable();
}

void GpuScene::uploadMaterialTable()
{
    // Two rgba32f texels per material (shaders/common/MaterialTable.glsl): specular rgb + shininess, emission.
    std::vector<glm::vec4> entries;
    const Material fallback;
    for (std::size_t i = 0; i <= m_scene.materials.size(); ++i) {
        const Material& m = i < m_scene.materials.size() ? m_scene.materials[i] : fallback;
        entries.emplace_back(m.specular, m.shininess);
        entries.emplace_back(m.emission, 0.0f);
    }
    const std::size_t bytes = entries.size() * sizeof(glm::vec4);
    if (!m_materialTable || m_materialTableBytes != bytes) {
        m_materialTable = gl::Buffer(bytes, entries.data());
        m_materialTableView = gl::Texture::createBufferView(GL_RGBA32F, m_materialTable.id(), int(entries.size()));
        m_materialTableBytes = bytes;
    } else {
        m_materialTable.upload(entries.data(), bytes);
    }
}

void GpuScene::bindMaterialTable(GLuint unit) const
{
    m_materialTableView.bindUnit(unit);
}

void GpuScene::draw(const gl::Program& program, MeshFilter filter, GLuint albedoUnit, const MaterialFilter& materials) const
{
    program.use();
    for (std::size_t i = 0; i < m_meshes.size(); ++i) {
        const Mesh& mesh = m_scene.meshes[i];
        if ((filter == MeshFilter::Static && mesh.dynamic) || (filter == MeshFilter::Dynamic && !mesh.dynamic))
            continue;
        if (m_meshes[i].indexCount == 0)
            continue;
        const Material fallback;
        const bool valid = mesh.material >= 0 && std::size_t(mesh.material) < m_scene.materials.size();
        const Material& material = valid ? m_scene.materials[std::size_t(mesh.material)] : fallback;
        if (materials && !materials(material))
            continue;
        program.set("uMaterialIndex", valid ? mesh.material : int(m_scene.materials.size()));
        program.set("uModel", mesh.transform);
        program.set("uNormalMatrix", glm::mat4(glm::inverseTranspose(glm::mat3(mesh.transform))));
        program.set("uAlbedo", material.albedo);
        program.set("uEmission", material.emission);
        program.set("uSpecular", material.specular);
        program.set("uShininess", material.shininess);
        const bool textured = material.albedoTexture >= 0 && std::size_t(material.albedoTexture) < m_textures.size();
        (textured ? m_textures[std::size_t(material.albedoTexture)] : m_whiteTexture).bindUnit(albedoUnit);
        m_meshes[i].vao.bind();
        glDrawElements(GL_TRIANGLES, m_meshes[i].indexCount, GL_UNSIGNED_INT, nullptr);
    }
    glBindVertexArray(0);
}

void GpuScene::setTransform(std::size_t mesh, const glm::mat4& transform)
{
    if (mesh < m_scene.meshes.size())
        m_scene.meshes[mesh].transform = transform;
}

void GpuScene::setMaterial(std::size_t index, const Material& material)
{
    if (index < m_scene.materials.size()) {
        m_scene.materials[index] = material;
        uploadMaterialTable();
    }
}

void GpuScene::setLights(const std::vector<PointLight>& points, const std::vector<DirectionalLight>& directionals)
{
    m_scene.pointLights = points;
    m_scene.directionalLights = directionals;
}

bool GpuScene::hasDynamicMeshes() const
{
    for (const Mesh& mesh : m_scene.meshes)
        if (mesh.dynamic)
            return true;
    return false;
}

} // namespace vct::render
