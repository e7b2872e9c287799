#include "EditorTestSetup.h"
#include "TestSupport.h"

#include "ui/MainWindow.h"
#include "ui/ViewportWidget.h"

#include "document/Document.h"
#include "document/DocumentState.h"
#include "document/SceneLoader.h"
#include "sync/NodePicker.h"

#include <glm/gtc/matrix_transform.hpp>

#include <QAction>
#include <QApplication>
#include <QEnterEvent>
#include <QLineEdit>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QSurfaceFormat>
#include <QTreeView>
#include <QUndoStack>
#include <QtTest>

using namespace vct;

namespace {

QString describe(const render::Camera& camera)
{
    return QStringLiteral("position %1 look-at %2 up %3")
        .arg(test::describe(camera.position), test::describe(camera.lookAt), test::describe(camera.up));
}

} // namespace

/**
 * Issue 20, "the camera gets lost": orbiting about the point under the cursor, View > Reset camera, Frame all
 * from inside the scene and Undo view, through the real editor under Xvfb.
 */
class CameraTest : public QObject {
    Q_OBJECT

public:
    static void initMain() { test::prepareEditorApplication(); }

private slots:
    void initTestCase();
    void init();
    void cleanupTestCase();
    void orbitKeepsThePointUnderTheCursorInPlace();
    void orbitOverNothingTurnsAboutTheSelection();
    void resetCameraRestoresTheSceneCamera();
    void undoViewReturnsToTheCameraBeforeTheLastGesture();
    void undoViewKeepsTheLast32Cameras();
    void frameAllFromInsideStaysInside();
    void viewKeysWorkWithoutAClickFirst();
    void bookmarksReturnToAViewAndUndo();

private:
    bool waitForFrame();
    QAction* action(const char* name) const;
    const render::Camera& camera() const { return m_window->document()->state().camera; }
    /** Where @p point lands in the viewport, in widget pixels from the top left (fractional). */
    QPointF screenPosition(const render::Camera& camera, const glm::vec3& point) const;
    /** What the ray through the centre of widget pixel @p pixel hits, as the viewport casts it. */
    sync::PickResult pickAt(const render::Camera& camera, const QPoint& pixel) const;
    /** A drag with @p button in @p steps mouse moves, as a hand would make it. */
    void drag(Qt::MouseButton button, const QPoint& from, const QPoint& by, int steps = 6);
    int nodeNamed(const QString& prefix) const;
    render::Aabb nodeBounds(int node) const;
    render::Aabb sceneBounds() const;

    std::unique_ptr<ui::MainWindow> m_window;
    render::Camera m_sceneCamera;
};

bool CameraTest::waitForFrame()
{
    return test::nextFrame(*m_window).width > 0;
}

QAction* CameraTest::action(const char* name) const
{
    QAction* found = m_window->findChild<QAction*>(QString::fromLatin1(name));
    if (!found)
        qFatal("no action %s", name);
    return found;
}

QPointF CameraTest::screenPosition(const render::Camera& camera, const glm::vec3& point) const
{
    // The projection clickSelectsTheObjectUnderTheCursor (tst_Editor) uses, in continuous pixel coordinates.
    const ui::ViewportWidget* viewport = m_window->viewport();
    const glm::mat4 view = glm::lookAt(camera.position, camera.lookAt, camera.up);
    const glm::mat4 projection = glm::perspective(
        glm::radians(camera.fovYDeg), float(viewport->width()) / float(viewport->height()), 0.01f, 100.0f);
    const glm::vec3 p
        = glm::project(point, view, projection, glm::vec4(0, 0, viewport->width(), viewport->height()));
    return QPointF(double(p.x), double(viewport->height()) - double(p.y));
}

