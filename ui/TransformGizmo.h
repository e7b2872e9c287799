#pragma once

#include "ViewProjection.h"

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include <QColor>
#include <QPointF>
#include <QPolygonF>

#include <vector>

namespace vct::ui {

/** Which handles the viewport shows for the selection (W / E / R, Q for none, as in Godot and Unity). */
enum class GizmoMode { None, Move, Rotate, Scale };

/**
 * The handles the viewport draws for moving, rotating and scaling the selection: an arrow along each world
 * axis (Move), a ring about each world axis (Rotate), a line to a square along each of the object's own axes
 * and a square in the middle for all three at once (Scale). Pure screen geometry, no GL and no document:
 * where each handle is drawn, which one is under the cursor, and what dragging one between two points means
 * in the world. The handles keep one size on screen, kSizePixels, wherever the object is.
 */
class TransformGizmo {
public:
    static constexpr int kUniform = 3; ///< the part of Scale's middle square: every axis at once
    static constexpr double kSizePixels = 80.0;
    static constexpr double kGrabPixels = 7.0; ///< how near the cursor must be to a handle to take it
    static constexpr unsigned kAllParts = 0xF;

    struct Handle {
        int part = -1; ///< axis 0..2, or kUniform
        QPolygonF shape; ///< widget pixels: a polyline, closed for rings and squares
        bool closed = false;
        QColor colour;
    };

    TransformGizmo() = default;
    /**
     * @p axes: the directions of parts 0..2 as columns (world axes to move and rotate along, the object's own
     * to scale along); @p parts: a bit per part the selection can take (a sun cannot be moved, a point light
     * only scaled as a whole).
     */
    TransformGizmo(GizmoMode mode, const glm::vec3& centre, const glm::mat3& axes, const ViewProjection& view,
        unsigned parts = kAllParts);

    GizmoMode mode() const { return m_mode; }
    const glm::vec3& centre() const { return m_centre; }
    /** World metres the handles span on screen (kSizePixels at the centre's depth). */
    float worldSize() const { return m_length; }
    /** Unit direction of part 0..2. */
    glm::vec3 axis(int part) const;
    /** The handles on screen; empty when the centre is behind the camera or the mode is None. */
    std::vector<Handle> handles() const;
    /** The part whose handle is within kGrabPixels of @p point, the nearest if several; -1 for none. */
    int partAt(const QPointF& point) const;

    /** World offset of moving part @p part from @p from to @p to: along its axis, following the cursor. */
    glm::vec3 translation(int part, const QPointF& from, const QPointF& to) const;
    /**
     * Degrees about part @p part's axis (right-handed) of a drag from @p from, a point on its ring, to @p to:
     * the cursor's progress along the ring's direction at @p from, over the ring's radius. Unlike the angle
     * swept around the centre, this also turns a ring seen edge-on, which is a line on screen.
     */
    float rotationDeg(int part, const QPointF& from, const QPointF& to) const;
    /** The factor of scaling by part @p part from @p from to @p to: distances from the centre, compared. */
    float scaleFactor(int part, const QPointF& from, const QPointF& to) const;

private:
    /** Screen offset from the centre to the tip of part @p part's axis (zero when it points at the camera).
     */
    QPointF screenAxis(int part) const;

    GizmoMode m_mode = GizmoMode::None;
    glm::vec3 m_centre { 0.0f };
    glm::mat3 m_axes { 1.0f };
    ViewProjection m_view;
    unsigned m_parts = kAllParts;
    float m_length = 0.0f; ///< world metres of kSizePixels at the centre
    QPointF m_screenCentre;
    bool m_onScreen = false;
};

} // namespace vct::ui
