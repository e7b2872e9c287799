#include "EditorTestSetup.h"
#include "TestSupport.h"
#include "ui/LightDock.h"
#include "ui/MainWindow.h"
#include "ui/TransformGizmo.h"
#include "ui/ViewportOverlay.h"
#include "ui/ViewportWidget.h"

#include "core/FrameStats.h"
#include "document/Document.h"
#include "scene/CameraBasis.h"

#include <glm/gtc/matrix_transform.hpp>

#include <QSignalSpy>
#include <QUndoStack>
#include <QtTest>

#include <cmath>

using namespace vct;

namespace {

/** A camera on +z looking at the origin, and a 400 x 300 image: screen right is +x, screen up is +y. */
ui::ViewProjection frontView()
{
    render::Camera camera;
    camera.position = glm::vec3(0.0f, 0.0f, 5.0f);
    camera.lookAt = glm::vec3(0.0f);
    camera.up = glm::vec3(0.0f, 1.0f, 0.0f);
    camera.fovYDeg = 60.0f;
    return { camera, QRectF(0, 0, 400, 300) };
}

QPointF along(const ui::TransformGizmo::Handle& handle, double share)
{
    return handle.shape[0] + share * (handle.shape[1] - handle.shape[0]);
}

const ui::TransformGizmo::Handle* handleOf(const std::vector<ui::TransformGizmo::Handle>& handles, int part)
{
    for (const ui::TransformGizmo::Handle& handle : handles)
        if (handle.part == part)
            return &handle;
    return nullptr;
}

} // namespace

/**
 * The viewport's move, rotate and scale handles (issue 20): their geometry on its own, then in the real
 * editor window (llvmpipe behind the viewport, under Xvfb), dragged with the mouse as a user would.
 */
class GizmoTest : public QObject {
    Q_OBJECT

public:
    static void initMain() { test::prepareEditorApplication(); }

private slots:
    void initTestCase();
    void cleanupTestCase();
    void handlesFollowTheCursorOnScreen();
    void keysChooseTheHandlesAndFlyOnlyWithTheRightButton();
    void draggingAHandleMovesTheNodeInOneUndoStep();
    void turningKeepsTheMiddleInPlace();
    void scalingAndEscape();
    void lightsTakeTheHandlesTheirKindHas();

private:
    render::FrameStats nextFrame();
    int shortBox() const;
    /**
     * Drags with the left button from @p from to @p to in steps, holding @p held while moving; @p escape
     * presses Esc before letting go.
     */
    void drag(const QPoint& from, const QPoint& to, bool escape = false,
        Qt::KeyboardModifiers held = Qt::NoModifier);
    std::vector<ui::TransformGizmo::Handle> shownHandles() const;
    /** Saves the window to the test output folder, to look at. */
    void screenshot(const char* name) const;

    std::unique_ptr<ui::MainWindow> m_window;
};

render::FrameStats GizmoTest::nextFrame()
{
    return test::nextFrame(*m_window);
}

int GizmoTest::shortBox() const
{
    return test::nodeNamed(*m_window->document(), QStringLiteral("shortbox"));
}

void GizmoTest::drag(const QPoint& from, const QPoint& to, bool escape, Qt::KeyboardModifiers held)
{
    ui::ViewportWidget* viewport = m_window->viewport();
    QTest::mousePress(viewport, Qt::LeftButton, Qt::NoModifier, from);
    constexpr int steps = 8;
    for (int i = 1; i <= steps; ++i) {
        const QPointF at = QPointF(from) + QPointF(to - from) * double(i) / steps;
        QMouseEvent move(
            QEvent::MouseMove, at, viewport->mapToGlobal(at), Qt::NoButton, Qt::LeftButton, held);
        QCoreApplication::sendEvent(viewport, &move);
    }
    if (escape)
        QTest::keyClick(viewport, Qt::Key_Escape);
    QTest::mouseRelease(viewport, Qt::LeftButton, Qt::NoModifier, to);
}

