#pragma once

#include "TransformGizmo.h"

#include "core/FrameStats.h"
#include "scene/Camera.h"

#include <glm/vec3.hpp>

#include <QLineF>
#include <QList>
#include <QPointF>
#include <QPolygonF>
#include <QRect>
#include <QWidget>

#include <optional>
#include <utility>
#include <vector>

namespace vct::doc {
class Document;
}

namespace vct::ui {

/**
 * What the viewport draws over the image, in 2D: the selected node's box, an icon for each light (a disc for
 * point lights, with its axis for spots; the outline of rects and disks; the direction of a sun from the
 * corner), and the figures of the last frame with what the renderer is busy with (re-voxelizing, converging
 * bounces). A transparent child of the viewport: it takes no input and leaves the GL image alone.
 */
class ViewportOverlay : public QWidget {
    Q_OBJECT

public:
    ViewportOverlay(QWidget* parent, const doc::Document* document);

    /** The figures and state of the frame just drawn, into the rectangle `image` (widget pixels). */
    void showFrame(const render::FrameStats& stats, bool interactive, const QRect& image);
    /** A message in the middle of the view until the next frame is shown (a rebuild that takes a while). */
    void setBusy(const QString& text);
    QString busyText() const { return m_busy; }
    /** The text in the corner: frame size and GPU time, voxel grid and memory, and what is being rebuilt. */
    QString statusText() const { return m_status; }
    /** Where each light in front of the camera gets its icon, widget pixels. */
    QList<QPointF> lightIconPositions() const;
    /** The light whose icon is nearest @p point within @p radius pixels (suns have none), or -1. */
    int lightAt(const QPointF& point, double radius = 8.0) const;
    /** The outlines of rect and disk lights in front of the camera. */
    QList<QPolygonF> surfaceLightOutlines() const;
    /** The edges of the selected node's box that lie in front of the camera; empty without a selection. */
    QList<QLineF> selectionEdges() const;
    /** The rectangle (widget pixels) the last frame was drawn into, which the projection maps to. */
    QRect imageRect() const { return m_image; }
    /** The transform gizmo to draw, with part @p highlighted (under the cursor or being dragged) brighter. */
    void setGizmo(const TransformGizmo& gizmo, int highlighted);
    const TransformGizmo& gizmo() const { return m_gizmo; }

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    /** (light index, where its icon goes) for each light with an icon in front of the camera. */
    std::vector<std::pair<int, QPointF>> lightIcons() const;
    /** `world` on screen, or nothing when it is behind the camera. */
    std::optional<QPointF> project(const glm::vec3& world) const;

    const doc::Document* m_document;
    QRect m_image;
    QString m_status;
    QString m_busy;
    TransformGizmo m_gizmo;
    int m_gizmoHighlight = -1;
};

} // namespace vct::ui
