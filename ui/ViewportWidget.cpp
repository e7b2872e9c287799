#include "ViewportWidget.h"

#include "CameraController.h"
#include "NonFiniteOverlay.h"
#include "ViewportOverlay.h"

#include "Renderer.h"
#include "document/Document.h"
#include "scene/CameraBasis.h"
#include "sync/NodePicker.h"
#include "sync/SceneSync.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <QEnterEvent>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QWheelEvent>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace vct::ui {

namespace {

void* qtProcAddress(const char* name)
{
    QOpenGLContext* context = QOpenGLContext::currentContext();
    return context ? reinterpret_cast<void*>(context->getProcAddress(name)) : nullptr;
}

constexpr float kOrbitDegreesPerPixel = 0.3f;
/// The keys that fly while the right button is held.
constexpr std::array kFlyKeys { Qt::Key_W, Qt::Key_A, Qt::Key_S, Qt::Key_D, Qt::Key_Q, Qt::Key_E };
/// Wheel steps further apart than this are separate zoom gestures for View > Undo view.
constexpr int kWheelGestureMs = 400;

} // namespace

ViewportWidget::ViewportWidget(doc::Document* document, QWidget* parent)
    : QOpenGLWidget(parent)
    , m_document(document)
    , m_sync(std::make_unique<sync::SceneSync>(document))
    , m_nonFiniteOverlay(new NonFiniteOverlay(this))
    , m_overlay(new ViewportOverlay(this, document))
    , m_gizmo(document)
{
    setFocusPolicy(Qt::StrongFocus);
    setMouseTracking(true);
    setMinimumSize(160, 120);
    m_refineTimer.setSingleShot(true);
    m_refineTimer.setInterval(300);
    connect(&m_refineTimer, &QTimer::timeout, this, [this] {
        m_interactive = false;
        update();
    });
    connect(document, &doc::Document::selectionChanged, this, [this](int node) {
        // A node chosen after a light takes the gizmo; the light does not come back when it is deselected.
        if (node >= 0)
            m_gizmo.setSelectedLight(-1);
        refreshGizmo();
    });
    m_flyTimer.setInterval(30);
    connect(&m_flyTimer, &QTimer::timeout, this, &ViewportWidget::flyStep);
    m_wheelGestureTimer.setSingleShot(true);
    m_wheelGestureTimer.setInterval(kWheelGestureMs);
    connect(&m_wheelGestureTimer, &QTimer::timeout, this, &ViewportWidget::endGestureIfIdle);
    // Any document edit changes the picture; camera edits arrive here too.
    connect(document, &doc::Document::changed, this, [this](const doc::ChangeEvent& event) {
        using Kind = doc::ChangeEvent::Kind;
        const render::Camera& camera = m_document->state().camera;
        // An import resets too but keeps the camera; a new scene or project brings its own, and the way back
        // would lead through another scene's cameras.
        if (event.kind == Kind::Reset && !doc::sameCamera(camera, m_knownCamera)) {
            m_history.clear();
            m_gestureStart.reset();
            m_pivot.reset();
            emit viewHistoryChanged(false);
        }
        if (event.kind == Kind::Reset || event.kind == Kind::Camera)
            m_knownCamera = camera;
        // These rebuild the voxels, which can take seconds on a fine grid: say so before the first of the
        // frames the rebuild is split over (staged rebuilds).
        if (m_renderer
            && (event.kind == Kind::Reset || event.kind == Kind::Structure || event.kind == Kind::Settings)) {
            m_overlay->setBusy(tr("Rebuilding the voxels…"));
            m_overlay->repaint();
            QTimer::singleShot(0, this, qOverload<>(&QWidget::update));
            return;
        }
        update();
    });
}

ViewportWidget::~ViewportWidget()
{
    releaseGl();
}

void ViewportWidget::initializeGL()
{
    // A dock floating or the window moving to another screen destroys the context: drop every GL object
    // while it is still current, and build anew in the next initializeGL.
    connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &ViewportWidget::releaseGl,
        Qt::UniqueConnection);
    ++m_contextGeneration;
    try {
        m_renderer = std::make_unique<render::Renderer>(qtProcAddress);
        // The stats panel shows the frame before: waiting for this frame's timer results would stall the UI.
        m_renderer->setTimesFromPreviousFrame(true);
        // Bounces converge over frames: an edit shows at once, and the light settles while the view is idle.
        m_renderer->setBounceIterationsPerFrame(kBounceIterationsPerFrame);
        m_sync->apply(*m_renderer, true);
        m_error.clear();
    } catch (const std::exception& e) {
        m_renderer.reset();
        m_error = QString::fromUtf8(e.what());
        emit rendererFailed(m_error);
    }
}