sync::PickResult CameraTest::pickAt(const render::Camera& camera, const QPoint& pixel) const
{
    const ui::ViewportWidget* viewport = m_window->viewport();
    const glm::mat4 view = glm::lookAt(camera.position, camera.lookAt, camera.up);
    const glm::mat4 projection = glm::perspective(
        glm::radians(camera.fovYDeg), float(viewport->width()) / float(viewport->height()), 0.01f, 100.0f);
    const glm::vec3 onRay = glm::unProject(
        glm::vec3(float(pixel.x()) + 0.5f, float(viewport->height()) - (float(pixel.y()) + 0.5f), 0.5f), view,
        projection, glm::vec4(0, 0, viewport->width(), viewport->height()));
    return sync::pickNode(*m_window->document(), camera.position, onRay - camera.position);
}

void CameraTest::drag(Qt::MouseButton button, const QPoint& from, const QPoint& by, int steps)
{
    ui::ViewportWidget* viewport = m_window->viewport();
    QTest::mousePress(viewport, button, Qt::NoModifier, from);
    for (int i = 1; i <= steps; ++i) {
        const QPoint at = from + by * i / steps;
        QMouseEvent move(QEvent::MouseMove, QPointF(at), viewport->mapToGlobal(QPointF(at)), Qt::NoButton,
            button, Qt::NoModifier);
        QCoreApplication::sendEvent(viewport, &move);
    }
    QTest::mouseRelease(viewport, button, Qt::NoModifier, from + by);
}

int CameraTest::nodeNamed(const QString& prefix) const
{
    return test::nodeNamed(*m_window->document(), prefix);
}

render::Aabb CameraTest::nodeBounds(int node) const
{
    const doc::Document* document = m_window->document();
    const doc::SceneNode& n = document->state().nodes[std::size_t(node)];
    const glm::mat4 world = document->nodeWorldTransform(node);
    render::Aabb box;
    for (const glm::vec3& p : document->sourceScene(n.source).meshes[std::size_t(n.mesh)].positions)
        box.extend(glm::vec3(world * glm::vec4(p, 1.0f)));
    return box;
}

render::Aabb CameraTest::sceneBounds() const
{
    render::Aabb box;
    for (std::size_t i = 0; i < m_window->document()->state().nodes.size(); ++i)
        if (m_window->document()->state().nodes[i].visible)
            box.extend(nodeBounds(int(i)));
    return box;
}

void CameraTest::initTestCase()
{
    // The scene's own camera, read apart from the editor: Reset camera must come back to exactly this.
    render::Scene scene;
    QString error;
    QVERIFY2(
        doc::SceneLoader::load(QStringLiteral("builtin:cornell_point"), scene, &error), qPrintable(error));
    m_sceneCamera = scene.camera;

    m_window = test::showEditor(QStringLiteral("builtin:cornell_point"));
    QVERIFY(m_window);
    QVERIFY2(waitForFrame(), "the viewport rendered no frame");
    QVERIFY2(m_window->viewport()->lastError().isEmpty(), qPrintable(m_window->viewport()->lastError()));
    QVERIFY(doc::sameCamera(camera(), m_sceneCamera));
}

void CameraTest::init()
{
    m_window->document()->setCamera(m_sceneCamera);
    m_window->document()->setSelectedNode(-1);
}

void CameraTest::cleanupTestCase()
{
    m_window.reset();
}

