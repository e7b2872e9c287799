#include "core/GpuScene.h"

#include "core/PixelClass.h"

#include <glm/gtc/matrix_inverse.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <utility>

namespace vct::render {

namespace {

Aabb worldBounds(const MeshCluster& cluster, const glm::mat4& transform)
{
    Aabb world;
    for (int corner = 0; corner < 8; ++corner)
        world.extend(glm::vec3(transform
            * glm::vec4((corner & 1) ? cluster.bounds.max.x : cluster.bounds.min.x,
                (corner & 2) ? cluster.bounds.max.y : cluster.bounds.min.y,
                (corner & 4) ? cluster.bounds.max.z : cluster.bounds.min.z, 1.0f)));
    return world;
}

// For vertices without a usable normal: the normal of a triangle that uses them, +z where none is usable.
std::vector<glm::vec3> fallbackNormals(const Mesh& mesh)
{
    std::vector<glm::vec3> normals(mesh.positions.size(), glm::vec3(0.0f, 0.0f, 1.0f));
    std::vector<bool> found(mesh.positions.size(), false);
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const std::uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
        if (a >= normals.size() || b >= normals.size() || c >= normals.size())
            continue;
        const glm::vec3 n
            = glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
        const float length = glm::length(n);
        if (!std::isfinite(length) || !(length > 0.0f))
            continue;
        for (const std::uint32_t v : { a, b, c })
            if (!found[v]) {
                normals[v] = n / length;
                found[v] = true;
            }
    }
    return normals;
}

struct Vertex {
    glm::vec3 position;
    glm::vec3 normal;
    glm::vec2 uv;
};
// dispatchTriangles() hands the vertices to compute shaders as eight floats each.
static_assert(sizeof(Vertex) == 8 * sizeof(float));

} // namespace

GpuScene::GpuScene(const Scene& scene)
    : m_scene(scene)
{
    // Negative or non-finite emission would turn into negative or NaN pixels and voxels: it emits nothing.
    for (Material& material : m_scene.materials)
        material.emission = material.usableEmission();
    for (const Mesh& mesh : m_scene.meshes) {
        std::vector<Vertex> vertices(mesh.positions.size());
        const std::vector<glm::vec3> faceNormals = fallbackNormals(mesh);
        for (std::size_t i = 0; i < vertices.size(); ++i) {
            vertices[i].position = mesh.positions[i];
            const glm::vec3 n = i < mesh.normals.size() ? mesh.normals[i] : glm::vec3(0.0f);
            const float length = glm::length(n);
            // The g-buffer relies on unit vertex normals (shaders/gbuffer/GBuffer.frag).
            vertices[i].normal = std::isfinite(length) && length > 1e-20f ? n / length : faceNormals[i];
            vertices[i].uv = i < mesh.uvs.size() ? mesh.uvs[i] : glm::vec2(0.0f);
        }
        GpuMesh gpu;
        const MeshClusters clustered(mesh.positions, mesh.indices);
        gpu.vertices = gl::Buffer(vertices.size() * sizeof(Vertex), vertices.data(), 0);
        gpu.indices
            = gl::Buffer(clustered.indices().size() * sizeof(std::uint32_t), clustered.indices().data(), 0);
        gpu.clusters = clustered.clusters();
        gpu.surface = std::make_unique<ClosedSurface>(mesh.positions, clustered.indices(), gpu.clusters);
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
        gl::Texture texture = gl::Texture::create2D(
            GL_SRGB8_ALPHA8, std::max(1, image.width), std::max(1, image.height), levels);
        if (image.width > 0 && image.height > 0
            && image.rgba.size() >= std::size_t(image.width) * image.height * 4) {
            // TextureImage rows run top to bottom and the importer flips V (aiProcess_FlipUVs): row 0 is t =
            // 0.
            glTextureSubImage2D(texture.id(), 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE,
                image.rgba.data());
            glGenerateTextureMipmap(texture.id());
        }
        texture.setWrap(GL_REPEAT);
        m_textures.push_back(std::move(texture));
    }
    m_whiteTexture = gl::Texture::create2D(GL_SRGB8_ALPHA8, 1, 1);
    const unsigned char white[4] = { 255, 255, 255, 255 };
    glTextureSubImage2D(m_whiteTexture.id(), 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, white);
    uploadMaterialTable();
    rebuildAreaLights();
}

