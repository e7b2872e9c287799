#include "GizmoController.h"

#include "document/Document.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace vct::ui {

namespace {

// The Transform panel's and the Light panel's ranges: a drag never makes a value they would refuse.
constexpr float kMinScale = 1.0e-4f;
constexpr float kMaxScale = 1.0e4f;
constexpr float kMinLightSize = 1.0e-3f;
constexpr float kMaxLightSize = 1.0e3f;
constexpr float kSnapDegrees = 15.0f;

glm::mat3 rotationOf(const doc::NodeTransform& t)
{
    doc::NodeTransform rotationOnly;
    rotationOnly.rotationDeg = t.rotationDeg;
    return glm::mat3(rotationOnly.matrix());
}

/** Degrees (x, y, z) of R = Rz * Ry * Rx, the order of NodeTransform::matrix(). */
glm::vec3 eulerDegrees(const glm::mat3& r)
{
    // glm is column-major: r[column][row].
    const float sinY = std::clamp(-r[0][2], -1.0f, 1.0f);
    const float y = std::asin(sinY);
    float x = 0.0f, z = 0.0f;
    if (std::abs(sinY) < 0.9999f) {
        x = std::atan2(r[1][2], r[2][2]);
        z = std::atan2(r[0][1], r[0][0]);
    } else {
        z = std::atan2(-r[1][0], r[1][1]); // gimbal lock: the turn about x folds into z
    }
    return glm::degrees(glm::vec3(x, y, z));
}

glm::mat3 turn(const glm::vec3& axis, float degrees)
{
    return glm::mat3(glm::rotate(glm::mat4(1.0f), glm::radians(degrees), axis));
}

} // namespace

GizmoController::GizmoController(doc::Document* document)
    : m_document(document)
{
}

GizmoController::Target GizmoController::target() const
{
    Target t;
    const doc::DocumentState& state = m_document->state();
    const int node = m_document->selectedNode();
    if (node >= 0 && std::size_t(node) < state.nodes.size()) {
        t.node = node;
        const doc::NodeTransform& transform = state.nodes[std::size_t(node)].transform;
        const render::Aabb bounds = m_document->nodeWorldBounds(node);
        t.centre = bounds.isEmpty() ? transform.translation : bounds.center();
        t.scaleAxes = rotationOf(transform);
        t.parts = TransformGizmo::kAllParts;
        return t;
    }
    if (m_light < 0 || std::size_t(m_light) >= state.lights.size())
        return t;
    const doc::LightNode& light = state.lights[std::size_t(m_light)];
    t.light = m_light;
    const bool directional = light.type == doc::LightType::Directional;
    const render::Aabb scene = m_document->sceneBounds();
    t.centre = directional ? (scene.isEmpty() ? glm::vec3(0.0f) : scene.center()) : light.position;
    const unsigned axes = 0x7, uniform = 1u << TransformGizmo::kUniform;
    switch (m_mode) {
    case GizmoMode::Move:
        t.parts = directional ? 0 : axes;
        break;
    case GizmoMode::Rotate:
        t.parts = light.type == doc::LightType::Point ? 0 : axes;
        break;
    case GizmoMode::Scale:
        t.parts = light.isSurface() || (light.isPointLike() && light.radius > 0.0f) ? uniform : 0;
        break;
    case GizmoMode::None:
        break;
    }
    return t;
}

TransformGizmo GizmoController::gizmo(const ViewProjection& view) const
{
    // Without handles nothing is looked up (the target's bounds read every vertex of its mesh).
    if (m_mode == GizmoMode::None)
        return {};
    const Target t = target();
    if ((t.node < 0 && t.light < 0) || t.parts == 0)
        return {};
    // Moving and turning go along the world's axes; scaling along the object's own, the ones its scale
    // factors belong to.
    return TransformGizmo(
        m_mode, t.centre, m_mode == GizmoMode::Scale ? t.scaleAxes : glm::mat3(1.0f), view, t.parts);
}

bool GizmoController::press(const ViewProjection& view, const QPointF& at)
{
    const TransformGizmo pressed = gizmo(view);
    const int part = pressed.partAt(at);
    if (part < 0)
        return false;
    m_pressed = pressed;
    m_target = target();
    m_part = part;
    m_pressAt = at;
    if (m_target.node >= 0)
        m_startTransform = m_document->state().nodes[std::size_t(m_target.node)].transform;
    else
        m_startLight = m_document->state().lights[std::size_t(m_target.light)];
    return true;
}

