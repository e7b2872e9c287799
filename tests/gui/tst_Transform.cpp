#include "EditorTestSetup.h"
#include "TestSupport.h"
#include "ui/MainWindow.h"
#include "ui/MaterialDock.h"
#include "ui/RenderSettingsDock.h"
#include "ui/TransformDock.h"
#include "ui/ViewportWidget.h"

#include "core/FrameStats.h"
#include "document/Document.h"

#include <glm/gtc/matrix_transform.hpp>

#include <QDoubleSpinBox>
#include <QMenu>
#include <QMenuBar>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QSurfaceFormat>
#include <QUndoStack>
#include <QtTest>

#include <cmath>

using namespace vct;

namespace {

bool nearlyEqual(const glm::mat4& a, const glm::mat4& b, float tolerance = 1e-5f)
{
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (std::abs(a[c][r] - b[c][r]) > tolerance)
                return false;
    return true;
}

/** What the voxelize pass did in a frame and why, e.g. "run: static geometry or grid changed". */
std::string voxelizing(const render::FrameStats& stats)
{
    for (const render::PassStats& pass : stats.passes)
        if (pass.name == "voxelize")
            return pass.action + ": " + pass.reason;
    return "no voxelize pass";
}

QString describe(const doc::NodeTransform& t)
{
    return QStringLiteral("translation %1 rotation %2 scale %3")
        .arg(test::describe(t.translation), test::describe(t.rotationDeg), test::describe(t.scale));
}

} // namespace

/** The Transform panel in the real editor window, with llvmpipe behind the viewport (under Xvfb). */
class TransformTest : public QObject {
    Q_OBJECT

public:
    static void initMain() { test::prepareEditorApplication(); }

private slots:
    void initTestCase();
    void cleanupTestCase();
    void panelSitsBesideTheMaterialInTheViewMenu();
    void withoutSelectionThePanelIsDisabled();
    void eachFieldIsItsOwnUndoStep();
    void uniformScaleReadsMixedAndSetsAllAxes();
    void valuesStayInRange();

private:
    QDoubleSpinBox* spin(const char* name) const;
    /** The stats of the next frame the viewport renders, or empty stats if none comes. */
    render::FrameStats nextFrame();
    int shortBox() const;

    std::unique_ptr<ui::MainWindow> m_window;
};

QDoubleSpinBox* TransformTest::spin(const char* name) const
{
    auto* box = m_window->transformDock()->findChild<QDoubleSpinBox*>(QString::fromLatin1(name));
    if (!box)
        qFatal("the Transform panel has no spin box %s", name);
    return box;
}

render::FrameStats TransformTest::nextFrame()
{
    return test::nextFrame(*m_window);
}

int TransformTest::shortBox() const
{
    return test::nodeNamed(*m_window->document(), QStringLiteral("shortbox"));
}

void TransformTest::initTestCase()
{
    qRegisterMetaType<render::FrameStats>();
    m_window = test::showEditor(QStringLiteral("builtin:cornell_point"));
    QVERIFY(m_window);
    QVERIFY2(!nextFrame().passes.empty(), "the viewport rendered no frame");
    QVERIFY2(m_window->viewport()->lastError().isEmpty(), qPrintable(m_window->viewport()->lastError()));
    QVERIFY(shortBox() >= 0);
}

void TransformTest::cleanupTestCase()
{
    m_window.reset();
}