std::vector<ui::TransformGizmo::Handle> GizmoTest::shownHandles() const
{
    return m_window->viewport()->overlay()->gizmo().handles();
}

void GizmoTest::screenshot(const char* name) const
{
    const QString path = test::outputDir() + QStringLiteral("/gizmo-%1.png").arg(QString::fromLatin1(name));
    QVERIFY(m_window->grab().save(path));
    qInfo("screenshot: %s", qPrintable(path));
}

void GizmoTest::initTestCase()
{
    qRegisterMetaType<render::FrameStats>();
    m_window = test::showEditor(QStringLiteral("builtin:cornell_point"));
    QVERIFY(m_window);
    QVERIFY2(!nextFrame().passes.empty(), "the viewport rendered no frame");
    QVERIFY(shortBox() >= 0);
}

void GizmoTest::cleanupTestCase()
{
    m_window.reset();
}

// Pure geometry: a drag along the X arrow moves by what the cursor covers at the object's depth, a quarter
// turn counter-clockwise about the axis that points at the viewer is +90 degrees, and scale compares
// distances from the middle.
void GizmoTest::handlesFollowTheCursorOnScreen()
{
    const ui::ViewProjection view = frontView();
    const ui::TransformGizmo move(ui::GizmoMode::Move, glm::vec3(0.0f), glm::mat3(1.0f), view);
    const std::vector<ui::TransformGizmo::Handle> arrows = move.handles();
    // Z points at the camera: its arrow could not be dragged along, so it is not shown.
    QCOMPARE(int(arrows.size()), 2);
    const QPointF centre(200, 150);
    QVERIFY(std::hypot(arrows[0].shape[0].x() - centre.x(), arrows[0].shape[0].y() - centre.y()) < 1e-6);
    QCOMPARE(move.partAt(along(arrows[0], 0.6)), 0);
    QCOMPARE(move.partAt(along(arrows[1], 0.6)), 1);
    QCOMPARE(move.partAt(centre + QPointF(-60, 60)), -1);
    const float metresPerPixel = view.metresPerPixel(glm::vec3(0.0f));
    const glm::vec3 moved = move.translation(0, centre + QPointF(10, 0), centre + QPointF(50, 7));
    QVERIFY2(std::abs(moved.x - 40.0f * metresPerPixel) < 1e-3f * metresPerPixel && moved.y == 0.0f
            && moved.z == 0.0f,
        qPrintable(test::describe(moved)));
    // Dragging the Y arrow up the screen moves up the world.
    QVERIFY(move.translation(1, centre + QPointF(0, -10), centre + QPointF(0, -30)).y > 0.0f);

    const ui::TransformGizmo rotate(ui::GizmoMode::Rotate, glm::vec3(0.0f), glm::mat3(1.0f), view);
    QCOMPARE(int(rotate.handles().size()), 3);
    // The ring about Z faces the camera: a circle of kSizePixels around the middle, grabbed anywhere on it
    // (away from the rings seen edge-on, the lines through the middle).
    const double r = ui::TransformGizmo::kSizePixels;
    QCOMPARE(rotate.partAt(centre + QPointF(r, -r) / std::sqrt(2.0)), 2);
    // Grabbed at its top and pulled left by a quarter of its length, it turns counter-clockwise as seen from
    // +Z, where the axis points: +90 degrees.
    const float quarter
        = rotate.rotationDeg(2, centre + QPointF(0, -r), centre + QPointF(-0.5 * M_PI * r, -r));
    // (The ring is 48 chords: the one at the top runs 3.75 degrees off its tangent.)
    QVERIFY2(std::abs(quarter - 90.0f) < 0.5f, qPrintable(QString::number(double(quarter))));
    // The ring about X is edge-on, a vertical line: dragging along it still turns.
    QVERIFY(std::abs(rotate.rotationDeg(0, centre + QPointF(0, -40), centre + QPointF(0, -20))) > 1.0f);

    const ui::TransformGizmo scale(ui::GizmoMode::Scale, glm::vec3(0.0f), glm::mat3(1.0f), view);
    QCOMPARE(scale.partAt(centre + QPointF(2, 1)), ui::TransformGizmo::kUniform);
    QCOMPARE(scale.scaleFactor(0, centre + QPointF(20, 0), centre + QPointF(40, 3)), 2.0f);
    QCOMPARE(scale.scaleFactor(ui::TransformGizmo::kUniform, centre + QPointF(3, 4), centre + QPointF(6, 8)),
        2.0f);
    // Past the middle a factor would turn negative: it stops at the smallest one instead.
    QVERIFY(scale.scaleFactor(0, centre + QPointF(20, 0), centre + QPointF(-20, 0)) > 0.0f);

    // Behind the camera there is nothing to draw or grab.
    const ui::TransformGizmo behind(ui::GizmoMode::Move, glm::vec3(0.0f, 0.0f, 10.0f), glm::mat3(1.0f), view);
    QVERIFY(behind.handles().empty());
    QCOMPARE(behind.partAt(centre), -1);
}

