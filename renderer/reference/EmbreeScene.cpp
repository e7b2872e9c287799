#include "reference/EmbreeScene.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec4.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

namespace vct::render {

namespace {

bool isFinite(const glm::vec3& v)
{
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

std::string deviceError(RTCDevice device)
{
    return "Embree error code " + std::to_string(int(rtcGetDeviceError(device)));
}

} // namespace

EmbreeScene::EmbreeScene(const Scene& scene)
{
    flatten(scene);
    m_device = rtcNewDevice(nullptr);
    if (!m_device)
        throw std::runtime_error("cannot create an Embree device: " + deviceError(nullptr));
    m_scene = rtcNewScene(m_device);
    if (!m_scene) {
        const std::string message = "cannot create an Embree scene: " + deviceError(m_device);
        rtcReleaseDevice(m_device);
        throw std::runtime_error(message);
    }
    // Watertight intersection: a reference must not leak light through shared edges.
    rtcSetSceneFlags(m_scene, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(m_scene, RTC_BUILD_QUALITY_HIGH);
    if (!m_triangles.empty()) {
        RTCGeometry geometry = rtcNewGeometry(m_device, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0,
            RTC_FORMAT_FLOAT3, 3 * sizeof(float), 3 * m_triangles.size()));
        auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
            geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), m_triangles.size()));
        if (!vertices || !indices) {
            rtcReleaseGeometry(geometry);
            const std::string message = "cannot allocate Embree buffers: " + deviceError(m_device);
            rtcReleaseScene(m_scene);
            rtcReleaseDevice(m_device);
            throw std::runtime_error(message);
        }
        for (std::size_t t = 0; t < m_triangles.size(); ++t)
            for (std::size_t k = 0; k < 3; ++k) {
                for (int c = 0; c < 3; ++c)
                    vertices[(3 * t + k) * 3 + std::size_t(c)] = m_triangles[t].vertices[k][c];
                indices[3 * t + k] = unsigned(3 * t + k);
            }
        rtcCommitGeometry(geometry);
        rtcAttachGeometry(m_scene, geometry);
        rtcReleaseGeometry(geometry); // the scene holds its own reference
    }
    rtcCommitScene(m_scene);
    if (rtcGetDeviceError(m_device) != RTC_ERROR_NONE) {
        const std::string message = "cannot build the Embree scene: " + deviceError(m_device);
        rtcReleaseScene(m_scene);
        rtcReleaseDevice(m_device);
        throw std::runtime_error(message);
    }
}

EmbreeScene::~EmbreeScene()
{
    rtcReleaseScene(m_scene);
    rtcReleaseDevice(m_device);
}

void EmbreeScene::flatten(const Scene& scene)
{
    m_materials = scene.materials;
    m_materials.push_back(Material {});
    const int fallbackMaterial = int(m_materials.size()) - 1;
    for (const Mesh& mesh : scene.meshes) {
        const glm::mat3 normalMatrix = glm::inverseTranspose(glm::mat3(mesh.transform));
        const bool hasNormals = mesh.normals.size() == mesh.positions.size();
        const bool hasUvs = mesh.uvs.size() == mesh.positions.size();
        const int material
            = mesh.material >= 0 && mesh.material < fallbackMaterial ? mesh.material : fallbackMaterial;
        for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
            SceneTriangle triangle;
            triangle.material = material;
            bool valid = true;
            for (std::size_t k = 0; k < 3; ++k) {
                const std::uint32_t index = mesh.indices[i + k];
                if (index >= mesh.positions.size()) {
                    valid = false;
                    break;
                }
                triangle.vertices[k] = glm::vec3(mesh.transform * glm::vec4(mesh.positions[index], 1.0f));
                triangle.normals[k] = hasNormals ? normalMatrix * mesh.normals[index] : glm::vec3(0.0f);
                triangle.uvs[k] = hasUvs ? mesh.uvs[index] : glm::vec2(0.0f);
            }
            if (!valid) {
                ++m_droppedTriangles;
                continue;
            }
            const glm::vec3 cross = glm::cross(
                triangle.vertices[1] - triangle.vertices[0], triangle.vertices[2] - triangle.vertices[0]);
            const float length = glm::length(cross);
            const glm::vec3 normal = cross / length;
            if (!(length > 0.0f) || !std::isfinite(length) || !isFinite(normal)
                || !isFinite(triangle.vertices[0]) || !isFinite(triangle.vertices[1])
                || !isFinite(triangle.vertices[2])) {
                ++m_droppedTriangles;
                continue;
            }
            triangle.geometricNormal = normal;
            triangle.area = 0.5f * length;
            for (glm::vec3& n : triangle.normals) {
                const float nLength = glm::length(n);
                n = nLength > 0.0f && std::isfinite(nLength) ? n / nLength : normal;
            }
            m_triangles.push_back(triangle);
        }
    }
}

std::optional<EmbreeScene::Hit> EmbreeScene::intersect(
    const glm::vec3& origin, const glm::vec3& direction, float maxDistance) const
{
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit query {};
    query.ray.org_x = origin.x;
    query.ray.org_y = origin.y;
    query.ray.org_z = origin.z;
    query.ray.dir_x = direction.x;
    query.ray.dir_y = direction.y;
    query.ray.dir_z = direction.z;
    query.ray.tnear = 0.0f;
    query.ray.tfar = maxDistance;
    query.ray.mask = ~0u;
    query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    query.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(m_scene, &context, &query);
    if (query.hit.geomID == RTC_INVALID_GEOMETRY_ID)
        return std::nullopt;
    return Hit { query.hit.primID, query.ray.tfar, query.hit.u, query.hit.v };
}

bool EmbreeScene::occluded(const glm::vec3& origin, const glm::vec3& direction, float maxDistance) const
{
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay ray {};
    ray.org_x = origin.x;
    ray.org_y = origin.y;
    ray.org_z = origin.z;
    ray.dir_x = direction.x;
    ray.dir_y = direction.y;
    ray.dir_z = direction.z;
    ray.tnear = 0.0f;
    ray.tfar = maxDistance;
    ray.mask = ~0u;
    rtcOccluded1(m_scene, &context, &ray);
    // Embree marks an occluded ray by setting tfar to -infinity.
    return ray.tfar < 0.0f;
}

} // namespace vct::render