void TransformTest::panelSitsBesideTheMaterialInTheViewMenu()
{
    ui::TransformDock* dock = m_window->findChild<ui::TransformDock*>(QStringLiteral("transformDock"));
    QVERIFY(dock);
    QCOMPARE(dock, m_window->transformDock());
    QCOMPARE(dock->windowTitle(), QStringLiteral("Transform"));
    QCOMPARE(m_window->dockWidgetArea(dock), Qt::RightDockWidgetArea);
    QVERIFY(m_window->tabifiedDockWidgets(m_window->materialDock()).contains(dock));

    // The View menu lists it with the other panels.
    QMenu* view = nullptr;
    for (QAction* action : m_window->menuBar()->actions())
        if (action->menu() && action->menu()->title().remove(QLatin1Char('&')) == QStringLiteral("View"))
            view = action->menu();
    QVERIFY(view);
    QVERIFY(view->actions().contains(dock->toggleViewAction()));

    // A tab of the material's group must not widen the column, or the viewport would give way to it: not with
    // nothing selected, nor once a selection shows the editors.
    const int viewportWidth = m_window->viewport()->width();
    for (int node : { -1, shortBox() }) {
        m_window->document()->setSelectedNode(node);
        QTest::qWait(100); // the dock layout settles on a posted layout request
        const int widest = std::max(
            m_window->materialDock()->sizeHint().width(), m_window->renderSettingsDock()->sizeHint().width());
        const QString widths
            = QStringLiteral("selection %1: minimum %2 (material %3), size hint %4 (widest %5), "
                             "viewport %6 (%7 before)")
                  .arg(node)
                  .arg(dock->minimumSizeHint().width())
                  .arg(m_window->materialDock()->minimumSizeHint().width())
                  .arg(dock->sizeHint().width())
                  .arg(widest)
                  .arg(m_window->viewport()->width())
                  .arg(viewportWidth);
        qInfo("%s", qPrintable(widths));
        QVERIFY2(dock->minimumSizeHint().width() <= m_window->materialDock()->minimumSizeHint().width(),
            qPrintable(widths));
        QVERIFY2(dock->sizeHint().width() <= widest, qPrintable(widths));
        QVERIFY2(m_window->viewport()->width() == viewportWidth, qPrintable(widths));
    }
    m_window->document()->setSelectedNode(-1);
}

void TransformTest::withoutSelectionThePanelIsDisabled()
{
    doc::Document* document = m_window->document();
    document->setSelectedNode(shortBox());
    QVERIFY(spin("positionX")->isEnabled());
    document->setSelectedNode(-1);
    for (const char* name : { "positionX", "positionY", "positionZ", "rotationX", "rotationY", "rotationZ",
             "uniformScale", "scaleX", "scaleY", "scaleZ" }) {
        QVERIFY2(!spin(name)->isEnabled(), name);
        QVERIFY2(!spin(name)->isVisibleTo(m_window->transformDock()), name);
    }
    // Nothing to edit: a value forced into a box changes no node.
    const doc::DocumentState before = document->state();
    const int steps = document->undoStack()->count();
    spin("positionX")->setValue(spin("positionX")->value() + 1.0);
    QCOMPARE(document->undoStack()->count(), steps);
    for (std::size_t i = 0; i < before.nodes.size(); ++i)
        QVERIFY(document->state().nodes[i].transform == before.nodes[i].transform);
}