void ViewportWidget::releaseGl()
{
    if (!m_renderer)
        return;
    makeCurrent();
    m_renderer.reset();
    doneCurrent();
}

QRect ViewportWidget::traceRect() const
{
    const int w = int(std::lround(width() * devicePixelRatioF())),
              h = int(std::lround(height() * devicePixelRatioF()));
    return m_inspector.enabled ? QRect(0, 0, w / 2, h) : QRect(0, 0, w, h);
}

QRect ViewportWidget::inspectorRect() const
{
    const int w = int(std::lround(width() * devicePixelRatioF())),
              h = int(std::lround(height() * devicePixelRatioF()));
    return QRect(w / 2, 0, w - w / 2, h);
}

void ViewportWidget::paintGL()
{
    if (!m_renderer)
        return;
    try {
        m_sync->apply(*m_renderer);
        const QRect trace = traceRect();
        const float scale = m_interactive ? kInteractiveScale : 1.0f;
        const int w = std::max(1, int(std::lround(trace.width() * scale)));
        const int h = std::max(1, int(std::lround(trace.height() * scale)));
        // A full rebuild (a new scene, grid or voxel setting) is split over frames: the window stays
        // responsive between them, showing the last complete image. Not while something is being dragged:
        // every move would start the rebuild again, and its image would never come.
        m_renderer->setStagedRebuilds(!m_interactive);
        const render::FrameStats stats = m_renderer->renderFrame(m_document->state().camera, w, h);
        const float exposure = m_document->state().settings.exposure;
        m_renderer->present(
            defaultFramebufferObject(), trace.x(), trace.y(), trace.width(), trace.height(), exposure);
        m_levelCount = m_renderer->voxelLevelCount();
        m_gridCount = m_renderer->gridCount();
        if (m_inspector.enabled) {
            const QRect right = inspectorRect();
            m_lastCubeCount = m_renderer->drawVoxelCubes(m_document->state().camera, inspectedLevel(),
                m_inspector.channel, defaultFramebufferObject(), right.x(), right.y(), right.width(),
                right.height(), exposure, inspectedGrid());
            emit cubesDrawn(int(m_lastCubeCount), m_levelCount, m_gridCount);
        }
        if (m_nonFiniteCheck) {
            // A readback, so only while asked for; the label changes after this paint, not inside it.
            QMetaObject::invokeMethod(
                m_nonFiniteOverlay,
                [overlay = m_nonFiniteOverlay, counts = m_renderer->countNonFinite()] {
                    overlay->showCounts(counts);
                },
                Qt::QueuedConnection);
        }
        emit frameRendered(stats);
        m_overlay->showFrame(
            stats, m_interactive, m_inspector.enabled ? QRect(0, 0, width() / 2, height()) : rect());
        refreshGizmo();
        if (!stats.lightConverged || stats.deferred)
            QTimer::singleShot(0, this, [this] { update(); });
    } catch (const std::exception& e) {
        m_error = QString::fromUtf8(e.what());
        emit rendererFailed(m_error);
    }
}

render::RadianceImage ViewportWidget::renderFullFrame(int width, int height, render::FrameStats* stats)
{
    if (!m_renderer)
        return {};
    makeCurrent();
    m_sync->apply(*m_renderer);
    // A frame rendered on request (export, comparison) reports its own times and has converged bounces.
    m_renderer->setTimesFromPreviousFrame(false);
    m_renderer->setBounceIterationsPerFrame(0);
    m_renderer->setStagedRebuilds(false);
    const render::FrameStats frameStats = m_renderer->renderFrame(m_document->state().camera, width, height);
    m_renderer->setBounceIterationsPerFrame(kBounceIterationsPerFrame);
    m_renderer->setTimesFromPreviousFrame(true);
    if (stats)
        *stats = frameStats;
    render::RadianceImage image = m_renderer->readFrame();
    doneCurrent();
    update(); // the next paint renders at the widget's own size again
    return image;
}

