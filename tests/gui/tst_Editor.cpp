#include "EditorTestSetup.h"
#include "TestSupport.h"

#include "ui/ExportSize.h"
#include "ui/MainWindow.h"
#include "ui/MaterialDock.h"
#include "ui/NonFiniteOverlay.h"
#include "ui/RenderSettingsDock.h"
#include "ui/StatsDock.h"
#include "ui/ViewportOverlay.h"
#include "ui/ViewportWidget.h"
#include "ui/VoxelInspectorDock.h"

#include "document/Document.h"
#include "document/DocumentState.h"
#include "imageio/ImageMetrics.h"

#include "imageio/ImageFile.h"

#include <glm/gtc/matrix_transform.hpp>

#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QLabel>
#include <QSignalSpy>
#include <QSlider>
#include <QStandardPaths>
#include <QStatusBar>
#include <QSurfaceFormat>
#include <QUndoStack>
#include <QtTest>

using namespace vct;

/** The editor driven through its real widgets under Xvfb, with llvmpipe behind the viewport. */
class EditorTest : public QObject {
    Q_OBJECT

public:
    static void initMain() { test::prepareEditorApplication(); }

private slots:
    void initTestCase();
    void cleanupTestCase();
    void viewportShowsAnImage();
    void emissiveFlagBrightensAndUndoRestores();
    void inspectorCountsMatchTheVoxels();
    void inspectorShowsEachClipmapLevel();
    void clickSelectsTheObjectUnderTheCursor();
    void ctrlDragMovesTheSelectionInOneUndoStep();
    void exportWritesImages();
    void viewportSurvivesContextRecreation();
    void inspectorScreenshot();
    void saveCloseOpenGivesTheSameDocument();
    void badFilesLeaveTheDocumentAlone();
    void recoveredWorkIsUntitledAndSurvivesUntilSaved();
    void nonFiniteOverlayReportsEveryTarget();
    void f5ReloadsShadersAndSaysWhatFailed();
    void overlayShowsSelectionLightsAndFigures();

private:
    bool waitForFrame();
    double meanRadiance();
    std::unique_ptr<ui::MainWindow> m_window;
};

bool EditorTest::waitForFrame()
{
    return test::nextFrame(*m_window).width > 0;
}

double EditorTest::meanRadiance()
{
    const render::RadianceImage image = m_window->viewport()->renderFullFrame(48, 48);
    return image.isEmpty() ? -1.0 : io::ImageMetrics::meanLuminance(image);
}

void EditorTest::initTestCase()
{
    m_window = test::showEditor(QStringLiteral("builtin:cornell_point"));
    QVERIFY(m_window);
    QVERIFY2(waitForFrame(), "the viewport rendered no frame");
    QVERIFY2(m_window->viewport()->lastError().isEmpty(), qPrintable(m_window->viewport()->lastError()));
}

void EditorTest::cleanupTestCase()
{
    m_window.reset();
}

void EditorTest::viewportShowsAnImage()
{
    const QImage frame = m_window->viewport()->grabFramebuffer();
    QVERIFY(!frame.isNull());
    double sum = 0.0;
    for (int y = 0; y < frame.height(); y += 4)
        for (int x = 0; x < frame.width(); x += 4)
            sum += qGray(frame.pixel(x, y));
    const double mean = sum / double((frame.height() / 4 + 1) * (frame.width() / 4 + 1));
    QVERIFY2(mean > 20.0, qPrintable(QString("mean grey %1").arg(mean)));
    const QString screenshot = test::outputDir() + QStringLiteral("/editor-screenshot.png");
    QVERIFY(m_window->grab().save(screenshot));
    qInfo("screenshot of the main window: %s", qPrintable(screenshot));
}