void GpuScene::rebuildAreaLights()
{
    m_areaLights = AreaLightSet::fromScene(m_scene);
    ++m_areaLightsVersion;
    // Four rgba32f texels per light (radiance + the texel of its first triangle; sphere centre + radius;
    // area, triangle count, planar flag, shadow flag; plane normal + offset), then three per triangle (its
    // corners), as shaders/common/AreaLights.glsl reads them. A frame may light with a prefix of the lights
    // (FrameRules::areaLightCount), so each light says where its triangles are.
    std::vector<glm::vec4> entries;
    const int firstTriangleTexel = 4 * int(m_areaLights.lights.size());
    for (const AreaLight& light : m_areaLights.lights) {
        entries.emplace_back(light.radiance, float(firstTriangleTexel + 3 * light.firstTriangle));
        entries.emplace_back(light.centre, light.radius);
        entries.emplace_back(light.area, float(light.triangleCount), light.planar ? 1.0f : 0.0f,
            light.castsShadows ? 1.0f : 0.0f);
        entries.emplace_back(light.planeNormal, light.planeOffset);
    }
    for (const glm::vec3& corner : m_areaLights.triangles)
        entries.emplace_back(corner, 1.0f);
    if (entries.empty())
        entries.emplace_back(0.0f); // a buffer texture needs storage
    m_areaLightTable = gl::Buffer(entries.size() * sizeof(glm::vec4), entries.data());
    m_areaLightTableView
        = gl::Texture::createBufferView(GL_RGBA32F, m_areaLightTable.id(), int(entries.size()));
}

void GpuScene::bindAreaLightTable(GLuint unit) const
{
    m_areaLightTableView.bindUnit(unit);
}

void GpuScene::uploadMaterialTable()
{
    // Two rgba32f texels per material (shaders/common/MaterialTable.glsl): specular rgb + shininess,
    // emission.
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
        m_materialTableView
            = gl::Texture::createBufferView(GL_RGBA32F, m_materialTable.id(), int(entries.size()));
        m_materialTableBytes = bytes;
    } else {
        m_materialTable.upload(entries.data(), bytes);
    }
}

void GpuScene::bindMaterialTable(GLuint unit) const
{
    m_materialTableView.bindUnit(unit);
}

const Material& GpuScene::materialOf(std::size_t index) const
{
    static const Material fallback;
    const int material = m_scene.meshes[index].material;
    return material >= 0 && std::size_t(material) < m_scene.materials.size()
        ? m_scene.materials[std::size_t(material)]
        : fallback;
}

void GpuScene::bindMesh(const gl::Program& program, std::size_t index, GLuint albedoUnit) const
{
    const Mesh& mesh = m_scene.meshes[index];
    const bool valid = mesh.material >= 0 && std::size_t(mesh.material) < m_scene.materials.size();
    const Material& material = materialOf(index);
    program.set("uMaterialIndex", valid ? mesh.material : int(m_scene.materials.size()));
    program.set("uModel", mesh.transform);
    program.set("uNormalMatrix", glm::mat4(glm::inverseTranspose(glm::mat3(mesh.transform))));
    program.set("uAlbedo", material.albedo);
    program.set("uEmission", material.emission);
    program.set("uSpecular", material.specular);
    program.set("uShininess", material.shininess);
    const bool textured
        = material.albedoTexture >= 0 && std::size_t(material.albedoTexture) < m_textures.size();
    (textured ? m_textures[std::size_t(material.albedoTexture)] : m_whiteTexture).bindUnit(albedoUnit);
    m_meshes[index].vao.bind();
}

bool GpuScene::cullsBackFaces(std::size_t index, const Viewpoint& from) const
{
    const GpuMesh& gpu = m_meshes[index];
    const glm::mat4& transform = m_scene.meshes[index].transform;
    if (!gpu.surface->isSolid() || !(glm::determinant(glm::mat3(transform)) > 0.0f))
        return false; // a mirroring transform turns GL's notion of front faces around
    if (gpu.cullViewpoint == from.position && gpu.cullTransform == transform)
        return gpu.cullBack;
    gpu.cullViewpoint = from.position;
    gpu.cullTransform = transform;
    gpu.cullBack = false;
    // The visible part of each ray starts on the near plane: between the eye and it there must be no surface,
    // or that start could lie inside a solid the eye is outside of.
    for (const MeshCluster& cluster : gpu.clusters) {
        const Aabb world = worldBounds(cluster, transform);
        if (!(glm::length(glm::clamp(from.position, world.min, world.max) - from.position) > from.nearRadius))
            return false;
    }
    const glm::vec3 local = glm::vec3(glm::inverse(transform) * glm::vec4(from.position, 1.0f));
    const std::optional<int> winding = gpu.surface->windingNumber(local);
    gpu.cullBack = winding && *winding == 0;
    return gpu.cullBack;
}

