#pragma once

#include "document/SceneLoadInfo.h"
#include "scene/RenderSettings.h"
#include "scene/Scene.h"

#include <QString>
#include <QStringList>

namespace vct::cli {

/**
 * Loads what a command line names: a .vctproj project (its scene, camera and settings), builtin:NAME or a
 * model file (with sibling NAME.lights.json / NAME.camera.json). Settings are only replaced by a project's.
 * `unitScale` is metres per unit of a model file (a project's sources carry their own, a built-in scene is in
 * metres). A project's relative model paths resolve against `sceneRoot`, or when it is empty against
 * $VCT_SCENE_ROOT, or when that is unset against the project's folder. A model file far from the world's
 * origin is rebased to a local one (doc::SceneRebase; scene.origin says where).
 */
bool loadSceneInput(const QString& spec, render::Scene& scene, render::RenderSettings& settings,
    doc::SceneLoadInfo& info, QString* error, float unitScale = 1.0f, const QString& sceneRoot = QString());

/** What a command renders from: the camera and the image size. */
struct ViewInput {
    render::Camera camera;
    int width = 640;
    int height = 360;
};

/**
 * Resolves the view of a loaded scene: an explicit lights file (empty path: none) replaces the scene's
 * lights; the camera and size come from the camera file (empty path: none), else from the project or scene.
 * Both files are in world coordinates and are read less scene.origin.
 */
bool resolveViewInput(const QString& lightsPath, const QString& cameraPath, const doc::SceneLoadInfo& info,
    render::Scene& scene, ViewInput& view, QString* error);

/** Applies `key=value` assignments (from --set) in order; returns an empty string or the first problem. */
QString applySettingAssignments(const QStringList& assignments, render::RenderSettings& settings);

} // namespace vct::cli