void EditorTest::emissiveFlagBrightensAndUndoRestores()
{
    doc::Document* document = m_window->document();
    // Select a node whose material is the white of the walls and boxes.
    int node = -1;
    for (std::size_t i = 0; i < document->state().nodes.size(); ++i)
        if (document->state().materials[std::size_t(document->state().nodes[i].material)].name == "white")
            node = int(i);
    QVERIFY(node >= 0);
    document->setSelectedNode(node);
    QCheckBox* emissive = m_window->materialDock()->findChild<QCheckBox*>(QStringLiteral("emissiveCheck"));
    QVERIFY(emissive);
    QVERIFY(!emissive->isChecked());
    const double before = meanRadiance();
    const int undoBefore = document->undoStack()->count();
    emissive->click();
    QVERIFY(emissive->isChecked());
    QCOMPARE(document->undoStack()->count(), undoBefore + 1);
    const double lit = meanRadiance();
    QVERIFY2(lit > before * 1.2, qPrintable(QString("%1 -> %2").arg(before).arg(lit)));
    document->undoStack()->undo();
    QVERIFY(!emissive->isChecked());
    const double restored = meanRadiance();
    QVERIFY2(std::abs(restored - before) <= 1e-3 * (1.0 + before),
        qPrintable(QString("%1 vs %2").arg(restored).arg(before)));
}

void EditorTest::inspectorCountsMatchTheVoxels()
{
    ui::VoxelInspectorDock* inspector = m_window->inspectorDock();
    QComboBox* resolution
        = m_window->renderSettingsDock()->findChild<QComboBox*>(QStringLiteral("voxelResolutionCombo"));
    QVERIFY(resolution);
    const int index = resolution->findText(QStringLiteral("64"), Qt::MatchStartsWith);
    QVERIFY(index >= 0);
    resolution->setCurrentIndex(index);
    QCOMPARE(m_window->document()->state().settings.voxelResolution, 64);
    inspector->enabledBox()->setChecked(true);
    inspector->levelSlider()->setValue(0);
    QVERIFY(waitForFrame());
    QCOMPARE(m_window->viewport()->voxelLevelCount(), 7);
    QCOMPARE(inspector->levelSlider()->maximum(), 6);
    const std::size_t occupied = m_window->viewport()->occupiedVoxelCount();
    QVERIFY(occupied > 0);
    QCOMPARE(m_window->viewport()->lastCubeCount(), occupied);
    QVERIFY(inspector->countLabel()->text().contains(QString::number(occupied)));
    std::size_t previous = occupied;
    for (int level = 1; level <= inspector->levelSlider()->maximum(); ++level) {
        inspector->levelSlider()->setValue(level);
        QVERIFY(waitForFrame());
        const std::size_t count = m_window->viewport()->lastCubeCount();
        QVERIFY2(count <= previous,
            qPrintable(QString("level %1: %2 after %3").arg(level).arg(count).arg(previous)));
        QVERIFY(count > 0);
        previous = count;
    }
    inspector->enabledBox()->setChecked(false);
}

