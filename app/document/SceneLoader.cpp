#include "SceneLoader.h"

#include "BuiltinScenes.h"
#include "CameraFile.h"
#include "LightsFile.h"
#include "ModelImporter.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <QDir>
#include <QFileInfo>

#include <algorithm>
#include <cmath>

namespace vct::doc {

namespace {

const QString kBuiltinPrefix = QStringLiteral("builtin:");

} // namespace

bool SceneLoader::load(const QString& spec, render::Scene& scene, QString* error, SceneLoadInfo* info)
{
    SceneLoadInfo localInfo;
    render::Scene result;

    if (spec.startsWith(kBuiltinPrefix)) {
        if (!BuiltinScenes::load(spec.mid(kBuiltinPrefix.size()), result, error))
            return false;
    } else {
        if (spec.isEmpty()) {
            if (error)
                *error = QStringLiteral("no scene given: expected builtin:NAME or a model file");
            return false;
        }
        if (!ModelImporter::importModel(spec, result, error, &localInfo.report))
            return false;
        localInfo.files << spec;

        const QFileInfo model(spec);
        const QString stem = model.dir().filePath(model.completeBaseName());
        const QString lightsPath = stem + QStringLiteral(".lights.json");
        if (QFileInfo::exists(lightsPath)) {
            if (!LightsFile::read(lightsPath, result, error))
                return false;
            localInfo.files << lightsPath;
        }
        const QString cameraPath = stem + QStringLiteral(".camera.json");
        if (QFileInfo::exists(cameraPath)) {
            CameraSetup setup;
            if (!CameraFile::read(cameraPath, setup, error))
                return false;
            result.camera = setup.camera;
            result.camera.nearPlane = nearPlaneFor(result.bounds());
            localInfo.hasCameraFile = true;
            localInfo.width = setup.width;
            localInfo.height = setup.height;
            localInfo.files << cameraPath;
        } else {
            result.camera = frameBounds(result.bounds());
        }
    }

    scene = std::move(result);
    if (info)
        *info = std::move(localInfo);
    return true;
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
