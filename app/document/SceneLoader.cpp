#include "SceneLoader.h"

#include "BuiltinScenes.h"
#include "CameraFile.h"
#include "Enclosure.h"
#include "LightsFile.h"
#include "SceneRebase.h"
#include "import/ModelImporter.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

#include <QDir>
#include <QFileInfo>

#include <algorithm>
#include <cmath>

namespace vct::doc {

namespace {

const QString kBuiltinPrefix = QStringLiteral("builtin:");

bool isFinite(const glm::vec3& v)
{
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

/** False when scaling pushed a coordinate or size past the float range (it was finite before). */
bool staysFinite(const render::Scene& scaled)
{
    const render::Aabb bounds = scaled.bounds();
    if (!bounds.isEmpty() && !(isFinite(bounds.min) && isFinite(bounds.max)))
        return false;
    for (const render::PointLight& p : scaled.pointLights)
        if (!isFinite(p.position) || !std::isfinite(p.radius))
            return false;
    for (const render::SurfaceLight& s : scaled.surfaceLights)
        if (!isFinite(s.centre) || !std::isfinite(s.width) || !std::isfinite(s.height))
            return false;
    return isFinite(scaled.camera.position) && isFinite(scaled.camera.lookAt)
        && std::isfinite(scaled.camera.nearPlane);
}

} // namespace

bool SceneLoader::load(const QString& spec, render::Scene& scene, QString* error, SceneLoadInfo* info,
    float unitScale, Origin origin)
{
    SceneLoadInfo localInfo;
    render::Scene result;
    auto fail = [&](const QString& problem) {
        if (error)
            *error = QStringLiteral("%1: %2").arg(QDir::toNativeSeparators(spec), problem);
        return false;
    };

    if (spec.startsWith(kBuiltinPrefix)) {
        // Their lights, camera and the goldens are tuned in metres; a scaled copy would match none of them.
        if (unitScale != 1.0f)
            return fail(QStringLiteral("built-in scenes are in metres: the unit scale must be 1, not %1")
                            .arg(double(unitScale)));
        if (!BuiltinScenes::load(spec.mid(kBuiltinPrefix.size()), result, error))
            return false;
    } else {
        if (spec.isEmpty()) {
            if (error)
                *error = QStringLiteral("no scene given: expected builtin:NAME or a model file");
            return false;
        }
        // Checked before the import, which may take seconds on a big model.
        if (const QString problem = unitScaleProblem(unitScale); !problem.isEmpty())
            return fail(problem);
        if (!ModelImporter::importModel(spec, result, error, &localInfo.report))
            return false;
        localInfo.files << spec;
        // In the model's units: the siblings are in them too.
        const glm::dvec3 localOrigin
            = origin == Origin::RebaseFar ? SceneRebase::originFor(result) : glm::dvec3(0.0);
        SceneRebase::rebase(result, localOrigin);

        const QFileInfo model(spec);
        const QString stem = model.dir().filePath(model.completeBaseName());
        const QString lightsPath = stem + QStringLiteral(".lights.json");
        if (QFileInfo::exists(lightsPath)) {
            if (!LightsFile::read(lightsPath, result, error, localOrigin))
                return false;
            localInfo.files << lightsPath;
        }
        const QString cameraPath = stem + QStringLiteral(".camera.json");
        if (QFileInfo::exists(cameraPath)) {
            CameraSetup setup;
            if (!CameraFile::read(cameraPath, setup, error, localOrigin))
                return false;
            result.camera = setup.camera;
            result.camera.nearPlane = nearPlaneFor(result.bounds());
            localInfo.hasCameraFile = true;
            localInfo.width = setup.width;
            localInfo.height = setup.height;
            localInfo.files << cameraPath;
        } else {
            result.camera = frameScene(result);
        }
        if (unitScale != 1.0f) {
            result = scaledScene(std::move(result), unitScale);
            if (!staysFinite(result))
                return fail(QStringLiteral("a unit scale of %1 m takes the model's coordinates beyond the "
                                           "range of a float")
                                .arg(double(unitScale)));
        }
    }

    scene = std::move(result);
    if (info)
        *info = std::move(localInfo);
    return true;
}

render::Scene SceneLoader::scaledScene(render::Scene scene, float unitScale)
{
    const float s = unitScale;
    const glm::mat4 scale = glm::scale(glm::mat4(1.0f), glm::vec3(s));
    for (render::Mesh& mesh : scene.meshes)
        mesh.transform = scale * mesh.transform;
    for (render::PointLight& light : scene.pointLights) {
        light.position *= s;
        light.radius *= s;
    }
    for (render::SurfaceLight& light : scene.surfaceLights) {
        light.centre *= s;
        light.width *= s;
        light.height *= s;
    }
    scene.camera.position *= s;
    scene.camera.lookAt *= s;
    // Both ways a loaded camera gets its near plane (nearPlaneFor, frameBounds) are proportional to the size.
    scene.camera.nearPlane *= s;
    scene.origin *= double(s);
    return scene;
}

glm::mat4 SceneLoader::uprightRotation(UpAxis up)
{
    // Z-up to Y-up: +z becomes +y and +y becomes -z, so x stays and handedness is kept.
    return up == UpAxis::Z ? glm::rotate(glm::mat4(1.0f), glm::radians(-90.0f), glm::vec3(1.0f, 0.0f, 0.0f))
                           : glm::mat4(1.0f);
}

render::Scene SceneLoader::uprightScene(render::Scene scene, UpAxis up)
{
    if (up == UpAxis::Y)
        return scene;
    const glm::mat4 turn = uprightRotation(up);
    const glm::mat3 turn3(turn);
    for (render::Mesh& mesh : scene.meshes)
        mesh.transform = turn * mesh.transform;
    for (render::PointLight& light : scene.pointLights) {
        light.position = turn3 * light.position;
        light.spotDirection = turn3 * light.spotDirection;
    }
    for (render::DirectionalLight& light : scene.directionalLights)
        light.direction = turn3 * light.direction;
    for (render::SurfaceLight& light : scene.surfaceLights) {
        light.centre = turn3 * light.centre;
        light.direction = turn3 * light.direction;
    }
    scene.camera.position = turn3 * scene.camera.position;
    scene.camera.lookAt = turn3 * scene.camera.lookAt;
    scene.camera.up = turn3 * scene.camera.up;
    return scene;
}

QString SceneLoader::parseUpAxis(const QString& text, UpAxis* up)
{
    const QString axis = text.trimmed().toLower();
    if (axis == QLatin1String("y") || axis == QLatin1String("+y")) {
        *up = UpAxis::Y;
        return {};
    }
    if (axis == QLatin1String("z") || axis == QLatin1String("+z")) {
        *up = UpAxis::Z;
        return {};
    }
    return QStringLiteral("expected the axis that points up in the model, y or z, not '%1'").arg(text);
}

QString SceneLoader::unitScaleProblem(float unitScale)
{
    if (std::isfinite(unitScale) && unitScale > 0.0f)
        return {};
    return QStringLiteral("the unit scale must be a finite number of metres per model unit above 0 (0.01 for "
                          "centimetres), not %1")
        .arg(double(unitScale));
}

QString SceneLoader::parseUnitScale(const QString& text, float* unitScale)
{
    bool ok = false;
    const float value = text.trimmed().toFloat(&ok);
    if (!ok)
        return QStringLiteral("expected metres per model unit as a number (0.01 for centimetres), not '%1'")
            .arg(text);
    if (QString problem = unitScaleProblem(value); !problem.isEmpty())
        return problem;
    *unitScale = value;
    return {};
}

render::Camera SceneLoader::frameScene(const render::Scene& scene)
{
    const render::Aabb bounds = scene.bounds();
    if (bounds.isEmpty() || !Enclosure::encloses(scene, bounds.center()))
        return frameBounds(bounds);
    // Inside a closed room: at its centre, looking along its longer horizontal side.
    render::Camera camera;
    camera.fovYDeg = kFramingFovYDeg;
    const glm::vec3 size = bounds.size();
    const glm::vec3 along = size.x >= size.z ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 0.0f, 1.0f);
    camera.position = bounds.center();
    camera.lookAt = camera.position + 0.25f * std::max(size.x, size.z) * along;
    camera.up = glm::vec3(0.0f, 1.0f, 0.0f);
    camera.nearPlane = nearPlaneFor(bounds);
    return camera;
}

render::Camera SceneLoader::frameBounds(const render::Aabb& bounds, float fovYDeg)
{
    render::Camera camera;
    camera.fovYDeg = fovYDeg;
    if (bounds.isEmpty())
        return camera;
    const glm::vec3 centre = bounds.center();
    // Floors only against a point-sized scene: an absolute one near real sizes would break tiny scenes.
    const float radius = std::max(0.5f * glm::length(bounds.size()), 1e-30f);
    const float distance = radius / std::sin(glm::radians(0.5f * fovYDeg));
    camera.lookAt = centre;
    camera.position = centre + glm::vec3(0.0f, 0.0f, distance);
    camera.up = glm::vec3(0.0f, 1.0f, 0.0f);
    camera.nearPlane = std::max(0.01f * (distance - radius), nearPlaneFor(bounds));
    return camera;
}

float SceneLoader::nearPlaneFor(const render::Aabb& bounds)
{
    return bounds.isEmpty() ? render::Camera {}.nearPlane
                            : std::max(1e-3f * glm::length(bounds.size()), 1e-30f);
}

} // namespace vct::doc