QStringList ViewportWidget::reloadShaders(const QString& folder)
{
    if (!m_renderer)
        return {};
    makeCurrent();
    const std::vector<std::string> failures = m_renderer->reloadShaders(folder.toStdString());
    doneCurrent();
    update();
    QStringList result;
    for (const std::string& failure : failures)
        result << QString::fromStdString(failure);
    return result;
}

int ViewportWidget::inspectedLevel() const
{
    return std::clamp(m_inspector.level, 0, std::max(0, m_levelCount - 1));
}

int ViewportWidget::inspectedGrid() const
{
    return std::clamp(m_inspector.grid, 0, std::max(0, m_gridCount - 1));
}

std::size_t ViewportWidget::occupiedVoxelCount()
{
    if (!m_renderer || m_levelCount == 0)
        return 0;
    makeCurrent();
    int size = 0;
    const std::vector<float> albedo = m_renderer->readVoxels("albedo", 0, size);
    doneCurrent();
    std::size_t count = 0;
    for (std::size_t i = 3; i < albedo.size(); i += 4)
        count += albedo[i] > 0.0f ? 1 : 0;
    return count;
}

void ViewportWidget::setNonFiniteCheck(bool enabled)
{
    m_nonFiniteCheck = enabled;
    if (!enabled)
        m_nonFiniteOverlay->hide();
    update();
}

void ViewportWidget::setInspector(const InspectorSettings& settings)
{
    if (settings == m_inspector)
        return;
    m_inspector = settings;
    update();
}

void ViewportWidget::startInteraction()
{
    m_interactive = true;
    m_refineTimer.start();
    update();
}

void ViewportWidget::setCamera(const render::Camera& camera)
{
    m_document->setCamera(camera);
    startInteraction();
}

void ViewportWidget::beginGesture()
{
    if (!m_gestureStart)
        m_gestureStart = m_document->state().camera;
}

void ViewportWidget::endGestureIfIdle()
{
    if (m_dragButton == Qt::NoButton && !m_flyTimer.isActive() && !m_wheelGestureTimer.isActive())
        endGesture();
}

void ViewportWidget::endGesture()
{
    m_wheelGestureTimer.stop();
    if (!m_gestureStart)
        return;
    m_history.record(*m_gestureStart, m_document->state().camera);
    m_gestureStart.reset();
    emit viewHistoryChanged(!m_history.isEmpty());
}

void ViewportWidget::goToBookmark(int index)
{
    const std::vector<doc::CameraBookmark>& bookmarks = m_document->state().bookmarks;
    if (index >= 0 && std::size_t(index) < bookmarks.size())
        jumpTo(bookmarks[std::size_t(index)].camera);
}

void ViewportWidget::jumpTo(const render::Camera& camera)
{
    // A jump in the middle of a drag or a flight splits it: what came before, the jump and what follows are
    // undone one at a time.
    const bool continuing = m_dragButton != Qt::NoButton || m_flyTimer.isActive();
    endGesture();
    m_history.record(m_document->state().camera, camera);
    setCamera(camera);
    emit viewHistoryChanged(!m_history.isEmpty());
    if (continuing)
        beginGesture();
}

void ViewportWidget::undoView()
{
    const bool continuing = m_dragButton != Qt::NoButton || m_flyTimer.isActive();
    // A zoom still waiting for the wheel to settle is the last gesture, not the one before it.
    endGesture();
    if (m_history.isEmpty())
        return;
    setCamera(m_history.takeLast());
    emit viewHistoryChanged(!m_history.isEmpty());
    if (continuing)
        beginGesture();
}

void ViewportWidget::resetCamera()
{
    jumpTo(m_document->savedCamera());
}

void ViewportWidget::startOrbit()
{
    const render::Camera& camera = m_document->state().camera;
    glm::vec3 origin, direction;
    const bool inInspector = m_inspector.enabled && !rayThrough(m_pressPosition, origin, direction, false);
    if (rayThrough(m_pressPosition, origin, direction, inInspector)) {
        const sync::PickResult hit = sync::pickNode(*m_document, origin, direction);
        if (hit.node >= 0) {
            m_pivot = hit.point;
            setCamera(CameraController::focusAtDepth(camera, hit.point));
            return;
        }
    }
    const render::Aabb selection
        = m_document->selectedNode() >= 0 ? visibleBounds(m_document->selectedNode()) : render::Aabb {};
    m_pivot = selection.isEmpty() ? camera.lookAt : selection.center();
}

