#pragma once

#include "core/RenderSettings.h"
#include "document/SceneLoadInfo.h"
#include "scene/Scene.h"

#include <QString>
#include <QStringList>

namespace vct::cli {

/**
 * Loads what a command line names: a .vctproj project (its scene, camera and settings), builtin:NAME or a
 * model file (with sibling NAME.lights.json / NAME.camera.json). Settings are only replaced by a project's.
 */
bool loadSceneInput(const QString& spec, render::Scene& scene, render::RenderSettings& settings,
    doc::SceneLoadInfo& info, QString* error);

/** Applies `key=value` assignments (from --set) in order; returns an empty string or the first problem. */
QString applySettingAssignments(const QStringList& assignments, render::RenderSettings& settings);

} // namespace vct::cli