// The first complaint: a drag orbited about the look-at point, metres behind what the user looked at,
// so the object under the cursor swung away. Now the surface point under the press stays under the cursor.
void CameraTest::orbitKeepsThePointUnderTheCursorInPlace()
{
    const int shortBox = nodeNamed(QStringLiteral("shortbox"));
    QVERIFY(shortBox >= 0);
    const render::Camera before = camera();
    const QPointF centre = screenPosition(before, nodeBounds(shortBox).center());
    const QPoint press(int(centre.x()), int(centre.y()));
    const sync::PickResult hit = pickAt(before, press);
    QCOMPARE(hit.node, shortBox);
    const QPointF pressed(press.x() + 0.5, press.y() + 0.5);
    QVERIFY2(QLineF(screenPosition(before, hit.point), pressed).length() < 0.5,
        "the test's projection and the viewport's ray disagree");

    drag(Qt::LeftButton, press, QPoint(60, 30));

    const render::Camera after = camera();
    const float turnedDeg
        = glm::degrees(std::acos(std::clamp(glm::dot(glm::normalize(before.lookAt - before.position),
                                                glm::normalize(after.lookAt - after.position)),
            -1.0f, 1.0f)));
    QVERIFY2(turnedDeg > 10.0f, qPrintable(QStringLiteral("the view turned only %1 degrees").arg(turnedDeg)));
    const QPointF now = screenPosition(after, hit.point);
    const double moved = QLineF(now, pressed).length();
    QVERIFY2(moved <= 2.0,
        qPrintable(QStringLiteral("the picked point %1 moved %2 px on screen, from (%3, %4) to (%5, %6)")
                       .arg(test::describe(hit.point))
                       .arg(moved)
                       .arg(pressed.x())
                       .arg(pressed.y())
                       .arg(now.x())
                       .arg(now.y())));
    QCOMPARE(m_window->document()->selectedNode(), -1); // a drag, not a click
}

void CameraTest::orbitOverNothingTurnsAboutTheSelection()
{
    const int tallBox = nodeNamed(QStringLiteral("tallbox"));
    QVERIFY(tallBox >= 0);
    m_window->document()->setSelectedNode(tallBox);
    const QPoint press(2, 2); // the black outside the box
    QCOMPARE(pickAt(camera(), press).node, -1);
    const glm::vec3 centre = nodeBounds(tallBox).center();
    const QPointF before = screenPosition(camera(), centre);
    drag(Qt::LeftButton, press, QPoint(60, 30));
    const QPointF after = screenPosition(camera(), centre);
    QVERIFY2(QLineF(before, after).length() <= 2.0,
        qPrintable(QStringLiteral("the selection's centre moved from (%1, %2) to (%3, %4)")
                       .arg(before.x())
                       .arg(before.y())
                       .arg(after.x())
                       .arg(after.y())));
    QCOMPARE(m_window->document()->selectedNode(), tallBox);
}

void CameraTest::resetCameraRestoresTheSceneCamera()
{
    QAction* reset = action("resetCameraAction");
    QCOMPARE(reset->shortcut(), QKeySequence(Qt::Key_Home));
    ui::ViewportWidget* viewport = m_window->viewport();
    drag(Qt::LeftButton, QPoint(viewport->width() / 2, viewport->height() / 2), QPoint(400, 150), 20);
    drag(Qt::MiddleButton, QPoint(viewport->width() / 2, viewport->height() / 2), QPoint(-80, 40));
    QVERIFY2(glm::distance(camera().position, m_sceneCamera.position) > 1.0f, qPrintable(describe(camera())));
    reset->trigger();
    QVERIFY2(doc::sameCamera(camera(), m_sceneCamera), qPrintable(describe(camera())));
    QCOMPARE(camera().position, m_sceneCamera.position);
    QCOMPARE(camera().lookAt, m_sceneCamera.lookAt);
    QCOMPARE(camera().up, m_sceneCamera.up);

    // After a save the document's own camera is the one saved, as reopening the project would give.
    drag(Qt::LeftButton, QPoint(viewport->width() / 2, viewport->height() / 2), QPoint(-90, 0));
    const render::Camera saved = camera();
    const QString path = test::outputDir() + QStringLiteral("/camera-reset.vctproj");
    QFile::remove(path);
    QVERIFY(m_window->saveProjectAs(path));
    drag(Qt::LeftButton, QPoint(viewport->width() / 2, viewport->height() / 2), QPoint(200, 50));
    QVERIFY(!doc::sameCamera(camera(), saved));
    reset->trigger();
    QVERIFY2(doc::sameCamera(camera(), saved), qPrintable(describe(camera())));
}