// With a clipmap the inspector offers each of its levels, and each shows its own cubes; back to one grid, the
// choice goes.
void EditorTest::inspectorShowsEachClipmapLevel()
{
    ui::VoxelInspectorDock* inspector = m_window->inspectorDock();
    QComboBox* grids
        = m_window->renderSettingsDock()->findChild<QComboBox*>(QStringLiteral("gridLevelsCombo"));
    QVERIFY(grids);
    QCOMPARE(inspector->gridBox()->count(), 1);
    QVERIFY(!inspector->gridBox()->isEnabled());
    grids->setCurrentIndex(grids->findData(2));
    QCOMPARE(m_window->document()->state().settings.clipLevels, 2);
    inspector->enabledBox()->setChecked(true);
    inspector->levelSlider()->setValue(0);
    QVERIFY(waitForFrame());
    QVERIFY(waitForFrame()); // the first frame with the inspector on tells the panel how many grids there are
    QCOMPARE(m_window->viewport()->voxelGridCount(), 2);
    QCOMPARE(inspector->gridBox()->count(), 2);
    QVERIFY(inspector->gridBox()->isEnabled());
    std::vector<std::size_t> cubes;
    for (int grid = 0; grid < 2; ++grid) {
        inspector->gridBox()->setCurrentIndex(grid);
        QCOMPARE(m_window->viewport()->inspector().grid, grid);
        QVERIFY(waitForFrame());
        cubes.push_back(m_window->viewport()->lastCubeCount());
        QVERIFY2(cubes.back() > 0, qPrintable(QString("grid %1 drew no cubes").arg(grid)));
        QVERIFY(inspector->countLabel()->text().contains(QString::number(cubes.back())));
    }
    // The levels are different grids: the coarser holds the whole room, the finer (cells half as wide) the
    // part of it in front of the camera.
    QVERIFY2(cubes[0] != cubes[1], qPrintable(QString("%1 and %2 cubes").arg(cubes[0]).arg(cubes[1])));
    // An edit back, not an undo: later cases count the undo stack's steps.
    grids->setCurrentIndex(grids->findData(1));
    QCOMPARE(m_window->document()->state().settings.voxelMode, render::VoxelMode::Dense);
    QVERIFY(waitForFrame());
    QCOMPARE(inspector->gridBox()->count(), 1);
    QCOMPARE(m_window->viewport()->inspector().grid, 0);
    // The same grid sparse (voxel_mode=sparse) shows the same voxels: its cubes come from the bricks.
    QVERIFY(waitForFrame());
    const std::size_t dense = m_window->viewport()->lastCubeCount();
    QVERIFY(dense > 0);
    grids->setCurrentIndex(grids->findData(0));
    QCOMPARE(m_window->document()->state().settings.voxelMode, render::VoxelMode::Sparse);
    QVERIFY(waitForFrame());
    QVERIFY(waitForFrame());
    QCOMPARE(m_window->viewport()->lastCubeCount(), dense);
    const auto* gridLabel = m_window->statsDock()->findChild<QLabel*>(QStringLiteral("voxelGridLabel"));
    QVERIFY(gridLabel);
    QVERIFY2(gridLabel->text().contains(QStringLiteral("bricks stored")), qPrintable(gridLabel->text()));
    grids->setCurrentIndex(grids->findData(1));
    QCOMPARE(m_window->document()->state().settings.voxelMode, render::VoxelMode::Dense);
    QVERIFY(waitForFrame());
    inspector->enabledBox()->setChecked(false);
}

void EditorTest::clickSelectsTheObjectUnderTheCursor()
{
    doc::Document* document = m_window->document();
    ui::ViewportWidget* viewport = m_window->viewport();
    int shortBox = -1;
    for (std::size_t i = 0; i < document->state().nodes.size(); ++i)
        if (document->state().nodes[i].name.startsWith(QStringLiteral("shortbox")))
            shortBox = int(i);
    QVERIFY(shortBox >= 0);
    // Project the short box's centre with the viewport's camera and click there.
    const render::Scene& source
        = document->sourceScene(document->state().nodes[std::size_t(shortBox)].source);
    render::Aabb box;
    const glm::mat4 world = document->nodeWorldTransform(shortBox);
    for (const glm::vec3& p :
        source.meshes[std::size_t(document->state().nodes[std::size_t(shortBox)].mesh)].positions)
        box.extend(glm::vec3(world * glm::vec4(p, 1.0f)));
    const render::Camera& camera = document->state().camera;
    const glm::mat4 view = glm::lookAt(camera.position, camera.lookAt, camera.up);
    const glm::mat4 projection = glm::perspective(
        glm::radians(camera.fovYDeg), float(viewport->width()) / float(viewport->height()), 0.01f, 100.0f);
    const glm::vec3 p = glm::project(
        box.center(), view, projection, glm::vec4(0, 0, viewport->width(), viewport->height()));
    const QPoint click(int(p.x), viewport->height() - 1 - int(p.y));
    document->setSelectedNode(-1);
    QTest::mouseClick(viewport, Qt::LeftButton, Qt::NoModifier, click);
    QCOMPARE(document->selectedNode(), shortBox);
    QTest::mouseClick(viewport, Qt::LeftButton, Qt::NoModifier, QPoint(2, 2)); // the black outside the box
    QVERIFY(document->selectedNode() != shortBox);
}