void GizmoTest::keysChooseTheHandlesAndFlyOnlyWithTheRightButton()
{
    ui::ViewportWidget* viewport = m_window->viewport();
    doc::Document* document = m_window->document();
    document->setSelectedNode(shortBox());
    viewport->setFocus();
    const render::Camera before = document->state().camera;
    for (const auto& [key, mode, handles] : { std::tuple { Qt::Key_W, ui::GizmoMode::Move, 3 },
             std::tuple { Qt::Key_E, ui::GizmoMode::Rotate, 3 },
             std::tuple { Qt::Key_R, ui::GizmoMode::Scale, 4 },
             std::tuple { Qt::Key_Q, ui::GizmoMode::None, 0 } }) {
        QTest::keyPress(viewport, key);
        QTest::qWait(120);
        QTest::keyRelease(viewport, key);
        QCOMPARE(viewport->gizmoMode(), mode);
        QCOMPARE(int(shownHandles().size()), handles);
    }
    // Choosing handles flies nowhere.
    QVERIFY(doc::sameCamera(document->state().camera, before));

    // With the right button down, W flies forward.
    const QPoint middle = viewport->rect().center();
    QTest::mousePress(viewport, Qt::RightButton, Qt::NoModifier, middle);
    QTest::keyPress(viewport, Qt::Key_W);
    QTest::qWait(300);
    QTest::keyRelease(viewport, Qt::Key_W);
    QTest::mouseRelease(viewport, Qt::RightButton, Qt::NoModifier, middle);
    const glm::vec3 travelled = document->state().camera.position - before.position;
    const glm::vec3 forward = render::CameraBasis::of(before).forward;
    QVERIFY2(glm::dot(travelled, forward) > 0.0f, qPrintable(test::describe(travelled)));
    QCOMPARE(viewport->gizmoMode(), ui::GizmoMode::None);
    document->setCamera(before);
}

