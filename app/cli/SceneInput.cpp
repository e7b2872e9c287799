#include "cli/SceneInput.h"

#include "document/CameraFile.h"
#include "document/Document.h"
#include "document/LightsFile.h"
#include "document/ProjectFile.h"
#include "document/SceneLoader.h"

#include <QFileInfo>

namespace vct::cli {

bool loadSceneInput(const QString& spec, render::Scene& scene, render::RenderSettings& settings,
    doc::SceneLoadInfo& info, QString* error, float unitScale, const QString& sceneRoot)
{
    if (spec.endsWith(QStringLiteral(".vctproj"), Qt::CaseInsensitive)) {
        auto fail = [&](const QString& problem) {
            if (error)
                *error = problem;
            return false;
        };
        if (unitScale != 1.0f)
            return fail(
                QStringLiteral("%1: a unit scale applies to a model file; a project gives each source "
                               "its own (sources[i].unit_scale)")
                    .arg(spec));
        // The environment serves every command sharing this function, vct-bench's too, without an option
        // each.
        const bool fromOption = !sceneRoot.isEmpty();
        const QString root
            = fromOption ? sceneRoot : qEnvironmentVariable(doc::ProjectFile::kModelRootVariable);
        if (!root.isEmpty() && !QFileInfo(root).isDir())
            return fail(QStringLiteral("the scene root '%1' (from %2) is not a folder")
                            .arg(root,
                                fromOption ? QStringLiteral("--scene-root")
                                           : QLatin1String(doc::ProjectFile::kModelRootVariable)));
        doc::Document project;
        project.setModelRoot(root);
        if (!project.openProject(spec, error))
            return false;
        scene = project.buildRenderScene();
        settings = project.state().settings;
        return true;
    }
    return doc::SceneLoader::load(spec, scene, error, &info, unitScale, doc::SceneLoader::Origin::RebaseFar);
}

QString applySettingAssignments(const QStringList& assignments, render::RenderSettings& settings)
{
    // Validated together: a setting may be valid only with another one given after it.
    std::vector<std::pair<std::string, std::string>> pairs;
    for (const QString& assignment : assignments) {
        const int eq = assignment.indexOf(QLatin1Char('='));
        if (eq <= 0)
            return QStringLiteral("--set expects key=value, got '%1'").arg(assignment);
        pairs.emplace_back(assignment.left(eq).toStdString(), assignment.mid(eq + 1).toStdString());
    }
    return QString::fromStdString(settings.setAll(pairs));
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
        if (!doc::LightsFile::read(lightsPath, lit, error, scene.origin))
            return false;
        scene = std::move(lit);
    }
    view.width = info.width > 0 ? info.width : 640;
    view.height = info.height > 0 ? info.height : 360;
    view.camera = scene.camera;
    if (!cameraPath.isEmpty()) {
        doc::CameraSetup setup;
        if (!doc::CameraFile::read(cameraPath, setup, error, scene.origin))
            return false;
        view.camera = setup.camera;
        view.camera.nearPlane = doc::SceneLoader::nearPlaneFor(scene.bounds());
        view.width = setup.width;
        view.height = setup.height;
    }
    return true;
}

} // namespace vct::cli
