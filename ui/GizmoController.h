#pragma once

#include "TransformGizmo.h"
#include "ViewProjection.h"

#include "document/LightNode.h"
#include "document/NodeTransform.h"

#include <QPointF>

namespace vct::doc {
class Document;
}

namespace vct::ui {

/**
 * What the viewport's transform gizmo acts on and what a drag of it does to the document. The target is the
 * selected node, or without one the light chosen in the scene tree. Every drag is one undo step (the edits of
 * one gesture merge); Escape during a drag puts the target back as it was.
 *
 * Nodes move along world axes, turn about world axes through the middle of their bounds, and scale along
 * their own axes about that middle, the translation adjusted so the middle stays put. Lights: point, spot,
 * rect and disk lights move; spots, rects, disks and suns turn (their direction; a sun's gizmo sits in the
 * middle of the scene); rects and disks scale their size as a whole, point and spot lights with a size their
 * radius. A rect turns whole: its Rotation (spin about its normal) follows its width axis.
 */
class GizmoController {
public:
    explicit GizmoController(doc::Document* document);

    GizmoMode mode() const { return m_mode; }
    void setMode(GizmoMode mode) { m_mode = mode; }
    /** The light the gizmo takes when no node is selected (the scene tree's current light), or -1. */
    int selectedLight() const { return m_light; }
    void setSelectedLight(int light) { m_light = light; }

    /** The gizmo of the current target as seen through @p view; a default one (no handles) without target. */
    TransformGizmo gizmo(const ViewProjection& view) const;
    /** Starts a drag when @p at is on a handle of the gizmo; false leaves the press to the camera. */
    bool press(const ViewProjection& view, const QPointF& at);
    /**
     * The target follows the cursor to @p at. With @p snap (Ctrl held) it moves by round steps that suit the
     * zoom (the power of ten nearest an eighth of the handles' length: 0.01, 0.1, 1 m...), turns by 15
     * degrees and scales by tenths.
     */
    void drag(const QPointF& at, bool snap = false);
    /** Ends the drag as one undo step. */
    void release();
    /** Ends the drag with the target back as it was before it. */
    void cancel();
    bool dragging() const { return m_part >= 0; }
    /** The handle being dragged, or -1. */
    int activePart() const { return m_part; }

private:
    /** What the gizmo acts on now: a node (index), else a light (index), else nothing. */
    struct Target {
        int node = -1;
        int light = -1;
        glm::vec3 centre { 0.0f };
        glm::mat3 scaleAxes { 1.0f };
        unsigned parts = 0; ///< handles the target can take in the current mode (TransformGizmo's bits)
    };
    Target target() const;
    void apply(const QPointF& at, bool snap);

    doc::Document* m_document;
    GizmoMode m_mode = GizmoMode::None;
    int m_light = -1;
    // The drag in progress: the gizmo as pressed (the view does not move while a handle is held) and the
    // target as it was.
    int m_part = -1;
    TransformGizmo m_pressed;
    Target m_target;
    QPointF m_pressAt;
    doc::NodeTransform m_startTransform;
    doc::LightNode m_startLight;
};

} // namespace vct::ui