void GizmoTest::draggingAHandleMovesTheNodeInOneUndoStep()
{
    ui::ViewportWidget* viewport = m_window->viewport();
    doc::Document* document = m_window->document();
    const int node = shortBox();
    document->setSelectedNode(node);
    viewport->setGizmoMode(ui::GizmoMode::Move);
    nextFrame();
    screenshot("move");
    const doc::NodeTransform original = document->state().nodes[std::size_t(node)].transform;
    const int steps = document->undoStack()->index();
    const ui::TransformGizmo::Handle* x = handleOf(shownHandles(), 0);
    QVERIFY(x);
    const QPoint start = along(*x, 0.7).toPoint();
    const QPointF unit = (x->shape[1] - x->shape[0])
        / std::hypot(x->shape[1].x() - x->shape[0].x(), x->shape[1].y() - x->shape[0].y());
    const QPoint end = start + (40.0 * unit).toPoint();
    const float expected = viewport->overlay()->gizmo().translation(0, start, end).x;
    drag(start, end);
    const doc::NodeTransform moved = document->state().nodes[std::size_t(node)].transform;
    qInfo("dragged 40 px along the X arrow: moved %s (expected %.4f m along X)",
        qPrintable(test::describe(moved.translation - original.translation)), double(expected));
    QVERIFY(expected > 0.0f);
    QVERIFY(std::abs(moved.translation.x - original.translation.x - expected) < 1e-4f * expected);
    QCOMPARE(moved.translation.y, original.translation.y);
    QCOMPARE(moved.translation.z, original.translation.z);
    QCOMPARE(document->undoStack()->index(), steps + 1);
    // The press took the handle, not the view: the selection and the camera stay.
    QCOMPARE(document->selectedNode(), node);
    document->undoStack()->undo();
    QVERIFY(document->state().nodes[std::size_t(node)].transform == original);

    // Ctrl held while moving snaps to a round step for the zoom: a power of ten near an eighth of the
    // handles.
    drag(start, end, false, Qt::ControlModifier);
    const float step
        = std::pow(10.0f, std::round(std::log10(viewport->overlay()->gizmo().worldSize() / 8.0f)));
    const float snapped
        = document->state().nodes[std::size_t(node)].transform.translation.x - original.translation.x;
    qInfo("snapped to %.4f m in steps of %.4f m", double(snapped), double(step));
    QVERIFY2(snapped > 0.0f && std::abs(snapped / step - std::round(snapped / step)) < 1e-3f,
        qPrintable(QString::number(double(snapped))));
    QVERIFY(std::abs(snapped - expected) <= 0.5f * step + 1e-6f);
    document->undoStack()->undo();
}

void GizmoTest::turningKeepsTheMiddleInPlace()
{
    ui::ViewportWidget* viewport = m_window->viewport();
    doc::Document* document = m_window->document();
    const int node = shortBox();
    document->setSelectedNode(node);
    viewport->setGizmoMode(ui::GizmoMode::Rotate);
    nextFrame();
    screenshot("rotate");
    const doc::NodeTransform original = document->state().nodes[std::size_t(node)].transform;
    const glm::vec3 middle = document->nodeWorldBounds(node).center();
    const ui::TransformGizmo::Handle* ring = handleOf(shownHandles(), 1);
    QVERIFY(ring);
    // Grabbed on the ring away from where the others cross it, and pulled along it by a tenth of a turn.
    const int n = int(ring->shape.size());
    const QPointF grab = ring->shape[n / 8];
    const QPointF onward = ring->shape[n / 8 + 1] - grab;
    const QPoint from = grab.toPoint();
    const QPoint to = from
        + (onward / std::hypot(onward.x(), onward.y()) * 0.2 * M_PI * ui::TransformGizmo::kSizePixels)
              .toPoint();
    const float expected = viewport->overlay()->gizmo().rotationDeg(1, from, to);
    drag(from, to);
    const doc::NodeTransform turned = document->state().nodes[std::size_t(node)].transform;
    qInfo("turned about Y: rotation %s, translation %s", qPrintable(test::describe(turned.rotationDeg)),
        qPrintable(test::describe(turned.translation)));
    QVERIFY2(std::abs(expected - 36.0f) < 3.0f, qPrintable(QString::number(double(expected))));
    QVERIFY2(
        std::abs(turned.rotationDeg.y - expected) < 1e-3f, qPrintable(test::describe(turned.rotationDeg)));
    QVERIFY(std::abs(turned.rotationDeg.x) < 1e-3f && std::abs(turned.rotationDeg.z) < 1e-3f);
    const glm::vec3 after = document->nodeWorldBounds(node).center();
    // The bounds of a turned box grow, but their middle stays where it was.
    QVERIFY2(glm::length(after - middle) < 1e-4f, qPrintable(test::describe(after - middle)));
    document->undoStack()->undo();
    QVERIFY(document->state().nodes[std::size_t(node)].transform == original);

    // Ctrl held while turning snaps to 15 degrees: the same drag turns by 30 or 45.
    drag(from, to, false, Qt::ControlModifier);
    const float snapped = document->state().nodes[std::size_t(node)].transform.rotationDeg.y;
    QVERIFY2(std::abs(snapped - 15.0f * std::round(expected / 15.0f)) < 1e-3f,
        qPrintable(QString::number(double(snapped))));
    document->undoStack()->undo();
}

