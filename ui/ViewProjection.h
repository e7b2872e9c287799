#pragma once

#include "scene/Camera.h"

#include <glm/vec3.hpp>

#include <QPointF>
#include <QRectF>

#include <optional>

namespace vct::ui {

/**
 * Where world points land in the viewport's image: the camera of the document and the rectangle (widget
 * pixels) the frame was drawn into. Shared by the overlay's icons and outlines and the transform gizmo, so
 * that what is drawn and what is grabbed agree.
 */
struct ViewProjection {
    render::Camera camera;
    QRectF image;

    /** `world` on screen, or nothing when it is behind the camera (or the image is empty). */
    std::optional<QPointF> toScreen(const glm::vec3& world) const;
    /** World metres that one pixel spans at the view depth of `world` (0 behind the camera). */
    float metresPerPixel(const glm::vec3& world) const;
};

} // namespace vct::ui