bool ViewportWidget::rayThrough(
    const QPoint& position, glm::vec3& origin, glm::vec3& direction, bool inspectorHalf) const
{
    const QRect rect = inspectorHalf ? inspectorRect() : traceRect();
    const float dpr = float(devicePixelRatioF());
    const float x = float(position.x()) * dpr - float(rect.x());
    const float y = float(position.y()) * dpr;
    if (x < 0.0f || x >= float(rect.width()) || rect.height() <= 0)
        return false;
    const render::Camera& camera = m_document->state().camera;
    const float aspect = float(rect.width()) / float(rect.height());
    const float ndcX = 2.0f * (x + 0.5f) / float(rect.width()) - 1.0f;
    const float ndcY = 1.0f - 2.0f * (y + 0.5f) / float(rect.height());
    origin = camera.position;
    direction = glm::normalize(render::CameraBasis::of(camera).through(ndcX, ndcY, aspect));
    return true;
}

void ViewportWidget::mousePressEvent(QMouseEvent* event)
{
    m_lastMouse = event->position().toPoint();
    m_pressPosition = m_lastMouse;
    if (event->button() == Qt::LeftButton && !(event->modifiers() & Qt::ControlModifier)
        && m_gizmo.press(viewProjection(), event->position())) {
        m_dragButton = Qt::LeftButton;
        refreshGizmo();
        setFocus();
        return;
    }
    m_dragButton = event->button();
    m_movingNode = event->button() == Qt::LeftButton && (event->modifiers() & Qt::ControlModifier)
        && m_document->selectedNode() >= 0;
    // The pivot is picked when the drag turns out to be an orbit: a click picks once, on release.
    m_pivot.reset();
    if (!m_movingNode)
        beginGesture();
    if (m_dragButton == Qt::RightButton)
        startFlying();
    setFocus();
}

void ViewportWidget::mouseMoveEvent(QMouseEvent* event)
{
    const QPoint position = event->position().toPoint();
    const QPoint delta = position - m_lastMouse;
    m_lastMouse = position;
    const render::Camera& camera = m_document->state().camera;
    if (m_gizmo.dragging()) {
        m_gizmo.drag(event->position(), event->modifiers() & Qt::ControlModifier);
        startInteraction();
        refreshGizmo();
        return;
    }
    if (m_dragButton == Qt::NoButton) {
        if (const int part = m_gizmo.gizmo(viewProjection()).partAt(event->position());
            part != m_gizmoHover) {
            m_gizmoHover = part;
            refreshGizmo();
        }
        if (m_inspector.enabled)
            hoverVoxel(position);
        return;
    }
    if (m_movingNode) {
        // Move the selected node in the view plane, scaled so it follows the cursor at its distance.
        const int node = m_document->selectedNode();
        if (node < 0 || std::size_t(node) >= m_document->state().nodes.size())
            return;
        doc::NodeTransform transform = m_document->state().nodes[std::size_t(node)].transform;
        const glm::vec3 center = glm::vec3(m_document->nodeWorldTransform(node)[3]);
        const render::CameraBasis basis = render::CameraBasis::of(camera);
        const glm::vec3 &forward = basis.forward, &right = basis.right, &up = basis.up;
        const float distance = std::max(glm::dot(center - camera.position, forward), 0.1f);
        const float metresPerPixel = 2.0f * distance * basis.tanHalfFovY / float(std::max(1, height()));
        glm::vec3 move = (right * float(delta.x()) - up * float(delta.y())) * metresPerPixel;
        // Holding X, Y or Z keeps the move on that world axis, as in Blender's G X / G Y / G Z.
        for (const auto& [key, axis] :
            { std::pair { Qt::Key_X, 0 }, std::pair { Qt::Key_Y, 1 }, std::pair { Qt::Key_Z, 2 } })
            if (m_flyKeys.contains(key)) {
                glm::vec3 unit(0.0f);
                unit[axis] = 1.0f;
                // Screen motion along the axis's projection moves the object along the axis.
                const glm::vec2 screenAxis(glm::dot(unit, right), -glm::dot(unit, up));
                const float along = glm::length(screenAxis) > 1e-3f
                    ? glm::dot(glm::vec2(float(delta.x()), float(delta.y())), glm::normalize(screenAxis))
                        / glm::length(screenAxis)
                    : 0.0f;
                move = unit * along * metresPerPixel;
            }
        transform.translation += move;
        m_document->setNodeTransform(node, transform);
        startInteraction();
        return;
    }
    const bool pan = m_dragButton == Qt::MiddleButton || (event->modifiers() & Qt::ShiftModifier);
    if (pan)
        setCamera(CameraController::pan(camera, -float(delta.x()) / float(std::max(1, height())),
            float(delta.y()) / float(std::max(1, height()))));
    else if (m_dragButton == Qt::RightButton) {
        // Looking around, as in Godot and Unity: the camera turns where it stands (and flies with
        // W/A/S/D/Q/E).
        setCamera(CameraController::orbitAbout(camera, camera.position,
            float(delta.x()) * kOrbitDegreesPerPixel, float(delta.y()) * kOrbitDegreesPerPixel));
    } else if (m_dragButton == Qt::LeftButton) {
        // Picked where the button went down: only a Shift pan earlier in this drag can have moved the view
        // since.
        if (!m_pivot)
            startOrbit();
        setCamera(CameraController::orbitAbout(m_document->state().camera, *m_pivot,
            float(delta.x()) * kOrbitDegreesPerPixel, float(delta.y()) * kOrbitDegreesPerPixel));
    }
}