void GizmoTest::scalingAndEscape()
{
    ui::ViewportWidget* viewport = m_window->viewport();
    doc::Document* document = m_window->document();
    const int node = shortBox();
    document->setSelectedNode(node);
    viewport->setGizmoMode(ui::GizmoMode::Scale);
    nextFrame();
    screenshot("scale");
    const doc::NodeTransform original = document->state().nodes[std::size_t(node)].transform;
    const glm::vec3 middle = document->nodeWorldBounds(node).center();
    const int steps = document->undoStack()->index();
    const ui::TransformGizmo::Handle* uniform = handleOf(shownHandles(), ui::TransformGizmo::kUniform);
    QVERIFY(uniform);
    const QPoint centre = uniform->shape.boundingRect().center().toPoint();
    const float factor = viewport->overlay()->gizmo().scaleFactor(
        ui::TransformGizmo::kUniform, centre + QPoint(4, 0), centre + QPoint(8, 0));
    QVERIFY2(factor > 1.5f && factor < 2.5f, qPrintable(QString::number(double(factor))));
    drag(centre + QPoint(4, 0), centre + QPoint(8, 0));
    const doc::NodeTransform scaled = document->state().nodes[std::size_t(node)].transform;
    QVERIFY2(glm::length(scaled.scale - factor * original.scale) < 1e-4f,
        qPrintable(test::describe(scaled.scale)));
    QVERIFY(glm::length(document->nodeWorldBounds(node).center() - middle) < 1e-4f);
    QCOMPARE(document->undoStack()->index(), steps + 1);

    // Esc while a handle is held puts the node back, and leaves no undo step behind.
    drag(centre + QPoint(4, 0), centre + QPoint(7, 0), true);
    QVERIFY2(document->state().nodes[std::size_t(node)].transform == scaled,
        qPrintable(test::describe(document->state().nodes[std::size_t(node)].transform.scale)));
    QCOMPARE(document->undoStack()->index(), steps + 1);
    document->undoStack()->undo();
    QVERIFY(document->state().nodes[std::size_t(node)].transform == original);
}