void GizmoController::drag(const QPointF& at, bool snap)
{
    if (m_part < 0)
        return;
    apply(at, snap);
}

void GizmoController::apply(const QPointF& at, bool snap)
{
    const glm::vec3 centre = m_target.centre;
    const GizmoMode mode = m_pressed.mode();
    glm::vec3 move = mode == GizmoMode::Move ? m_pressed.translation(m_part, m_pressAt, at) : glm::vec3(0.0f);
    float turnDeg = mode == GizmoMode::Rotate ? m_pressed.rotationDeg(m_part, m_pressAt, at) : 0.0f;
    float factor = mode == GizmoMode::Scale ? m_pressed.scaleFactor(m_part, m_pressAt, at) : 1.0f;
    if (snap) {
        const float step
            = std::pow(10.0f, std::round(std::log10(std::max(m_pressed.worldSize(), 1e-6f) / 8.0f)));
        const glm::vec3 axis = m_pressed.axis(m_part);
        move = axis * (std::round(glm::dot(move, axis) / step) * step);
        turnDeg = std::round(turnDeg / kSnapDegrees) * kSnapDegrees;
        factor = std::max(std::round(factor * 10.0f) / 10.0f, 0.1f);
    }
    if (m_target.node >= 0) {
        doc::NodeTransform t = m_startTransform;
        if (mode == GizmoMode::Move) {
            t.translation += move;
        } else if (mode == GizmoMode::Rotate) {
            // About the middle of the bounds: M' = C R C^-1 M, so T' = c + R (T - c) and the rotation goes
            // in front of the node's own.
            const glm::mat3 r = turn(m_pressed.axis(m_part), turnDeg);
            t.translation = centre + r * (t.translation - centre);
            t.rotationDeg = eulerDegrees(r * rotationOf(t));
        } else if (mode == GizmoMode::Scale) {
            glm::vec3 factors(1.0f);
            if (m_part == TransformGizmo::kUniform)
                factors = glm::vec3(factor);
            else
                factors[m_part] = factor;
            factors = glm::clamp(t.scale * factors, kMinScale, kMaxScale) / t.scale;
            // Along the node's own axes about the middle: T' = c + R D R^-1 (T - c), S' = D S.
            const glm::mat3 r = rotationOf(t);
            const glm::vec3 local = glm::transpose(r) * (t.translation - centre);
            t.translation = centre + r * (factors * local);
            t.scale *= factors;
        }
        m_document->setNodeTransform(m_target.node, t, doc::NodeTransformField::Whole);
        return;
    }
    doc::LightNode light = m_startLight;
    if (mode == GizmoMode::Move) {
        light.position += move;
    } else if (mode == GizmoMode::Rotate) {
        const glm::mat3 r = turn(m_pressed.axis(m_part), turnDeg);
        glm::vec3 width, height, front;
        const bool hasAxes = light.isSurface() && light.surfaceLight().axes(width, height, front);
        light.direction = r * light.direction;
        // A rect turns whole: its spin about its own normal (areaRotationDeg, measured from the horizontal
        // across its direction) follows the turned width axis, so it does not swing about as it faces anew.
        render::SurfaceLight facing = light.surfaceLight();
        facing.rotationDeg = 0.0f;
        glm::vec3 horizontal, across, newFront;
        if (hasAxes && facing.axes(horizontal, across, newFront)) {
            const glm::vec3 turnedWidth = r * width;
            light.areaRotationDeg
                = glm::degrees(std::atan2(glm::dot(turnedWidth, across), glm::dot(turnedWidth, horizontal)));
        }
    } else if (mode == GizmoMode::Scale) {
        const auto scaled
            = [factor](float size) { return std::clamp(size * factor, kMinLightSize, kMaxLightSize); };
        if (light.isSurface()) {
            light.areaWidth = scaled(light.areaWidth);
            light.areaHeight = scaled(light.areaHeight);
        } else {
            light.radius = scaled(light.radius);
        }
    }
    m_document->setLight(m_target.light, light, doc::LightField::Whole);
}

void GizmoController::release()
{
    if (m_part < 0)
        return;
    m_part = -1;
    m_document->endEditGesture();
}

void GizmoController::cancel()
{
    if (m_part < 0)
        return;
    if (m_target.node >= 0)
        m_document->setNodeTransform(m_target.node, m_startTransform, doc::NodeTransformField::Whole);
    else
        m_document->setLight(m_target.light, m_startLight, doc::LightField::Whole);
    release();
}

} // namespace vct::ui
