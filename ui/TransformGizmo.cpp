#include "TransformGizmo.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace vct::ui {

namespace {

const QColor kAxisColours[3] = { QColor(235, 70, 70), QColor(90, 200, 80), QColor(70, 130, 240) };
const QColor kUniformColour(235, 235, 235);
constexpr int kRingSegments = 48;
constexpr double kSquareHalf = 4.0; ///< half the side of Scale's squares, pixels
constexpr float kLargestFactor = 1.0e3f; ///< one drag scales by at most this, or its inverse

double length(const QPointF& v)
{
    return std::hypot(v.x(), v.y());
}

double dot(const QPointF& a, const QPointF& b)
{
    return a.x() * b.x() + a.y() * b.y();
}

/** Distance from @p p to the segment a-b. */
double distanceToSegment(const QPointF& p, const QPointF& a, const QPointF& b)
{
    const QPointF ab = b - a;
    const double lengthSquared = dot(ab, ab);
    const double t = lengthSquared > 0.0 ? std::clamp(dot(p - a, ab) / lengthSquared, 0.0, 1.0) : 0.0;
    return length(p - (a + t * ab));
}

QPolygonF square(const QPointF& centre, double half)
{
    return QPolygonF({ centre + QPointF(-half, -half), centre + QPointF(half, -half),
        centre + QPointF(half, half), centre + QPointF(-half, half) });
}

} // namespace

TransformGizmo::TransformGizmo(GizmoMode mode, const glm::vec3& centre, const glm::mat3& axes,
    const ViewProjection& view, unsigned parts)
    : m_mode(mode)
    , m_centre(centre)
    , m_axes(axes)
    , m_view(view)
    , m_parts(parts)
{
    for (int i = 0; i < 3; ++i) {
        const float l = glm::length(m_axes[i]);
        m_axes[i] = l > 0.0f && std::isfinite(l) ? m_axes[i] / l : glm::vec3(i == 0, i == 1, i == 2);
    }
    m_length = float(kSizePixels) * view.metresPerPixel(centre);
    if (const std::optional<QPointF> p = view.toScreen(centre); p && m_length > 0.0f) {
        m_screenCentre = *p;
        m_onScreen = true;
    }
}

glm::vec3 TransformGizmo::axis(int part) const
{
    return part >= 0 && part < 3 ? m_axes[part] : glm::vec3(0.0f);
}

QPointF TransformGizmo::screenAxis(int part) const
{
    const std::optional<QPointF> tip = m_view.toScreen(m_centre + axis(part) * m_length);
    return tip ? *tip - m_screenCentre : QPointF();
}

std::vector<TransformGizmo::Handle> TransformGizmo::handles() const
{
    std::vector<Handle> result;
    if (!m_onScreen || m_mode == GizmoMode::None)
        return result;
    for (int part = 0; part < 3; ++part) {
        if (!(m_parts & (1u << part)))
            continue;
        Handle handle { part, {}, false, kAxisColours[part] };
        if (m_mode == GizmoMode::Rotate) {
            // The ring in the plane across the axis; it stays grabbable seen edge-on, as a line.
            const glm::vec3 a = axis(part);
            const glm::vec3 u = glm::normalize(
                std::abs(a.x) < 0.9f ? glm::cross(a, glm::vec3(1, 0, 0)) : glm::cross(a, glm::vec3(0, 1, 0)));
            const glm::vec3 v = glm::cross(a, u);
            for (int i = 0; i < kRingSegments; ++i) {
                const float angle = 2.0f * std::numbers::pi_v<float> * float(i) / float(kRingSegments);
                const std::optional<QPointF> p
                    = m_view.toScreen(m_centre + m_length * (std::cos(angle) * u + std::sin(angle) * v));
                if (!p) {
                    handle.shape.clear();
                    break;
                }
                handle.shape << *p;
            }
            handle.closed = true;
        } else {
            // A handle along an axis that points at the camera could not be dragged along: it is left out.
            const QPointF along = screenAxis(part);
            if (length(along) < 0.15 * kSizePixels)
                continue;
            const QPointF tip = m_screenCentre + along;
            handle.shape << m_screenCentre << tip;
            if (m_mode == GizmoMode::Move) {
                const QPointF unit = along / length(along), side(-unit.y(), unit.x());
                handle.shape << tip - 10.0 * unit + 4.0 * side << tip << tip - 10.0 * unit - 4.0 * side;
            } else {
                for (const QPointF& corner : square(tip, kSquareHalf))
                    handle.shape << corner;
                handle.shape << square(tip, kSquareHalf).front();
            }
        }
        if (!handle.shape.isEmpty())
            result.push_back(handle);
    }
    if (m_mode == GizmoMode::Scale && (m_parts & (1u << kUniform)))
        result.push_back({ kUniform, square(m_screenCentre, 1.5 * kSquareHalf), true, kUniformColour });
    return result;
}