void GizmoTest::lightsTakeTheHandlesTheirKindHas()
{
    ui::ViewportWidget* viewport = m_window->viewport();
    doc::Document* document = m_window->document();
    QVERIFY(!document->state().lights.empty());
    QCOMPARE(document->state().lights[0].type, doc::LightType::Point);
    // A click on the light's icon chooses it, as its row in the Scene panel would.
    document->setSelectedNode(shortBox());
    viewport->setGizmoMode(ui::GizmoMode::Move);
    nextFrame();
    const QList<QPointF> icons = viewport->overlay()->lightIconPositions();
    QCOMPARE(icons.size(), qsizetype(1));
    QTest::mouseClick(viewport, Qt::LeftButton, Qt::NoModifier, icons.front().toPoint());
    QCOMPARE(document->selectedNode(), -1);
    QCOMPARE(m_window->lightDock()->currentLight(), 0);
    nextFrame();
    const doc::LightNode original = document->state().lights[0];
    const ui::TransformGizmo::Handle* y = handleOf(shownHandles(), 1);
    QVERIFY2(y,
        qPrintable(QStringLiteral("%1 handles for the light at %2")
                       .arg(shownHandles().size())
                       .arg(test::describe(original.position))));
    const QPoint start = along(*y, 0.7).toPoint();
    drag(start, start + ((y->shape[0] - y->shape[1]) * 0.25).toPoint()); // down the Y arrow
    const doc::LightNode moved = document->state().lights[0];
    QVERIFY2(moved.position.y < original.position.y, qPrintable(test::describe(moved.position)));
    QCOMPARE(moved.position.x, original.position.x);
    QCOMPARE(moved.position.z, original.position.z);
    document->undoStack()->undo();
    QVERIFY(document->state().lights[0] == original);

    // A point light has no direction to turn, and no size to scale until it has a radius.
    viewport->setGizmoMode(ui::GizmoMode::Rotate);
    QVERIFY(shownHandles().empty());
    viewport->setGizmoMode(ui::GizmoMode::Scale);
    QVERIFY(shownHandles().empty());
    // A rect light turns whole: its width axis turns with its direction (its spin about its normal follows).
    doc::LightNode rect;
    rect.type = doc::LightType::Rect;
    rect.name = QStringLiteral("Rect");
    rect.position = original.position - glm::vec3(0.0f, 0.1f, 0.0f);
    rect.direction = glm::vec3(0.0f, -1.0f, 0.0f);
    rect.areaWidth = 0.4f;
    rect.areaHeight = 0.2f;
    rect.areaRotationDeg = 20.0f;
    document->addLight(rect);
    const int rectIndex = int(document->state().lights.size()) - 1;
    viewport->setSelectedLight(rectIndex);
    viewport->setGizmoMode(ui::GizmoMode::Rotate);
    nextFrame();
    const ui::TransformGizmo::Handle* xRing = handleOf(shownHandles(), 0);
    QVERIFY(xRing);
    const int n = int(xRing->shape.size());
    const QPointF grab = xRing->shape[n / 8];
    const QPointF onward = xRing->shape[n / 8 + 1] - grab;
    const QPoint from = grab.toPoint();
    const QPoint to = from + (onward / std::hypot(onward.x(), onward.y()) * 40.0).toPoint();
    const float turnDeg = viewport->overlay()->gizmo().rotationDeg(0, from, to);
    glm::vec3 width, height, front;
    QVERIFY(document->state().lights[std::size_t(rectIndex)].surfaceLight().axes(width, height, front));
    drag(from, to);
    const glm::mat3 turn = glm::mat3(glm::rotate(glm::mat4(1.0f), glm::radians(turnDeg), glm::vec3(1, 0, 0)));
    glm::vec3 turnedWidth, turnedHeight, turnedFront;
    QVERIFY(document->state().lights[std::size_t(rectIndex)].surfaceLight().axes(
        turnedWidth, turnedHeight, turnedFront));
    qInfo("rect turned %.1f degrees about X: width axis %s -> %s", double(turnDeg),
        qPrintable(test::describe(width)), qPrintable(test::describe(turnedWidth)));
    QVERIFY(std::abs(turnDeg) > 5.0f);
    QVERIFY2(glm::length(turnedFront - turn * front) < 1e-4f, qPrintable(test::describe(turnedFront)));
    QVERIFY2(glm::length(turnedWidth - turn * width) < 1e-4f, qPrintable(test::describe(turnedWidth)));
    document->undoStack()->undo(); // the turn
    document->undoStack()->undo(); // the new light
    viewport->setSelectedLight(0);
    viewport->setGizmoMode(ui::GizmoMode::Scale);

    // Choosing a node gives the handles to it; deselecting it does not bring the light's back.
    document->setSelectedNode(shortBox());
    QCOMPARE(int(shownHandles().size()), 4);
    document->setSelectedNode(-1);
    QVERIFY(shownHandles().empty());
    viewport->setGizmoMode(ui::GizmoMode::None);
}

QTEST_MAIN(GizmoTest)
#include "tst_Gizmo.moc"