void EditorTest::ctrlDragMovesTheSelectionInOneUndoStep()
{
    doc::Document* document = m_window->document();
    ui::ViewportWidget* viewport = m_window->viewport();
    const int node = 0;
    document->setSelectedNode(node);
    const doc::NodeTransform before = document->state().nodes[node].transform;
    const int steps = document->undoStack()->count();
    const QPoint start(viewport->width() / 4, viewport->height() / 2);
    QTest::keyPress(viewport, Qt::Key_Y);
    QTest::mousePress(viewport, Qt::LeftButton, Qt::ControlModifier, start);
    for (int i = 1; i <= 5; ++i) {
        QMouseEvent move(QEvent::MouseMove, QPointF(start + QPoint(3 * i, -4 * i)),
            viewport->mapToGlobal(QPointF(start + QPoint(3 * i, -4 * i))), Qt::NoButton, Qt::LeftButton,
            Qt::ControlModifier);
        QCoreApplication::sendEvent(viewport, &move);
    }
    QTest::mouseRelease(viewport, Qt::LeftButton, Qt::ControlModifier, start + QPoint(15, -20));
    QTest::keyRelease(viewport, Qt::Key_Y);
    const doc::NodeTransform after = document->state().nodes[node].transform;
    QVERIFY2(after.translation.y > before.translation.y, "dragging up with Y held moves the node up");
    QCOMPARE(after.translation.x, before.translation.x); // kept on the Y axis
    QCOMPARE(after.translation.z, before.translation.z);
    QCOMPARE(document->undoStack()->count(), steps + 1); // five moves, one step
    document->undoStack()->undo();
    QVERIFY(document->state().nodes[node].transform == before);
}

void EditorTest::exportWritesImages()
{
    const QString png = test::outputDir() + QStringLiteral("/editor-export.png");
    const QString pfm = test::outputDir() + QStringLiteral("/editor-export.pfm");
    QFile::remove(png);
    QFile::remove(pfm);
    QVERIFY(m_window->exportImage(png));
    QVERIFY(m_window->exportImage(pfm));
    QVERIFY(!QImage(png).isNull());
    std::string error;
    const auto linear = io::ImageFile::read(pfm.toStdString(), &error);
    QVERIFY2(linear, error.c_str());
    QCOMPARE(io::ImageMetrics::nonFiniteCount(*linear), std::size_t(0));
    QVERIFY(io::ImageMetrics::meanLuminance(*linear) > 0.0);

    // At a size of the user's choosing, typed as the dialog takes it.
    const std::optional<QSize> size = ui::ExportSize::parse(QStringLiteral("96 x 54"));
    QCOMPARE(size, std::optional<QSize>(QSize(96, 54)));
    QVERIFY(m_window->exportImage(pfm, *size));
    const auto sized = io::ImageFile::read(pfm.toStdString(), &error);
    QVERIFY2(sized, error.c_str());
    QCOMPARE(sized->width, 96);
    QCOMPARE(sized->height, 54);
    QCOMPARE(ui::ExportSize::parse(ui::ExportSize::presets(QSize(640, 480)).front()),
        std::optional<QSize>(QSize(640, 480)));
    QCOMPARE(ui::ExportSize::parse(QStringLiteral("1920×1080 (Full HD)")),
        std::optional<QSize>(QSize(1920, 1080)));
    QVERIFY(!ui::ExportSize::parse(QStringLiteral("0x100")));
    QVERIFY(!ui::ExportSize::parse(QStringLiteral("20000x100")));
    QVERIFY(!ui::ExportSize::parse(QStringLiteral("large")));
}