void ViewportWidget::mouseReleaseEvent(QMouseEvent* event)
{
    if (m_gizmo.dragging()) {
        m_gizmo.release();
        m_dragButton = Qt::NoButton;
        refreshGizmo();
        return;
    }
    if (event->button() == Qt::RightButton) {
        // Letting go of the right button ends the flight; the keys fly again only with the button down.
        for (const int key : kFlyKeys)
            m_flyKeys.remove(key);
        m_flyTimer.stop();
    }
    const bool click = (event->position().toPoint() - m_pressPosition).manhattanLength() < 4;
    const int clickedLight = click && event->button() == Qt::LeftButton && !m_movingNode
        ? m_overlay->lightAt(event->position())
        : -1;
    if (clickedLight >= 0) {
        m_document->setSelectedNode(-1);
        emit lightClicked(clickedLight);
    } else if (click && event->button() == Qt::LeftButton && !m_movingNode) {
        glm::vec3 origin, direction;
        const bool inInspector
            = m_inspector.enabled && !rayThrough(event->position().toPoint(), origin, direction, false);
        if (rayThrough(event->position().toPoint(), origin, direction, inInspector))
            m_document->setSelectedNode(sync::pickNode(*m_document, origin, direction).node);
    }
    // A second drag of the node is an undo step of its own.
    if (m_movingNode)
        m_document->endEditGesture();
    m_dragButton = Qt::NoButton;
    m_movingNode = false;
    m_pivot.reset();
    endGestureIfIdle();
}

void ViewportWidget::wheelEvent(QWheelEvent* event)
{
    beginGesture();
    setCamera(CameraController::zoom(m_document->state().camera, float(event->angleDelta().y()) / 120.0f));
    m_wheelGestureTimer.start();
}

QList<std::pair<QString, QString>> ViewportWidget::inputBindings()
{
    // Kept beside keyPressEvent and the mouse handlers: a key added there belongs here too, unless an action
    // of the main window has it as well (F is View > Frame selection, listed with the actions).
    return {
        { tr("W / E / R"),
            tr("Handles to move / rotate / scale the selection (or the light chosen in the "
               "Scene panel)") },
        { tr("Q"), tr("No handles") },
        { tr("Drag a handle"), tr("Move, rotate or scale along its axis; Esc while dragging puts it back") },
        { tr("Ctrl while dragging a handle"),
            tr("Snap: round steps for the zoom, 15°, tenths of the scale") },
        { tr("Right drag"), tr("Look around") },
        { tr("W / S with the right button held"), tr("Fly forward / back") },
        { tr("A / D with the right button held"), tr("Fly left / right") },
        { tr("Q / E with the right button held"), tr("Fly down / up") },
        { tr("Left drag"), tr("Orbit about the point under the cursor") },
        { tr("Middle drag, Shift+drag"), tr("Pan") },
        { tr("Wheel"), tr("Zoom") },
        { tr("Click"), tr("Select the object under the cursor, or the light whose icon it is on") },
        { tr("Ctrl+drag"), tr("Move the selected object") },
        { tr("X / Y / Z held with Ctrl+drag"), tr("Move along that world axis only") },
    };
}