void TransformTest::eachFieldIsItsOwnUndoStep()
{
    doc::Document* document = m_window->document();
    QUndoStack* undo = document->undoStack();
    const int node = shortBox();
    QVERIFY2(!document->state().nodes[std::size_t(node)].dynamic, "the short box is a static node");
    document->setSelectedNode(node);
    const doc::NodeTransform original = document->state().nodes[std::size_t(node)].transform;
    // Unrotated and unscaled, so that the expected rotation below is simply 30 degrees about Y.
    QCOMPARE(original.rotationDeg, glm::vec3(0.0f));
    QCOMPARE(original.scale, glm::vec3(1.0f));
    const glm::mat4 originalWorld = document->nodeWorldTransform(node);
    // The mesh's own placement, which the node's transform is applied on top of.
    const glm::mat4 imported = glm::inverse(original.matrix()) * originalWorld;
    const auto transform = [&] { return document->state().nodes[std::size_t(node)].transform; };
    const auto expectWorld = [&](const char* step) {
        const glm::mat4 expected = transform().matrix() * imported;
        QVERIFY2(nearlyEqual(document->nodeWorldTransform(node), expected), step);
    };
    QCOMPARE(spin("positionX")->value(), double(original.translation.x));
    QCOMPARE(spin("uniformScale")->value(), double(original.scale.x));
    // Settled: the voxels are reused until an edit, so it is the edit below that re-voxelizes.
    const std::string idle = voxelizing(nextFrame());
    QVERIFY2(idle.rfind("reused", 0) == 0, idle.c_str());
    const int steps = undo->index();

    // X position, in two steps of one gesture (the spin box's arrows): one undo step.
    const double x = double(original.translation.x) + 0.1;
    spin("positionX")->stepBy(5); // 0.01 m a step
    spin("positionX")->setValue(x);
    QCOMPARE(undo->index(), steps + 1);
    QCOMPARE(transform().translation.x, float(x));
    QCOMPARE(transform().translation.y, original.translation.y);
    QCOMPARE(transform().translation.z, original.translation.z);
    QCOMPARE(transform().rotationDeg, original.rotationDeg);
    QCOMPARE(transform().scale, original.scale);
    expectWorld("after moving along X");
    QVERIFY(std::abs(document->nodeWorldTransform(node)[3].x - originalWorld[3].x - 0.1f) < 1e-5f);

    // The viewport re-voxelizes the moved static node (SceneSync turns the edit into a mesh transform), in
    // the first frame of the rebuild.
    const std::string moved = voxelizing(test::firstFrame(*m_window));
    QVERIFY2(moved == "run: static geometry or grid changed", moved.c_str());

    // Rotation about Y: the next step.
    spin("rotationY")->setValue(30.0);
    QCOMPARE(undo->index(), steps + 2);
    QCOMPARE(transform().rotationDeg.y, 30.0f);
    QCOMPARE(transform().translation.x, float(x));
    expectWorld("after rotating about Y");
    const glm::mat4 turned = glm::rotate(glm::mat4(1.0f), glm::radians(30.0f), glm::vec3(0, 1, 0));
    QVERIFY(nearlyEqual(glm::mat4(glm::mat3(transform().matrix())), turned));

    // Uniform scale: the third step, all three axes at once.
    spin("uniformScale")->setValue(1.5);
    QCOMPARE(undo->index(), steps + 3);
    QCOMPARE(transform().scale, glm::vec3(1.5f));
    QCOMPARE(transform().rotationDeg.y, 30.0f);
    QCOMPARE(spin("scaleX")->value(), 1.5);
    QCOMPARE(spin("scaleZ")->value(), 1.5);
    expectWorld("after scaling");
    QVERIFY(undo->text(undo->count() - 1).startsWith(QStringLiteral("Scale ")));
    QVERIFY(undo->text(undo->count() - 2).startsWith(QStringLiteral("Rotate ")));
    QVERIFY(undo->text(undo->count() - 3).startsWith(QStringLiteral("Move ")));
    const doc::NodeTransform edited = transform();

    // Three undos give back the original exactly, and the panel follows.
    undo->undo();
    QCOMPARE(transform().scale, original.scale);
    QCOMPARE(transform().rotationDeg.y, 30.0f);
    QCOMPARE(spin("uniformScale")->value(), double(original.scale.x));
    undo->undo();
    QCOMPARE(transform().rotationDeg, original.rotationDeg);
    QCOMPARE(transform().translation.x, float(x));
    QCOMPARE(spin("rotationY")->value(), double(original.rotationDeg.y));
    undo->undo();
    QVERIFY2(transform() == original, qPrintable(describe(transform())));
    QVERIFY(document->nodeWorldTransform(node) == originalWorld);
    QCOMPARE(undo->count() - undo->index(), 3);
    QCOMPARE(spin("positionX")->value(), double(original.translation.x));

    // Redo puts every edit back.
    undo->redo();
    QCOMPARE(transform().translation.x, float(x));
    QCOMPARE(spin("positionX")->value(), x);
    undo->redo();
    undo->redo();
    QVERIFY2(transform() == edited, qPrintable(describe(transform())));
    QCOMPARE(spin("uniformScale")->value(), 1.5);
    expectWorld("after redo");

    undo->setIndex(steps);
    QVERIFY(transform() == original);
}