// Floating a panel or moving to another screen destroys the GL context: the viewport must rebuild.
void EditorTest::viewportSurvivesContextRecreation()
{
    ui::ViewportWidget viewport(m_window->document());
    QSignalSpy frames(&viewport, &ui::ViewportWidget::frameRendered);
    viewport.resize(160, 120);
    viewport.show();
    QVERIFY(QTest::qWaitForWindowExposed(&viewport));
    QVERIFY(frames.count() > 0 || frames.wait(20000));
    const int generation = viewport.contextGeneration();
    QDockWidget dock;
    dock.setWidget(&viewport); // a new top-level: new window, new context
    dock.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dock));
    frames.clear();
    viewport.update();
    QVERIFY(frames.wait(20000));
    QVERIFY(viewport.contextGeneration() > generation); // the old context went away and GL was rebuilt
    QVERIFY2(viewport.lastError().isEmpty(), qPrintable(viewport.lastError()));
    const QImage image = viewport.grabFramebuffer();
    QVERIFY(!image.isNull());
    int lit = 0;
    for (int y = 0; y < image.height(); y += 2)
        for (int x = 0; x < image.width(); x += 2)
            lit += qGray(image.pixel(x, y)) > 30 ? 1 : 0;
    QVERIFY(lit > 50);
    dock.setWidget(nullptr);
    viewport.setParent(nullptr);
}

void EditorTest::inspectorScreenshot()
{
    ui::VoxelInspectorDock* inspector = m_window->inspectorDock();
    inspector->enabledBox()->setChecked(true);
    inspector->channelBox()->setCurrentIndex(
        inspector->channelBox()->findData(int(render::VoxelChannel::Radiance)));
    inspector->levelSlider()->setValue(2);
    QVERIFY(waitForFrame());
    QVERIFY(m_window->viewport()->lastCubeCount() > 0);
    const QString screenshot = test::outputDir() + QStringLiteral("/editor-inspector.png");
    QVERIFY(m_window->grab().save(screenshot));
    qInfo("screenshot with the voxel inspector at level 2: %s", qPrintable(screenshot));
    inspector->enabledBox()->setChecked(false);
}

void EditorTest::saveCloseOpenGivesTheSameDocument()
{
    doc::Document* document = m_window->document();
    doc::NodeTransform moved = document->state().nodes[0].transform;
    moved.translation.x += 0.25f;
    document->setNodeTransform(0, moved);
    const QString path = test::outputDir() + QStringLiteral("/editor-roundtrip.vctproj");
    QFile::remove(path);
    QVERIFY(m_window->saveProjectAs(path));
    QVERIFY(!document->isModified());
    ui::MainWindow reopened;
    QVERIFY(reopened.openProject(path));
    QVERIFY(doc::sameDocument(reopened.document()->state(), document->state()));
}

void EditorTest::badFilesLeaveTheDocumentAlone()
{
    doc::Document* document = m_window->document();
    const doc::DocumentState before = document->state();
    const QString filePath = document->filePath();
    const QString corrupt = test::outputDir() + QStringLiteral("/corrupt.vctproj");
    QFile file(corrupt);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("{\"format\": \"vct-studio-project\", \"version\": 1, \"nodes\": [");
    file.close();
    QVERIFY(!m_window->openProject(corrupt));
    QVERIFY(doc::sameDocument(document->state(), before));
    QCOMPARE(document->filePath(), filePath);
    // A save that cannot happen (the parent "directory" is a file) fails and keeps the document as it was.
    QVERIFY(!m_window->saveProjectAs(corrupt + QStringLiteral("/inside.vctproj")));
    QCOMPARE(document->filePath(), filePath);
}