void ViewportWidget::keyPressEvent(QKeyEvent* event)
{
    switch (event->key()) {
    case Qt::Key_F:
        frameSelected();
        return;
    case Qt::Key_X:
    case Qt::Key_Y:
    case Qt::Key_Z:
        if (!event->isAutoRepeat())
            m_flyKeys.insert(event->key()); // axis constraint for Ctrl+drag; no flying
        return;
    case Qt::Key_Escape:
        if (m_gizmo.dragging()) {
            m_gizmo.cancel();
            m_dragButton = Qt::NoButton;
            refreshGizmo();
            return;
        }
        QOpenGLWidget::keyPressEvent(event);
        return;
    case Qt::Key_W:
    case Qt::Key_A:
    case Qt::Key_S:
    case Qt::Key_D:
    case Qt::Key_Q:
    case Qt::Key_E:
    case Qt::Key_R:
        // With the right button down the keys fly, as in Godot and Unity; without it W, E and R choose the
        // gizmo (Q none).
        if (event->isAutoRepeat())
            return;
        if (m_dragButton == Qt::RightButton) {
            if (event->key() != Qt::Key_R) {
                m_flyKeys.insert(event->key());
                startFlying();
            }
            return;
        }
        if (event->key() == Qt::Key_W)
            setGizmoMode(GizmoMode::Move);
        else if (event->key() == Qt::Key_E)
            setGizmoMode(GizmoMode::Rotate);
        else if (event->key() == Qt::Key_R)
            setGizmoMode(GizmoMode::Scale);
        else if (event->key() == Qt::Key_Q)
            setGizmoMode(GizmoMode::None);
        return;
    default:
        QOpenGLWidget::keyPressEvent(event);
    }
}

void ViewportWidget::keyReleaseEvent(QKeyEvent* event)
{
    if (!event->isAutoRepeat())
        m_flyKeys.remove(event->key());
    if (!flyKeyHeld()) {
        m_flyTimer.stop();
        endGestureIfIdle();
    }
    QOpenGLWidget::keyReleaseEvent(event);
}

void ViewportWidget::focusOutEvent(QFocusEvent* event)
{
    m_flyKeys.clear();
    m_flyTimer.stop();
    endGestureIfIdle();
    QOpenGLWidget::focusOutEvent(event);
}

void ViewportWidget::enterEvent(QEnterEvent* event)
{
    // The pointer over the view gives its keys to the view, as in Blender, unless a text field is being typed
    // in (a name, a number): moving the mouse must not take its keystrokes away.
    const QWidget* focused = window()->focusWidget();
    if (!focused || !(focused->inherits("QLineEdit") || focused->inherits("QAbstractSpinBox")))
        setFocus(Qt::MouseFocusReason);
    QOpenGLWidget::enterEvent(event);
}

void ViewportWidget::resizeEvent(QResizeEvent* event)
{
    QOpenGLWidget::resizeEvent(event);
    m_overlay->setGeometry(rect());
}

bool ViewportWidget::flyKeyHeld() const
{
    return std::any_of(kFlyKeys.begin(), kFlyKeys.end(), [this](int key) { return m_flyKeys.contains(key); });
}

void ViewportWidget::startFlying()
{
    if (!flyKeyHeld() || m_flyTimer.isActive())
        return;
    beginGesture();
    // A quarter of the geometry's diagonal per second: the room is crossed in a few seconds whatever its
    // unit. Measured once per flight, not per step (the bounds read every vertex).
    const render::Aabb bounds = m_document->sceneBounds();
    const float diagonal = bounds.isEmpty() ? 0.0f : glm::length(bounds.size());
    m_flySpeed = 0.25f * (diagonal > 0.0f && std::isfinite(diagonal) ? diagonal : 1.0f);
    m_flyClock.start();
    m_flyTimer.start();
}

void ViewportWidget::setGizmoMode(GizmoMode mode)
{
    if (m_gizmo.dragging())
        return;
    m_gizmo.setMode(mode);
    refreshGizmo();
}

void ViewportWidget::setSelectedLight(int light)
{
    m_gizmo.setSelectedLight(light);
    refreshGizmo();
}

ViewProjection ViewportWidget::viewProjection() const
{
    return { m_document->state().camera, QRectF(m_overlay->imageRect()) };
}

