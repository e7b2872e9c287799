#include "cli/SceneInput.h"

#include "document/CameraFile.h"
#include "document/Document.h"
#include "document/LightsFile.h"
#include "document/SceneLoader.h"

namespace vct::cli {

bool loadSceneInput(const QString& spec, render::Scene& scene, render::RenderSettings& settings,
    doc::SceneLoadInfo& info, QString* error)
{
    if (spec.endsWith(QStringLiteral(".vctproj"), Qt::CaseInsensitive)) {
        doc::Document project;
        if (!project.openProject(spec, error))
            return false;
        scene = project.buildRenderScene();
        settings = project.state().settings;
        return true;
    }
    return doc::SceneLoader::load(spec, scene, error, &info);
}

QString applySettingAssignments(const QStringList& assignments, render::RenderSettings& settings)
{
    for (const QString& assignment : assignments) {
        const int eq = assignment.indexOf(QLatin1Char('='));
        if (eq <= 0)
            return QStringLiteral("--set expects key=value, got '%1'").arg(assignment);
        const std::string problem
            = settings.set(assignment.left(eq).toStdString(), assignment.mid(eq + 1).toStdString());
        if (!problem.empty())
            return QString::fromStdString(problem);
    }
    return {};
}

bool resolveViewInput(const QString& lightsPath, const QString& cameraPath, const doc::SceneLoadInfo& info,
    render::Scene& scene, ViewInput& view, QString* error)
{
    if (!lightsPath.isEmpty()) {
        // Replaces the lights of the scene (or of a sibling NAME.lights.json); the scene is untouched on
        // error.
        render::Scene lit = scene;
        lit.pointLights.clear();
        lit.directionalLights.clear();
        lit.surfaceLights.clear();
        if (!doc::LightsFile::read(lightsPath, lit, error))
            return false;
        scene = std::move(lit);
    }
    view.width = info.width > 0 ? info.width : 640;
    view.height = info.height > 0 ? info.height : 360;
    view.camera = scene.camera;
    if (!cameraPath.isEmpty()) {
        doc::CameraSetup setup;
        if (!doc::CameraFile::read(cameraPath, setup, error))
            return false;
        view.camera = setup.camera;
        view.camera.nearPlane = doc::SceneLoader::nearPlaneFor(scene.bounds());
        view.width = setup.width;
        view.height = setup.height;
    }
    return true;
}

} // namespace vct::cli