// A crash after an autosave, then recovery: the recovered document is untitled and modified (Save asks for a
// path, closing asks), the recovery file outlives a second crash, and only a save elsewhere retires it.
void EditorTest::recoveredWorkIsUntitledAndSurvivesUntilSaved()
{
    const QString recovery = ui::MainWindow::recoveryPath();
    QFile::remove(recovery);
    render::Material edited;
    {
        // The window goes away without closing, as it does when the process is killed: no closeEvent runs.
        auto crashing = std::make_unique<ui::MainWindow>();
        crashing->openInitial(QStringLiteral("builtin:cornell_point"));
        edited = crashing->document()->state().materials[0];
        edited.albedo = glm::vec3(0.1f, 0.7f, 0.2f);
        crashing->document()->setMaterial(0, edited);
        crashing->autosave();
        QVERIFY2(QFileInfo::exists(recovery), "autosave wrote no recovery file");
    }
    for (int crash = 0; crash < 2; ++crash) {
        ui::MainWindow recovered;
        QVERIFY(recovered.recoverAutosave());
        doc::Document* document = recovered.document();
        QVERIFY2(document->filePath().isEmpty(),
            qPrintable("recovered document is titled " + document->filePath()));
        QVERIFY2(document->isModified(), "a recovered document must count as unsaved");
        QVERIFY(recovered.isWindowModified());
        QVERIFY2(!recovered.windowTitle().contains(QStringLiteral("recovery")),
            qPrintable(recovered.windowTitle()));
        QCOMPARE(document->state().materials[0].albedo, edited.albedo);
        // Still there after recovering: a second crash before saving must not lose the work.
        QVERIFY2(
            QFileInfo::exists(recovery), "recovery removed the only copy of the work before it was saved");
    }
    const QString saved = test::outputDir() + QStringLiteral("/recovered.vctproj");
    QFile::remove(saved);
    {
        ui::MainWindow recovered;
        QVERIFY(recovered.recoverAutosave());
        QVERIFY(recovered.saveProjectAs(saved));
        QVERIFY(!recovered.document()->isModified());
        QCOMPARE(recovered.document()->filePath(), QFileInfo(saved).absoluteFilePath());
        QVERIFY2(!QFileInfo::exists(recovery), "the recovery file outlived the save that made it obsolete");
    }
    ui::MainWindow reopened;
    QVERIFY(reopened.openProject(saved));
    QCOMPARE(reopened.document()->state().materials[0].albedo, edited.albedo);
    QVERIFY(!reopened.document()->isModified());
}

QTEST_MAIN(EditorTest)
// View > Check for NaN/Inf runs the renderer's reduction after each frame and shows the result over the
// image; the default scene is finite, so the overlay must say so for every checked target.
void EditorTest::nonFiniteOverlayReportsEveryTarget()
{
    QAction* action = m_window->findChild<QAction*>(QStringLiteral("nonFiniteCheckAction"));
    QVERIFY(action);
    QVERIFY(action->isCheckable());
    const ui::NonFiniteOverlay* overlay = m_window->viewport()->nonFiniteOverlay();
    QVERIFY(!overlay->isVisible());
    action->setChecked(true);
    QVERIFY(m_window->viewport()->nonFiniteCheck());
    QVERIFY(waitForFrame());
    QTRY_VERIFY(overlay->isVisible());
    // Every 2D target plus at least one voxel level per volume.
    QVERIFY2(overlay->checkedResources() >= 5 + m_window->viewport()->voxelLevelCount(),
        qPrintable(overlay->text()));
    QCOMPARE(overlay->total(), std::uint64_t(0));
    QVERIFY2(overlay->text().contains(QStringLiteral("none in")), qPrintable(overlay->text()));
    action->setChecked(false);
    QVERIFY(!overlay->isVisible());
}

// Render > Reload shaders (F5) reads $VCT_SHADER_DIR: a shader that no longer compiles is named in the status
// bar and the view keeps drawing with its last good version; fixed, it reloads.
void EditorTest::f5ReloadsShadersAndSaysWhatFailed()
{
    QAction* action = m_window->findChild<QAction*>(QStringLiteral("reloadShadersAction"));
    QVERIFY(action);
    QCOMPARE(action->shortcut(), QKeySequence(Qt::Key_F5));
    QVERIFY(waitForFrame());
    const QString dir = test::outputDir() + QStringLiteral("/editor-shader-reload");
    QDir(dir).removeRecursively();
    test::writeFile(dir + QStringLiteral("/present/Present.frag"), "#error deliberately broken\n");
    qputenv("VCT_SHADER_DIR", dir.toUtf8());
    action->trigger();
    const QString failed = m_window->statusBar()->currentMessage();
    QVERIFY2(failed.contains(QStringLiteral("kept their last good version"))
            && failed.contains(QStringLiteral("Present.frag")),
        qPrintable(failed));
    QVERIFY(waitForFrame());
    QVERIFY(m_window->viewport()->lastError().isEmpty());

    qputenv("VCT_SHADER_DIR", (test::sourceDir() + QStringLiteral("/shaders")).toUtf8());
    action->trigger();
    qunsetenv("VCT_SHADER_DIR");
    const QString reloaded = m_window->statusBar()->currentMessage();
    QVERIFY2(reloaded.startsWith(QStringLiteral("Shaders reloaded")), qPrintable(reloaded));
    QVERIFY(waitForFrame());
}