bool GpuScene::showsFrontOnly(std::size_t index) const
{
    // A mirroring transform turns GL's notion of front faces around: draw both sides then, as before.
    return !materialOf(index).doubleSided
        && glm::determinant(glm::mat3(m_scene.meshes[index].transform)) > 0.0f;
}

std::vector<GpuScene::Run> GpuScene::runsOf(const DrawOptions& options) const
{
    std::vector<Run> runs;
    const bool perCluster = options.visibleIn || options.from;
    for (std::size_t i = 0; i < m_meshes.size(); ++i) {
        const Mesh& mesh = m_scene.meshes[i];
        if (!mesh.visible)
            continue;
        if ((options.layer == MeshFilter::Static && mesh.dynamic)
            || (options.layer == MeshFilter::Dynamic && !mesh.dynamic))
            continue;
        if (m_meshes[i].indexCount == 0)
            continue;
        if (options.materials && !options.materials(materialOf(i)))
            continue;
        if (!perCluster) {
            runs.push_back({ i, 0, std::uint32_t(m_meshes[i].indexCount), 0.0f });
            continue;
        }
        for (const MeshCluster& cluster : m_meshes[i].clusters) {
            const Aabb world = worldBounds(cluster, mesh.transform);
            if (options.visibleIn && !options.visibleIn->mayContain(world))
                continue;
            float distance = 0.0f;
            if (options.from) {
                const glm::vec3 eye = options.from->position;
                distance = glm::length(glm::clamp(eye, world.min, world.max) - eye);
                if (!std::isfinite(distance))
                    distance = 0.0f;
            }
            // Neighbouring clusters of one mesh drawn in a row become one draw.
            if (!options.from && !runs.empty() && runs.back().mesh == i
                && runs.back().firstIndex + runs.back().indexCount == cluster.firstIndex)
                runs.back().indexCount += cluster.indexCount;
            else
                runs.push_back({ i, cluster.firstIndex, cluster.indexCount, distance });
        }
    }
    if (options.from)
        std::stable_sort(
            runs.begin(), runs.end(), [](const Run& a, const Run& b) { return a.distance < b.distance; });
    return runs;
}

void GpuScene::draw(const gl::Program& program, const DrawOptions& options, GLuint albedoUnit) const
{
    program.use();
    std::size_t bound = m_meshes.size();
    for (const Run& run : runsOf(options)) {
        if (run.mesh != bound) {
            bindMesh(program, run.mesh, albedoUnit);
            if (options.stencilPixelClass)
                glStencilFunc(GL_ALWAYS, GLint(pixelClassOf(materialOf(run.mesh))), 0xFF);
            if (options.from && (cullsBackFaces(run.mesh, *options.from) || showsFrontOnly(run.mesh))) {
                glEnable(GL_CULL_FACE);
                glCullFace(GL_BACK);
            } else {
                glDisable(GL_CULL_FACE);
            }
            bound = run.mesh;
        }
        glDrawElements(GL_TRIANGLES, GLsizei(run.indexCount), GL_UNSIGNED_INT,
            reinterpret_cast<const void*>(std::uintptr_t(run.firstIndex) * sizeof(std::uint32_t)));
    }
    glDisable(GL_CULL_FACE);
    glBindVertexArray(0);
}