void ViewportWidget::refreshGizmo()
{
    const TransformGizmo gizmo = m_gizmo.gizmo(viewProjection());
    m_overlay->setGizmo(gizmo, m_gizmo.dragging() ? m_gizmo.activePart() : m_gizmoHover);
}

void ViewportWidget::flyStep()
{
    const float seconds = float(m_flyClock.restart()) * 1e-3f;
    const float speed = m_flySpeed * seconds;
    float forward = 0, right = 0, up = 0;
    forward += m_flyKeys.contains(Qt::Key_W) ? speed : 0.0f;
    forward -= m_flyKeys.contains(Qt::Key_S) ? speed : 0.0f;
    right += m_flyKeys.contains(Qt::Key_D) ? speed : 0.0f;
    right -= m_flyKeys.contains(Qt::Key_A) ? speed : 0.0f;
    up += m_flyKeys.contains(Qt::Key_E) ? speed : 0.0f;
    up -= m_flyKeys.contains(Qt::Key_Q) ? speed : 0.0f;
    setCamera(CameraController::fly(m_document->state().camera, forward, right, up));
}

void ViewportWidget::frameSelected()
{
    const int node = m_document->selectedNode();
    if (node < 0) {
        frameAll();
        return;
    }
    jumpTo(CameraController::frame(m_document->state().camera, visibleBounds(node)));
}

void ViewportWidget::frameAll()
{
    jumpTo(CameraController::frameAll(m_document->state().camera, visibleBounds()));
}

render::Aabb ViewportWidget::visibleBounds(int only) const
{
    render::Aabb box;
    const auto& nodes = m_document->state().nodes;
    for (std::size_t n = 0; n < nodes.size(); ++n) {
        if ((only >= 0 && int(n) != only) || !nodes[n].visible)
            continue;
        const render::Scene& source = m_document->sourceScene(nodes[n].source);
        if (nodes[n].mesh < 0 || std::size_t(nodes[n].mesh) >= source.meshes.size())
            continue;
        const glm::mat4 world = m_document->nodeWorldTransform(int(n));
        for (const glm::vec3& p : source.meshes[std::size_t(nodes[n].mesh)].positions)
            box.extend(glm::vec3(world * glm::vec4(p, 1.0f)));
    }
    return box;
}

void ViewportWidget::hoverVoxel(const QPoint& position)
{
    glm::vec3 origin, direction;
    if (!m_renderer || !rayThrough(position, origin, direction, true)) {
        emit voxelHovered(QString());
        return;
    }
    makeCurrent();
    const render::VoxelListing& listing
        = m_renderer->listVoxels(inspectedLevel(), m_inspector.channel, inspectedGrid());
    doneCurrent();
    float best = std::numeric_limits<float>::max();
    const render::VoxelSample* hit = nullptr;
    for (const render::VoxelSample& sample : listing.samples) {
        const glm::vec3 lo = listing.origin + glm::vec3(sample.coord) * listing.cellSize;
        const glm::vec3 hi = lo + glm::vec3(listing.cellSize);
        float t0 = 0.0f, t1 = best;
        for (int axis = 0; axis < 3 && t0 <= t1; ++axis) {
            float a = (lo[axis] - origin[axis]) / direction[axis],
                  b = (hi[axis] - origin[axis]) / direction[axis];
            if (a > b)
                std::swap(a, b);
            t0 = std::max(t0, a);
            t1 = std::min(t1, b);
        }
        if (t0 <= t1 && t0 < best) {
            best = t0;
            hit = &sample;
        }
    }
    if (!hit) {
        emit voxelHovered(QString());
        return;
    }
    const QString grid = m_gridCount > 1 ? QStringLiteral("grid %1, ").arg(listing.grid) : QString();
    emit voxelHovered(QStringLiteral("%1level %2 voxel (%3, %4, %5): %6 %7 %8, opacity %9")
                          .arg(grid)
                          .arg(listing.level)
                          .arg(hit->coord.x)
                          .arg(hit->coord.y)
                          .arg(hit->coord.z)
                          .arg(double(hit->value.r), 0, 'g', 4)
                          .arg(double(hit->value.g), 0, 'g', 4)
                          .arg(double(hit->value.b), 0, 'g', 4)
                          .arg(double(hit->value.a), 0, 'g', 3));
}

} // namespace vct::ui