void CameraTest::undoViewReturnsToTheCameraBeforeTheLastGesture()
{
    QAction* undoView = action("undoViewAction");
    QVERIFY(undoView->shortcut() != QKeySequence(QKeySequence::Redo));
    ui::ViewportWidget* viewport = m_window->viewport();
    const QPoint middle(viewport->width() / 2, viewport->height() / 2);
    const render::Camera start = camera();
    drag(Qt::LeftButton, middle, QPoint(80, -20));
    const render::Camera orbited = camera();
    QVERIFY(!doc::sameCamera(orbited, start));
    drag(Qt::MiddleButton, middle, QPoint(-50, 30));
    QVERIFY(!doc::sameCamera(camera(), orbited));
    QVERIFY(undoView->isEnabled());

    undoView->trigger();
    QVERIFY2(doc::sameCamera(camera(), orbited), qPrintable(describe(camera())));
    undoView->trigger();
    QVERIFY2(doc::sameCamera(camera(), start), qPrintable(describe(camera())));

    // A wheel burst is one gesture, undone at once even before the wheel has settled.
    for (int i = 0; i < 3; ++i) {
        QWheelEvent wheel(QPointF(middle), viewport->mapToGlobal(QPointF(middle)), QPoint(), QPoint(0, 120),
            Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
        QCoreApplication::sendEvent(viewport, &wheel);
    }
    QVERIFY(!doc::sameCamera(camera(), start));
    undoView->trigger();
    QVERIFY2(doc::sameCamera(camera(), start), qPrintable(describe(camera())));

    // Frame and reset are gestures too.
    action("frameAllAction")->trigger();
    const render::Camera framed = camera();
    QVERIFY(!doc::sameCamera(framed, start));
    drag(Qt::LeftButton, middle, QPoint(-70, 0));
    const render::Camera orbitedAgain = camera();
    action("resetCameraAction")->trigger();
    QVERIFY(doc::sameCamera(camera(), m_window->document()->savedCamera()));
    undoView->trigger();
    QVERIFY2(doc::sameCamera(camera(), orbitedAgain), qPrintable(describe(camera())));
    undoView->trigger();
    QVERIFY2(doc::sameCamera(camera(), framed), qPrintable(describe(camera())));
    undoView->trigger();
    QVERIFY2(doc::sameCamera(camera(), start), qPrintable(describe(camera())));
}

void CameraTest::undoViewKeepsTheLast32Cameras()
{
    QAction* undoView = action("undoViewAction");
    ui::ViewportWidget* viewport = m_window->viewport();
    const QPoint middle(viewport->width() / 2, viewport->height() / 2);
    std::vector<render::Camera> before;
    for (int i = 0; i < 40; ++i) {
        before.push_back(camera());
        drag(Qt::LeftButton, middle, QPoint(10, 0), 2);
    }
    int undone = 0;
    while (undoView->isEnabled() && undone < 100) {
        undoView->trigger();
        ++undone;
        QVERIFY2(doc::sameCamera(camera(), before[before.size() - std::size_t(undone)]),
            qPrintable(QStringLiteral("undo %1: %2").arg(undone).arg(describe(camera()))));
    }
    QCOMPARE(undone, 32);
}

// The second complaint: framing everything from inside a building backed the camera out through the
// wall. From inside the scene's bounds Frame all keeps the camera where it is and turns it to their centre.
void CameraTest::frameAllFromInsideStaysInside()
{
    const render::Aabb bounds = sceneBounds();
    QVERIFY(!bounds.isEmpty());
    auto inside = [&bounds](const glm::vec3& p) {
        return glm::all(glm::greaterThan(p, bounds.min)) && glm::all(glm::lessThan(p, bounds.max));
    };
    render::Camera inRoom = m_sceneCamera;
    inRoom.position = bounds.center() + bounds.size() * glm::vec3(0.3f, -0.2f, 0.35f);
    inRoom.lookAt = inRoom.position + glm::vec3(1.0f, 0.0f, 0.0f);
    QVERIFY(inside(inRoom.position));
    m_window->document()->setCamera(inRoom);

    action("frameAllAction")->trigger();
    QVERIFY2(inside(camera().position), qPrintable(describe(camera())));
    QCOMPARE(camera().position, inRoom.position);
    QCOMPARE(camera().lookAt, bounds.center());
    QCOMPARE(camera().up, inRoom.up);

    // F with nothing selected frames everything, and so also stays inside.
    m_window->document()->setCamera(inRoom);
    m_window->viewport()->frameSelected();
    QVERIFY2(inside(camera().position), qPrintable(describe(camera())));

    // From outside, Frame all still backs off to fit the whole scene in view.
    QVERIFY(!inside(m_sceneCamera.position));
    m_window->document()->setCamera(m_sceneCamera);
    action("frameAllAction")->trigger();
    QVERIFY(!inside(camera().position));
    QCOMPARE(camera().lookAt, bounds.center());
    const float radius = 0.5f * glm::length(bounds.size());
    QVERIFY(glm::distance(camera().position, bounds.center()) > radius);
}

QTEST_MAIN(CameraTest)
// The view has the keys from the start, and takes them back when the pointer comes over it, but not from a
// field being typed in.
void CameraTest::viewKeysWorkWithoutAClickFirst()
{
    auto window = test::showEditor(QStringLiteral("builtin:cornell_point"));
    QVERIFY(window);
    QTRY_COMPARE(window->focusWidget(), static_cast<QWidget*>(window->viewport()));

    const auto enterView = [&] {
        const QPointF centre(window->viewport()->width() / 2.0, window->viewport()->height() / 2.0);
        QEnterEvent enter(centre, centre, window->viewport()->mapToGlobal(centre));
        QApplication::sendEvent(window->viewport(), &enter);
    };
    auto* name = window->findChild<QLineEdit*>(QStringLiteral("lightName"));
    QVERIFY(name);
    name->setFocus();
    QTRY_COMPARE(window->focusWidget(), static_cast<QWidget*>(name));
    enterView();
    QCOMPARE(window->focusWidget(), static_cast<QWidget*>(name));

    auto* tree = window->findChild<QTreeView*>();
    QVERIFY(tree);
    tree->setFocus();
    QTRY_COMPARE(window->focusWidget(), static_cast<QWidget*>(tree));
    enterView();
    QCOMPARE(window->focusWidget(), static_cast<QWidget*>(window->viewport()));
}

// View > Bookmark view keeps the camera in the document (one undo step); its entry in View > Bookmarks
// (Ctrl+1) goes back to it, as a step of Undo view.
void CameraTest::bookmarksReturnToAViewAndUndo()
{
    const render::Camera kept = camera();
    const int steps = m_window->document()->undoStack()->count();
    action("bookmarkViewAction")->trigger();
    QCOMPARE(m_window->document()->state().bookmarks.size(), std::size_t(1));
    QCOMPARE(m_window->document()->state().bookmarks[0].name, QStringLiteral("View 1"));
    QCOMPARE(m_window->document()->undoStack()->count(), steps + 1);
    QVERIFY(m_window->document()->isModified());

    render::Camera moved = kept;
    moved.position += glm::vec3(0.3f, 0.1f, -0.2f);
    m_window->document()->setCamera(moved);
    QAction* go = action("bookmark0Action");
    QCOMPARE(go->shortcut(), QKeySequence(Qt::CTRL | Qt::Key_1));
    go->trigger();
    QVERIFY(doc::sameCamera(camera(), kept));
    action("undoViewAction")->trigger();
    QVERIFY(doc::sameCamera(camera(), moved));

    m_window->document()->undoStack()->undo();
    QVERIFY(m_window->document()->state().bookmarks.empty());
    QVERIFY(!m_window->findChild<QAction*>(QStringLiteral("bookmark0Action")));
}

#include "tst_Camera.moc"