void GpuScene::dispatchTriangles(const gl::Program& program, const DrawOptions& options, GLuint albedoUnit,
    const TriangleDispatch& dispatch) const
{
    program.use();
    DrawOptions unordered = options;
    unordered.from = nullptr;
    const std::vector<Run> runs = runsOf(unordered);
    ListedTriangles* const listed = dispatch.listed;
    if (listed) {
        std::vector<std::size_t> meshes;
        std::vector<std::uint32_t> runTriangles;
        for (const Run& run : runs) {
            meshes.push_back(run.mesh);
            runTriangles.push_back(run.indexCount / 3);
        }
        listed->reset(std::move(meshes), runTriangles);
        listed->indices.bindBase(GL_SHADER_STORAGE_BUFFER, dispatch.vertexBinding + 2);
        listed->commands.bindBase(GL_SHADER_STORAGE_BUFFER, dispatch.vertexBinding + 3);
    }
    std::size_t bound = m_meshes.size();
    GLuint listFirst = 0;
    // A run of more triangles than maxGroups workgroups take (a scanned model of millions) goes in parts,
    // which list into the same command.
    const GLuint groupSize = std::max(dispatch.groupSize, 1u);
    const GLuint perDispatch = GLuint(std::min<std::uint64_t>(
        std::uint64_t(std::max(dispatch.maxGroups, 1u)) * groupSize, std::numeric_limits<GLuint>::max()));
    for (std::size_t i = 0; i < runs.size(); ++i) {
        const Run& run = runs[i];
        const GLuint runTriangles = run.indexCount / 3;
        if (listed) {
            program.set("uListRun", GLuint(i));
            program.set("uListFirst", listFirst);
            listFirst += 3 * runTriangles;
        }
        if (run.mesh != bound) {
            bindMesh(program, run.mesh, albedoUnit);
            const GpuMesh& gpu = m_meshes[run.mesh];
            gpu.vertices.bindBase(GL_SHADER_STORAGE_BUFFER, dispatch.vertexBinding);
            gpu.indices.bindBase(GL_SHADER_STORAGE_BUFFER, dispatch.vertexBinding + 1);
            program.set("uVertexCount", GLuint(m_scene.meshes[run.mesh].positions.size()));
            bound = run.mesh;
        }
        for (GLuint done = 0; done < runTriangles;) {
            const GLuint triangles = std::min(runTriangles - done, perDispatch);
            program.set("uFirstIndex", GLuint(run.firstIndex + 3 * done));
            program.set("uTriangleCount", triangles);
            glDispatchCompute(GLuint((std::uint64_t(triangles) + groupSize - 1) / groupSize), 1, 1);
            done += triangles;
        }
    }
    glBindVertexArray(0);
}

void GpuScene::drawListed(const gl::Program& program, const ListedTriangles& listed, GLuint albedoUnit) const
{
    program.use();
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, listed.commands.id());
    // Each mesh's vertex array takes the listed indices for its draws and gets its own back after them.
    std::size_t bound = m_meshes.size();
    for (std::size_t i = 0; i < listed.runMeshes.size(); ++i) {
        const std::size_t mesh = listed.runMeshes[i];
        if (mesh != bound) {
            if (bound < m_meshes.size())
                glVertexArrayElementBuffer(m_meshes[bound].vao.id(), m_meshes[bound].indices.id());
            bindMesh(program, mesh, albedoUnit);
            glVertexArrayElementBuffer(m_meshes[mesh].vao.id(), listed.indices.id());
            bound = mesh;
        }
        glDrawElementsIndirect(GL_TRIANGLES, GL_UNSIGNED_INT,
            reinterpret_cast<const void*>(i * ListedTriangles::kCommandWords * sizeof(std::uint32_t)));
    }
    if (bound < m_meshes.size())
        glVertexArrayElementBuffer(m_meshes[bound].vao.id(), m_meshes[bound].indices.id());
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
    glBindVertexArray(0);
}

void GpuScene::setTransform(std::size_t mesh, const glm::mat4& transform)
{
    if (mesh < m_scene.meshes.size()) {
        m_scene.meshes[mesh].transform = transform;
        if (materialOf(mesh).isEmissive())
            rebuildAreaLights();
    }
}

void GpuScene::setVisible(std::size_t mesh, bool visible)
{
    if (mesh < m_scene.meshes.size() && m_scene.meshes[mesh].visible != visible) {
        m_scene.meshes[mesh].visible = visible;
        if (materialOf(mesh).isEmissive())
            rebuildAreaLights();
    }
}

void GpuScene::setMaterial(std::size_t index, const Material& material)
{
    if (index < m_scene.materials.size()) {
        const bool emitters = m_scene.materials[index].emission != material.usableEmission();
        m_scene.materials[index] = material;
        m_scene.materials[index].emission = material.usableEmission();
        uploadMaterialTable();
        if (emitters)
            rebuildAreaLights();
    }
}

void GpuScene::setLights(const std::vector<PointLight>& points,
    const std::vector<DirectionalLight>& directionals, const std::vector<SurfaceLight>& surfaces)
{
    m_scene.pointLights = points;
    m_scene.directionalLights = directionals;
    if (surfaces != m_scene.surfaceLights) {
        m_scene.surfaceLights = surfaces;
        rebuildAreaLights();
    }
}

bool GpuScene::hasDynamicMeshes() const
{
    for (const Mesh& mesh : m_scene.meshes)
        if (mesh.dynamic && mesh.visible)
            return true;
    return false;
}

} // namespace vct::render