void TransformTest::uniformScaleReadsMixedAndSetsAllAxes()
{
    doc::Document* document = m_window->document();
    QUndoStack* undo = document->undoStack();
    const int node = shortBox();
    document->setSelectedNode(node);
    const doc::NodeTransform original = document->state().nodes[std::size_t(node)].transform;
    const auto transform = [&] { return document->state().nodes[std::size_t(node)].transform; };
    const int steps = undo->index();

    spin("scaleY")->setValue(2.0);
    spin("scaleZ")->setValue(3.0);
    QCOMPARE(transform().scale, glm::vec3(1.0f, 2.0f, 3.0f));
    QCOMPARE(undo->index(), steps + 2); // one step per axis
    QCOMPARE(spin("uniformScale")->text(), QStringLiteral("mixed"));
    // A wheel turn or an arrow over "mixed" changes nothing: there is no one value to step from.
    spin("uniformScale")->stepBy(1);
    QCOMPARE(transform().scale, glm::vec3(1.0f, 2.0f, 3.0f));
    QCOMPARE(undo->index(), steps + 2);

    // Setting the uniform scale sets each axis to it (not a factor on top of theirs).
    spin("uniformScale")->setValue(2.0);
    QCOMPARE(transform().scale, glm::vec3(2.0f));
    QCOMPARE(spin("scaleY")->value(), 2.0);
    QVERIFY(spin("uniformScale")->text() != QStringLiteral("mixed"));

    // The "mixed" marker below the smallest scale is no edit, and stepping down stops at the smallest scale.
    spin("uniformScale")->setValue(0.0);
    QCOMPARE(transform().scale, glm::vec3(2.0f));
    QCOMPARE(undo->index(), steps + 3);
    spin("uniformScale")->setValue(0.0002);
    spin("uniformScale")->stepBy(-10);
    QCOMPARE(transform().scale, glm::vec3(1.0e-4f));
    QCOMPARE(spin("uniformScale")->text(), QStringLiteral("0.0001"));
    QCOMPARE(undo->index(), steps + 3); // one run of uniform edits: still the third step

    undo->setIndex(steps);
    QVERIFY(transform() == original);
    QCOMPARE(spin("uniformScale")->value(), double(original.scale.x));
}

void TransformTest::valuesStayInRange()
{
    doc::Document* document = m_window->document();
    QUndoStack* undo = document->undoStack();
    const int node = shortBox();
    document->setSelectedNode(node);
    const doc::NodeTransform original = document->state().nodes[std::size_t(node)].transform;
    const auto transform = [&] { return document->state().nodes[std::size_t(node)].transform; };
    const int steps = undo->index();

    spin("positionZ")->setValue(1.0e9);
    QCOMPARE(transform().translation.z, 1.0e6f);
    spin("positionZ")->setValue(-std::numeric_limits<double>::infinity());
    QCOMPARE(transform().translation.z, -1.0e6f);
    spin("scaleX")->setValue(0.0);
    QCOMPARE(transform().scale.x, 1.0e-4f);
    spin("scaleX")->setValue(1.0e9);
    QCOMPARE(transform().scale.x, 1.0e4f);
    spin("uniformScale")->setValue(std::numeric_limits<double>::quiet_NaN());
    const glm::vec3 scale = transform().scale;
    for (int i = 0; i < 3; ++i)
        QVERIFY2(std::isfinite(scale[i]) && scale[i] > 0.0f, qPrintable(test::describe(scale)));

    undo->setIndex(steps);
    QVERIFY(transform() == original);
}

QTEST_MAIN(TransformTest)
#include "tst_Transform.moc"