// The view says what it shows: the selected node's box, an icon where each light is, the frame's figures.
void EditorTest::overlayShowsSelectionLightsAndFigures()
{
    m_window->document()->setSelectedNode(-1);
    QVERIFY(waitForFrame());
    const ui::ViewportOverlay* overlay = m_window->viewport()->overlay();
    QVERIFY(overlay && overlay->isVisible());
    QVERIFY(overlay->testAttribute(Qt::WA_TransparentForMouseEvents));
    const QString status = overlay->statusText();
    QVERIFY2(status.contains(QStringLiteral("ms GPU")) && status.contains(QStringLiteral("MiB"))
            && status.contains(
                QStringLiteral("voxels %1").arg(m_window->document()->state().settings.voxelResolution)
                + QStringLiteral("³")),
        qPrintable(status));
    QVERIFY(overlay->selectionEdges().isEmpty());

    // The point light of cornell_point hangs in the middle of the box, in view: its icon is on the image.
    const QList<QPointF> icons = overlay->lightIconPositions();
    QCOMPARE(icons.size(), qsizetype(1));
    QVERIFY(overlay->rect().contains(icons.front().toPoint()));
    const QImage drawn = m_window->viewport()->grab().toImage();
    const QColor atIcon = drawn.pixelColor(icons.front().toPoint());
    QVERIFY2(atIcon.red() > 200 && atIcon.green() > 200 && atIcon.blue() < 150, qPrintable(atIcon.name()));

    // A selected box is outlined by its twelve edges, all in front of the camera.
    m_window->document()->setSelectedNode(0);
    QCOMPARE(overlay->selectionEdges().size(), qsizetype(12));
    m_window->document()->setSelectedNode(-1);
    QVERIFY(overlay->selectionEdges().isEmpty());

    // A change that re-voxelizes says so until the frame after it.
    render::Material material = m_window->document()->state().materials.front();
    material.albedo *= 0.5f;
    m_window->document()->setMaterial(0, material);
    QVERIFY(waitForFrame());
    QVERIFY2(
        overlay->statusText().contains(QStringLiteral("re-voxelizing")), qPrintable(overlay->statusText()));
    m_window->document()->undoStack()->undo();
    QVERIFY(waitForFrame());

    // A rebuild says so before its first frame, and the message goes with that frame. The rebuild is split
    // over frames (issue 20: no frozen window): the first voxelizes and keeps the last complete image,
    // saying what comes next, and the viewport renders the rest by itself until the image is complete.
    render::RenderSettings settings = m_window->document()->state().settings;
    settings.voxelResolution = settings.voxelResolution == 32 ? 64 : 32;
    std::vector<render::FrameStats> frames;
    const QMetaObject::Connection counting = connect(m_window->viewport(), &ui::ViewportWidget::frameRendered,
        this, [&frames](const render::FrameStats& stats) { frames.push_back(stats); });
    m_window->document()->setSettings(settings);
    QCOMPARE(overlay->busyText(), QStringLiteral("Rebuilding the voxels…"));
    QTRY_VERIFY_WITH_TIMEOUT(!frames.empty(), 20000);
    QVERIFY(overlay->busyText().isEmpty());
    QVERIFY(frames.front().deferred);
    QCOMPARE(frames.front().voxelResolution, settings.voxelResolution);
    QVERIFY2(overlay->statusText().contains(QStringLiteral("rebuilding: inject light next")),
        qPrintable(overlay->statusText()));
    QTRY_VERIFY_WITH_TIMEOUT(!frames.back().deferred, 20000);
    disconnect(counting);
    QVERIFY(!overlay->statusText().contains(QStringLiteral("rebuilding:")));
    m_window->document()->undoStack()->undo();
    QVERIFY(waitForFrame());
}

#include "tst_Editor.moc"