int TransformGizmo::partAt(const QPointF& point) const
{
    int best = -1;
    double nearest = kGrabPixels;
    for (const Handle& handle : handles()) {
        if (handle.part == kUniform && handle.shape.containsPoint(point, Qt::OddEvenFill))
            return kUniform;
        const int n = int(handle.shape.size());
        for (int i = 0; i + 1 < n + (handle.closed ? 1 : 0); ++i) {
            const double d = distanceToSegment(point, handle.shape[i], handle.shape[(i + 1) % n]);
            if (d < nearest) {
                nearest = d;
                best = handle.part;
            }
        }
    }
    return best;
}

glm::vec3 TransformGizmo::translation(int part, const QPointF& from, const QPointF& to) const
{
    const QPointF along = screenAxis(part);
    const double lengthSquared = dot(along, along);
    if (!m_onScreen || lengthSquared <= 0.0)
        return glm::vec3(0.0f);
    // The axis's tip is m_length away in the world and `along` away on screen: the cursor's progress along it
    // scales by that ratio.
    return axis(part) * (m_length * float(dot(to - from, along) / lengthSquared));
}

float TransformGizmo::rotationDeg(int part, const QPointF& from, const QPointF& to) const
{
    if (m_mode != GizmoMode::Rotate)
        return 0.0f;
    for (const Handle& handle : handles()) {
        if (handle.part != part)
            continue;
        // The ring is drawn in order of a positive turn about the axis: its segment nearest the press gives
        // the way the cursor turns it.
        const int n = int(handle.shape.size());
        QPointF direction;
        double nearest = std::numeric_limits<double>::infinity();
        for (int i = 0; i < n; ++i) {
            const QPointF a = handle.shape[i], b = handle.shape[(i + 1) % n];
            const double d = distanceToSegment(from, a, b);
            if (d < nearest && length(b - a) > 1e-6) {
                nearest = d;
                direction = (b - a) / length(b - a);
            }
        }
        return float(glm::degrees(dot(to - from, direction) / kSizePixels));
    }
    return 0.0f;
}

float TransformGizmo::scaleFactor(int part, const QPointF& from, const QPointF& to) const
{
    if (!m_onScreen)
        return 1.0f;
    double before = 0.0, after = 0.0;
    if (part == kUniform) {
        before = length(from - m_screenCentre);
        after = length(to - m_screenCentre);
    } else {
        const QPointF along = screenAxis(part);
        if (length(along) <= 0.0)
            return 1.0f;
        const QPointF unit = along / length(along);
        before = dot(from - m_screenCentre, unit);
        after = dot(to - m_screenCentre, unit);
    }
    // A press right on the centre has nothing to compare with; past the centre the factor would turn
    // negative.
    if (std::abs(before) < 1.0)
        return 1.0f;
    return std::clamp(float(after / before), 1.0f / kLargestFactor, kLargestFactor);
}

} // namespace vct::ui
