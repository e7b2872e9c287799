#pragma once

#include "core/BrickOccupancy.h"
#include "core/FrameStats.h"
#include "scene/RenderSettings.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QString>

#include <vector>

namespace vct::cli {

/** The `--stats` document: per-pass milliseconds (median over the timed frames), voxel memory, settings. */
QJsonObject statsToJson(const std::vector<render::FrameStats>& frames, const render::RenderSettings& settings,
    const QString& scene, const QString& glDescription);
/** Brick occupancy per grid and brick size (Renderer::brickOccupancy), for `--stats`. */
QJsonArray bricksToJson(const std::vector<render::BrickOccupancy>& bricks);

} // namespace vct::cli
