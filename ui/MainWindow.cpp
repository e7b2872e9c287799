#include "MainWindow.h"

#include "AboutDialog.h"
#include "AccuracyChartDock.h"
#include "ExportSize.h"
#include "LightDock.h"
#include "MaterialDock.h"
#include "RenderSettingsDock.h"
#include "SceneGraphDock.h"
#include "ShaderFolder.h"
#include "ShortcutsDialog.h"
#include "StatsDock.h"
#include "TransformDock.h"
#include "UndoShortcutFilter.h"
#include "ViewportWidget.h"
#include "VoxelInspectorDock.h"
#include "reference/ReferenceCompareDock.h"

#include "document/BuiltinScenes.h"
#include "document/Document.h"
#include "document/ProjectFile.h"
#include "document/SceneLoader.h"
#include "imageio/ImageFile.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDateTime>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFutureWatcher>
#include <QGuiApplication>
#include <QInputDialog>
#include <QLineEdit>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QProgressDialog>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTimer>
#include <QUndoStack>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>

namespace vct::ui {

namespace {

constexpr int kMaxRecentFiles = 8;
const QString kProjectFilter = QStringLiteral("VCT Studio projects (*.vctproj)");
const QString kModelFilter
    = QStringLiteral("Models (*.obj *.gltf *.glb *.ply *.fbx *.dae *.3ds *.stl);;All files (*)");

bool isModelFile(const QString& path)
{
    static const QStringList extensions
        = { "obj", "gltf", "glb", "ply", "fbx", "dae", "3ds", "stl", "blend", "x3d" };
    return extensions.contains(QFileInfo(path).suffix().toLower());
}

// Tests and CI have nobody to answer a dialog.
bool dialogsAllowed()
{
    return !qEnvironmentVariableIsSet("VCT_NO_DIALOGS");
}

} // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent)
    , m_document(new doc::Document(this))
    , m_viewport(new ViewportWidget(m_document, this))
{
    setCentralWidget(m_viewport);
    // The view's keys (W/A/S/D, F, Home) work from the start, without a click into it first.
    m_viewport->setFocus(Qt::OtherFocusReason);
    setAcceptDrops(true);
    setDockNestingEnabled(true);
    buildDocks();
    buildMenus();
    resize(1280, 800);
    const QSettings settings;
    // The client area is saved and restored as it is. restoreGeometry() guesses the frame of a window not
    // shown yet, and where no window manager reports one it put the window a title bar (20 px) lower on
    // every start (tst_Layout::restoredSessionKeepsTheViewInPlace).
    const QRect saved = settings.value(QStringLiteral("window/rect")).toRect();
    if (saved.isValid() && QGuiApplication::screenAt(saved.center()))
        setGeometry(saved);
    if (settings.value(QStringLiteral("window/maximized")).toBool())
        setWindowState(windowState() | Qt::WindowMaximized);
    restoreState(settings.value(QStringLiteral("window/state")).toByteArray());

    connect(m_document->undoStack(), &QUndoStack::cleanChanged, this, &MainWindow::updateTitle);
    connect(m_document, &doc::Document::filePathChanged, this, &MainWindow::updateTitle);
    connect(m_viewport, &ViewportWidget::rendererFailed, this,
        [this](const QString& message) { statusBar()->showMessage(tr("Renderer error: %1").arg(message)); });
    m_autosaveTimer.setInterval(60 * 1000);
    connect(&m_autosaveTimer, &QTimer::timeout, this, &MainWindow::autosave);
    m_autosaveTimer.start();
    updateTitle();
}

MainWindow::~MainWindow() = default;

QString MainWindow::recoveryPath()
{
    const QString dir = QStandardPaths::writableLocation(QStandardPaths::AppDataLocation);
    QDir().mkpath(dir);
    return dir + QStringLiteral("/recovery.vctproj");
}

void MainWindow::buildDocks()
{
    m_sceneDock = new SceneGraphDock(this);
    m_materialDock = new MaterialDock(this);
    m_transformDock = new TransformDock(this);
    m_lightDock = new LightDock(this);
    m_settingsDock = new RenderSettingsDock(this);
    m_inspectorDock = new VoxelInspectorDock(this);
    m_statsDock = new StatsDock(this);
    m_compareDock = new ReferenceCompareDock(this);
    m_accuracyDock = new AccuracyChartDock(this);
    m_sceneDock->setDocument(m_document);
    m_compareDock->setDocument(m_document);
    // Every comparison made here is a point on the accuracy chart, beside the last sweep's.
    connect(m_compareDock, &ReferenceCompareDock::comparisonFinished, this, [this] {
        const ReferenceUpdate& last = m_compareDock->lastUpdate();
        // Stale: the settings changed since it started, and the point could not say which it measured.
        if (last.samplesPerPixel <= 0 || m_compareDock->isStale())
            return;
        const render::RenderSettings& s = m_document->state().settings;
        m_accuracyDock->addComparison(tr("in the editor: %1 voxels a side, %2 cones of %3°; reference %4 spp")
                                          .arg(s.voxelResolution)
                                          .arg(s.diffuseConeCount)
                                          .arg(double(s.diffuseApertureDeg))
                                          .arg(last.samplesPerPixel),
            m_compareDock->vctGpuMs(), last.relativeMse);
    });
    m_materialDock->setDocument(m_document);
    m_transformDock->setDocument(m_document);
    m_lightDock->setDocument(m_document);
    m_settingsDock->setDocument(m_document);
    addDockWidget(Qt::LeftDockWidgetArea, m_sceneDock);
    addDockWidget(Qt::LeftDockWidgetArea, m_lightDock);
    addDockWidget(Qt::RightDockWidgetArea, m_materialDock);
    addDockWidget(Qt::RightDockWidgetArea, m_transformDock);
    addDockWidget(Qt::RightDockWidgetArea, m_settingsDock);
    addDockWidget(Qt::RightDockWidgetArea, m_inspectorDock);
    addDockWidget(Qt::RightDockWidgetArea, m_statsDock);
    // A tab beside the material, not a row below it: the right column keeps its width and the docks under it
    // their height.
    tabifyDockWidget(m_materialDock, m_transformDock);
    tabifyDockWidget(m_materialDock, m_settingsDock);
    tabifyDockWidget(m_inspectorDock, m_statsDock);
    m_materialDock->raise();
    m_inspectorDock->raise();
    // The comparison wants width for three images side by side; both start hidden so the default layout stays
    // uncluttered (the View menu or Ctrl+R shows them).
    addDockWidget(Qt::BottomDockWidgetArea, m_compareDock);
    addDockWidget(Qt::BottomDockWidgetArea, m_accuracyDock);
    tabifyDockWidget(m_compareDock, m_accuracyDock);
    m_compareDock->hide();
    m_accuracyDock->hide();
    m_compareDock->setFrameSource(
        [this] {
            return double(std::max(1, m_viewport->width())) / double(std::max(1, m_viewport->height()));
        },
        [this](int width, int height, double& gpuMs) {
            render::FrameStats stats;
            render::RadianceImage image = m_viewport->renderFullFrame(width, height, &stats);
            gpuMs = image.isEmpty() ? -1.0 : stats.totalGpuMs;
            return image;
        });

    connect(m_sceneDock, &SceneGraphDock::lightSelected, m_lightDock, &LightDock::setCurrentLight);
    connect(m_sceneDock, &SceneGraphDock::lightSelected, m_viewport, &ViewportWidget::setSelectedLight);
    connect(m_viewport, &ViewportWidget::lightClicked, m_sceneDock, &SceneGraphDock::selectLight);
    connect(m_inspectorDock, &VoxelInspectorDock::settingsChanged, m_viewport, &ViewportWidget::setInspector);
    connect(m_viewport, &ViewportWidget::cubesDrawn, m_inspectorDock, &VoxelInspectorDock::setCubeCount);
    connect(m_viewport, &ViewportWidget::voxelHovered, m_inspectorDock, &VoxelInspectorDock::setHoverText);
    connect(m_viewport, &ViewportWidget::frameRendered, m_statsDock, &StatsDock::showStats);
    // Where the eye is: a refusal shown only inside the dock can sit below its fold.
    connect(m_settingsDock, &RenderSettingsDock::settingRefused, this,
        [this](const QString& reason) { statusBar()->showMessage(reason, 10000); });
}

void MainWindow::buildMenus()
{
    QMenu* file = menuBar()->addMenu(tr("&File"));
    QMenu* fromScene = file->addMenu(tr("&New from built-in scene"));
    for (const QString& name : doc::BuiltinScenes::names())
        fromScene->addAction(name, this, [this, name] {
            if (!maybeSave())
                return;
            QString error;
            if (!m_document->newFromScene(QStringLiteral("builtin:") + name, &error))
                showError(tr("New scene"), error);
        });
    file->addAction(tr("&Open project..."), QKeySequence::Open, this, [this] {
        if (!maybeSave())
            return;
        const QString path
            = QFileDialog::getOpenFileName(this, tr("Open project"), QString(), kProjectFilter);
        if (!path.isEmpty())
            openProject(path);
    });
    m_recentMenu = file->addMenu(tr("Open &recent"));
    rebuildRecentMenu();
    file->addAction(tr("&Save"), QKeySequence::Save, this, [this] { save(); });
    file->addAction(tr("Save &as..."), QKeySequence::SaveAs, this, [this] { saveAs(); });
    file->addSeparator();
    file->addAction(tr("&Import model..."), QKeySequence(tr("Ctrl+I")), this, [this] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Import model"), QString(), kModelFilter);
        if (!path.isEmpty())
            importModelAskingUnit(path);
    });
    file->addAction(tr("&Export image..."), QKeySequence(tr("Ctrl+E")), this, [this] {
        const QString path = QFileDialog::getSaveFileName(this, tr("Export image"),
            QStringLiteral("render.png"),
            tr("PNG, tone-mapped (*.png);;PFM, linear radiance (*.pfm);;OpenEXR, linear radiance (*.exr)"));
        if (path.isEmpty())
            return;
        const qreal dpr = m_viewport->devicePixelRatioF();
        const QSize view(int(m_viewport->width() * dpr), int(m_viewport->height() * dpr));
        bool ok = true;
        const QString choice = QInputDialog::getItem(this, tr("Export image"),
            tr("Size in pixels (width×height; type another if you like):"), ExportSize::presets(view), 0,
            true, &ok);
        if (!ok)
            return;
        const std::optional<QSize> size = ExportSize::parse(choice);
        if (!size) {
            showError(tr("Export image"),
                tr("'%1' is not a size: expected width×height, each 1 to %2 pixels")
                    .arg(choice)
                    .arg(ExportSize::kMaxSide));
            return;
        }
        exportImage(path, *size);
    });
    file->addSeparator();
    file->addAction(tr("&Quit"), QKeySequence::Quit, this, &QWidget::close);

    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    QAction* undo = m_document->undoStack()->createUndoAction(this, tr("&Undo"));
    undo->setShortcut(QKeySequence::Undo);
    QAction* redo = m_document->undoStack()->createRedoAction(this, tr("&Redo"));
    // Ctrl+Shift+Z and Ctrl+Y redo on every platform, whichever of them its convention lists.
    QList<QKeySequence> redoKeys = QKeySequence::keyBindings(QKeySequence::Redo);
    for (const QKeySequence& key :
        { QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z), QKeySequence(Qt::CTRL | Qt::Key_Y) })
        if (!redoKeys.contains(key))
            redoKeys.append(key);
    redo->setShortcuts(redoKeys);
    undo->setObjectName(QStringLiteral("undoAction"));
    redo->setObjectName(QStringLiteral("redoAction"));
    edit->addAction(undo);
    edit->addAction(redo);
    qApp->installEventFilter(new UndoShortcutFilter(this, undo, redo));

    m_viewMenu = menuBar()->addMenu(tr("&View"));
    for (QDockWidget* dock : { static_cast<QDockWidget*>(m_sceneDock),
             static_cast<QDockWidget*>(m_materialDock), static_cast<QDockWidget*>(m_transformDock),
             static_cast<QDockWidget*>(m_lightDock), static_cast<QDockWidget*>(m_settingsDock),
             static_cast<QDockWidget*>(m_inspectorDock), static_cast<QDockWidget*>(m_statsDock),
             static_cast<QDockWidget*>(m_compareDock), static_cast<QDockWidget*>(m_accuracyDock) })
        m_viewMenu->addAction(dock->toggleViewAction());
    m_viewMenu->addSeparator();
    m_viewMenu->addAction(
        tr("&Frame selection"), QKeySequence(tr("F")), m_viewport, &ViewportWidget::frameSelected);
    m_viewMenu
        ->addAction(tr("Frame &all"), QKeySequence(tr("Shift+F")), m_viewport, &ViewportWidget::frameAll)
        ->setObjectName(QStringLiteral("frameAllAction"));
    m_viewMenu
        ->addAction(tr("&Reset camera"), QKeySequence(Qt::Key_Home), m_viewport, &ViewportWidget::resetCamera)
        ->setObjectName(QStringLiteral("resetCameraAction"));
    // Alt+Z, not Ctrl+Shift+Z: that is redo on Linux and macOS.
    QAction* undoView = m_viewMenu->addAction(
        tr("&Undo view"), QKeySequence(tr("Alt+Z")), m_viewport, &ViewportWidget::undoView);
    undoView->setObjectName(QStringLiteral("undoViewAction"));
    undoView->setEnabled(false);
    connect(m_viewport, &ViewportWidget::viewHistoryChanged, undoView, &QAction::setEnabled);
    QAction* bookmark
        = m_viewMenu->addAction(tr("&Bookmark view..."), QKeySequence(tr("Ctrl+B")), this, [this] {
              QString name;
              if (dialogsAllowed()) {
                  bool ok = false;
                  name = QInputDialog::getText(this, tr("Bookmark view"), tr("Name:"), QLineEdit::Normal,
                      tr("View %1").arg(m_document->state().bookmarks.size() + 1), &ok);
                  if (!ok)
                      return;
              }
              m_document->addBookmark(name);
          });
    bookmark->setObjectName(QStringLiteral("bookmarkViewAction"));
    bookmark->setToolTip(tr("Keep the current view in the project, to come back to from View > Bookmarks"));
    m_bookmarksMenu = m_viewMenu->addMenu(tr("Boo&kmarks"));
    m_bookmarksMenu->setObjectName(QStringLiteral("bookmarksMenu"));
    rebuildBookmarksMenu();
    connect(m_document, &doc::Document::changed, this, [this](const doc::ChangeEvent& event) {
        if (event.kind == doc::ChangeEvent::Kind::Bookmarks || event.kind == doc::ChangeEvent::Kind::Reset)
            rebuildBookmarksMenu();
    });
    QAction* nonFinite = m_viewMenu->addAction(tr("Check for &NaN/Inf"));
    nonFinite->setObjectName(QStringLiteral("nonFiniteCheckAction"));
    nonFinite->setCheckable(true);
    nonFinite->setToolTip(
        tr("Counts non-finite texels in every render target and voxel level after each frame"));
    connect(nonFinite, &QAction::toggled, m_viewport, &ViewportWidget::setNonFiniteCheck);

    QMenu* renderMenu = menuBar()->addMenu(tr("&Render"));
    QAction* compare = renderMenu->addAction(tr("&Compare with reference"));
    compare->setObjectName(QStringLiteral("compareReferenceAction"));
    compare->setShortcut(QKeySequence(tr("Ctrl+R")));
    compare->setToolTip(
        tr("Path-trace the current view in the background and compare the cone-traced image with it"));
    connect(compare, &QAction::triggered, this, [this] {
        m_compareDock->show();
        m_compareDock->raise();
        m_compareDock->startComparison();
    });
    QAction* reload = renderMenu->addAction(tr("Re&load shaders"));
    reload->setObjectName(QStringLiteral("reloadShadersAction"));
    reload->setShortcut(QKeySequence(Qt::Key_F5));
    reload->setToolTip(tr("Rebuild every shader from the shaders/ folder ($VCT_SHADER_DIR, else the source "
                          "tree); a shader that fails to compile keeps its last good version"));
    connect(reload, &QAction::triggered, this, &MainWindow::reloadShaders);
    QAction* chart = renderMenu->addAction(tr("&Accuracy chart"));
    chart->setObjectName(QStringLiteral("accuracyChartAction"));
    connect(chart, &QAction::triggered, this, [this] {
        m_accuracyDock->show();
        m_accuracyDock->raise();
    });

    QMenu* help = menuBar()->addMenu(tr("&Help"));
    help->addAction(tr("&Keyboard shortcuts"), QKeySequence::HelpContents, this,
            [this] { ShortcutsDialog::showFor(this); })
        ->setObjectName(QStringLiteral("shortcutsAction"));
    QAction* about = help->addAction(tr("&About VCT Studio"), this, [this] { AboutDialog::showFor(this); });
    about->setObjectName(QStringLiteral("aboutAction"));
    about->setMenuRole(QAction::AboutRole);
}

void MainWindow::openInitial(const QString& specOrProject, float unitScale, doc::SceneLoader::UpAxis up)
{
    const QString recovery = recoveryPath();
    if (QFileInfo::exists(recovery) && dialogsAllowed()) {
        const auto answer = QMessageBox::question(this, tr("Recover unsaved work?"),
            tr("VCT Studio did not close normally last time. Recover the autosaved document?"));
        if (answer == QMessageBox::Yes && recoverAutosave())
            return;
        if (answer != QMessageBox::Yes)
            QFile::remove(recovery);
    }
    QString error;
    const bool ok = specOrProject.endsWith(QStringLiteral(".vctproj"), Qt::CaseInsensitive)
        ? m_document->openProject(specOrProject, &error)
        : m_document->newFromScene(specOrProject, &error, unitScale, up);
    if (!ok) {
        showError(tr("Open"), error);
        m_document->newFromScene(QStringLiteral("builtin:default"), &error);
    } else if (!m_document->openNote().isEmpty()) {
        statusBar()->showMessage(m_document->openNote(), 15000);
    }
}

bool MainWindow::recoverAutosave()
{
    QString error;
    if (!m_document->recoverProject(recoveryPath(), &error)) {
        // Kept aside, not deleted: what it holds may still be read by hand; the next start does not offer it
        // again.
        const QString kept = recoveryPath() + QStringLiteral(".failed-")
            + QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-hhmmss"));
        QFile::remove(kept);
        const bool moved = QFile::rename(recoveryPath(), kept);
        showError(tr("Recovery failed"),
            moved ? tr("%1 (the autosaved copy is kept as %2)").arg(error, QDir::toNativeSeparators(kept))
                  : error);
        return false;
    }
    statusBar()->showMessage(
        tr("Recovered the autosaved document: it is untitled until you save it (Ctrl+S)."));
    return true;
}

bool MainWindow::openProject(const QString& path)
{
    QString error;
    if (!m_document->openProject(path, &error)) {
        showError(tr("Open project"), error);
        return false;
    }
    addRecentFile(path);
    return true;
}

bool MainWindow::saveProjectAs(const QString& path)
{
    QString error;
    if (!m_document->saveProject(path, &error)) {
        showError(tr("Save project"), error);
        return false;
    }
    addRecentFile(path);
    QFile::remove(recoveryPath());
    return true;
}

bool MainWindow::save()
{
    return m_document->filePath().isEmpty() ? saveAs() : saveProjectAs(m_document->filePath());
}

bool MainWindow::saveAs()
{
    QString path
        = QFileDialog::getSaveFileName(this, tr("Save project"), m_document->filePath(), kProjectFilter);
    if (path.isEmpty())
        return false;
    if (!path.endsWith(QStringLiteral(".vctproj"), Qt::CaseInsensitive))
        path += QStringLiteral(".vctproj");
    return saveProjectAs(path);
}

bool MainWindow::askUnitScale(const QString& path, float* unitScale)
{
    *unitScale = 1.0f;
    if (!dialogsAllowed())
        return true;
    // Models carry no unit (OBJ has none; glTF is in metres but many exports ignore it), so the user says.
    const std::vector<std::pair<QString, float>> units
        = { { tr("Metres"), 1.0f }, { tr("Centimetres (0.01 m)"), 0.01f },
              { tr("Millimetres (0.001 m)"), 0.001f }, { tr("Inches (0.0254 m)"), 0.0254f } };
    QStringList items;
    for (const auto& unit : units)
        items << unit.first;
    items << tr("Custom factor...");
    bool ok = false;
    const QString item = QInputDialog::getItem(this, tr("Import model"),
        tr("One unit of %1 is:").arg(QFileInfo(path).fileName()), items, 0, false, &ok);
    if (!ok)
        return false;
    const qsizetype index = items.indexOf(item);
    if (index >= 0 && std::size_t(index) < units.size()) {
        *unitScale = units[std::size_t(index)].second;
        return true;
    }
    // Text rather than a spin box: factors such as 1e-6 need more decimals than a spin box shows.
    const QString text = QInputDialog::getText(
        this, tr("Import model"), tr("Metres per model unit:"), QLineEdit::Normal, QStringLiteral("1"), &ok);
    if (!ok)
        return false;
    if (const QString problem = doc::SceneLoader::parseUnitScale(text, unitScale); !problem.isEmpty()) {
        showError(tr("Import model"), tr("Unit scale: %1").arg(problem));
        return false;
    }
    return true;
}

void MainWindow::importModelAskingUnit(const QString& path)
{
    float unitScale = 1.0f;
    doc::SceneLoader::UpAxis up = doc::SceneLoader::UpAxis::Y;
    if (askUnitScale(path, &unitScale) && askUpAxis(path, &up))
        importModel(path, unitScale, up);
}

bool MainWindow::askUpAxis(const QString& path, doc::SceneLoader::UpAxis* up)
{
    *up = doc::SceneLoader::UpAxis::Y;
    if (!dialogsAllowed())
        return true;
    const QStringList items { tr("Y (glTF, FBX, most OBJ)"), tr("Z (CAD tools, 3ds Max, some exports)") };
    bool ok = false;
    const QString item = QInputDialog::getItem(this, tr("Import model"),
        tr("The axis that points up in %1:").arg(QFileInfo(path).fileName()), items, 0, false, &ok);
    if (!ok)
        return false;
    *up = items.indexOf(item) == 1 ? doc::SceneLoader::UpAxis::Z : doc::SceneLoader::UpAxis::Y;
    return true;
}

bool MainWindow::importModel(const QString& path, float unitScale, doc::SceneLoader::UpAxis up)
{
    // Assimp may take seconds on a big model: it runs on a worker thread while a dialog shows progress.
    // Cancel closes the dialog at once and throws the result away when the worker finishes (Assimp has no
    // way to stop half-way).
    struct Loaded {
        render::Scene scene;
        QString error;
        bool ok = false;
    };
    QFutureWatcher<Loaded> watcher;
    QProgressDialog progress(tr("Importing %1...").arg(QFileInfo(path).fileName()), tr("Cancel"), 0, 0, this);
    progress.setWindowModality(Qt::WindowModal);
    progress.setMinimumDuration(300);
    QEventLoop loop;
    connect(&watcher, &QFutureWatcher<Loaded>::finished, &loop, &QEventLoop::quit);
    connect(&progress, &QProgressDialog::canceled, &loop, &QEventLoop::quit);
    watcher.setFuture(QtConcurrent::run([path, unitScale] {
        Loaded loaded;
        loaded.ok = doc::SceneLoader::load(path, loaded.scene, &loaded.error, nullptr, unitScale);
        return loaded;
    }));
    loop.exec();
    progress.close();
    if (!watcher.isFinished()) {
        statusBar()->showMessage(tr("Import of %1 cancelled").arg(QFileInfo(path).fileName()), 5000);
        // The worker keeps running detached from this function: let it finish and free its result.
        auto* orphan = new QFutureWatcher<Loaded>(this);
        connect(orphan, &QFutureWatcher<Loaded>::finished, orphan, &QObject::deleteLater);
        orphan->setFuture(watcher.future());
        return false;
    }
    Loaded loaded = watcher.result();
    if (!loaded.ok) {
        showError(tr("Import model"), loaded.error);
        return false;
    }
    m_document->addImportedModel(path, std::move(loaded.scene), unitScale, up);
    statusBar()->showMessage(tr("Imported %1").arg(QFileInfo(path).fileName()), 5000);
    return true;
}

void MainWindow::rebuildBookmarksMenu()
{
    m_bookmarksMenu->clear();
    const std::vector<doc::CameraBookmark>& bookmarks = m_document->state().bookmarks;
    m_bookmarksMenu->setEnabled(!bookmarks.empty());
    if (bookmarks.empty())
        return;
    for (std::size_t i = 0; i < bookmarks.size(); ++i) {
        QAction* go = m_bookmarksMenu->addAction(bookmarks[i].name);
        go->setObjectName(QStringLiteral("bookmark%1Action").arg(i));
        if (i < 9)
            go->setShortcut(QKeySequence(Qt::CTRL | Qt::Key(Qt::Key_1 + int(i))));
        connect(go, &QAction::triggered, m_viewport, [this, i] { m_viewport->goToBookmark(int(i)); });
    }
    m_bookmarksMenu->addSeparator();
    QMenu* remove = m_bookmarksMenu->addMenu(tr("&Remove"));
    for (std::size_t i = 0; i < bookmarks.size(); ++i)
        remove->addAction(bookmarks[i].name, this, [this, i] { m_document->removeBookmark(int(i)); });
}

bool MainWindow::reloadShaders()
{
    const QString folder = ShaderFolder::forReload();
    if (folder.isEmpty()) {
        statusBar()->showMessage(tr("No shaders to reload: set VCT_SHADER_DIR to a shaders/ folder (this "
                                    "editor's source tree is gone)"),
            10000);
        return false;
    }
    const QStringList failures = m_viewport->reloadShaders(folder);
    if (failures.isEmpty()) {
        statusBar()->showMessage(tr("Shaders reloaded from %1").arg(QDir::toNativeSeparators(folder)), 5000);
        return true;
    }
    for (const QString& failure : failures)
        qWarning("shader reload: %s", qPrintable(failure));
    // The first line of the driver's log names the file and line; the rest goes to the log.
    statusBar()->showMessage(
        tr("Shader reload: %n program(s) kept their last good version: %1", nullptr, int(failures.size()))
            .arg(failures.first().section(QLatin1Char('\n'), 0, 1).simplified()));
    return false;
}

bool MainWindow::exportImage(const QString& path, QSize size)
{
    const qreal dpr = m_viewport->devicePixelRatioF();
    if (size.isEmpty())
        size = QSize(int(m_viewport->width() * dpr), int(m_viewport->height() * dpr));
    const render::RadianceImage image = m_viewport->renderFullFrame(size.width(), size.height());
    std::string error;
    if (image.isEmpty()
        || !io::ImageFile::write(path.toStdString(), image, m_document->state().settings.exposure, &error)) {
        showError(tr("Export image"),
            image.isEmpty() ? tr("nothing has been rendered yet") : QString::fromStdString(error));
        return false;
    }
    statusBar()->showMessage(tr("Exported %1").arg(QDir::toNativeSeparators(path)), 5000);
    return true;
}

bool MainWindow::maybeSave()
{
    if (!m_document->isModified() || !dialogsAllowed())
        return true;
    const auto answer = QMessageBox::warning(this, tr("Unsaved changes"),
        tr("The document has unsaved changes. Save them?"),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
    if (answer == QMessageBox::Save)
        return save();
    return answer == QMessageBox::Discard;
}

void MainWindow::showEvent(QShowEvent* event)
{
    QMainWindow::showEvent(event);
    if (m_dockWidthsFixed)
        return;
    m_dockWidthsFixed = true;
    // Dock areas otherwise follow their panels' size hints, so a panel whose rows change (a light of another
    // type, a longer name in the scene tree) moved the view. Widths set once here are the user's to change.
    QTimer::singleShot(0, this, [this] {
        resizeDocks({ m_sceneDock, m_materialDock }, { m_sceneDock->width(), m_materialDock->width() },
            Qt::Horizontal);
    });
}

void MainWindow::closeEvent(QCloseEvent* event)
{
    if (!maybeSave()) {
        event->ignore();
        return;
    }
    QSettings settings;
    settings.setValue(QStringLiteral("window/rect"), normalGeometry());
    settings.setValue(QStringLiteral("window/maximized"), isMaximized());
    settings.setValue(QStringLiteral("window/state"), saveState());
    // A normal close leaves no recovery file, so the next start offers none.
    QFile::remove(recoveryPath());
    event->accept();
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event)
{
    for (const QUrl& url : event->mimeData()->urls())
        if (url.isLocalFile()
            && (isModelFile(url.toLocalFile()) || url.toLocalFile().endsWith(QStringLiteral(".vctproj")))) {
            event->acceptProposedAction();
            return;
        }
}

void MainWindow::dropEvent(QDropEvent* event)
{
    for (const QUrl& url : event->mimeData()->urls()) {
        const QString path = url.toLocalFile();
        if (path.endsWith(QStringLiteral(".vctproj"), Qt::CaseInsensitive)) {
            if (maybeSave())
                openProject(path);
        } else if (isModelFile(path)) {
            importModelAskingUnit(path);
        }
    }
}

void MainWindow::showError(const QString& title, const QString& message)
{
    statusBar()->showMessage(message);
    if (dialogsAllowed())
        QMessageBox::warning(this, title, message);
    else
        qWarning("%s: %s", qPrintable(title), qPrintable(message));
}

void MainWindow::addRecentFile(const QString& path)
{
    QSettings settings;
    QStringList files = settings.value(QStringLiteral("recentFiles")).toStringList();
    const QString absolute = QFileInfo(path).absoluteFilePath();
    files.removeAll(absolute);
    files.prepend(absolute);
    while (files.size() > kMaxRecentFiles)
        files.removeLast();
    settings.setValue(QStringLiteral("recentFiles"), files);
    rebuildRecentMenu();
}

void MainWindow::rebuildRecentMenu()
{
    m_recentMenu->clear();
    QStringList files = QSettings().value(QStringLiteral("recentFiles")).toStringList();
    // A file deleted or moved since is no way back to the work: leave it out rather than fail on a click.
    files.erase(std::remove_if(
                    files.begin(), files.end(), [](const QString& path) { return !QFileInfo::exists(path); }),
        files.end());
    for (const QString& path : files)
        m_recentMenu
            ->addAction(QFileInfo(path).fileName(), this,
                [this, path] {
                    if (maybeSave())
                        openProject(path);
                })
            ->setToolTip(path);
    m_recentMenu->setEnabled(!files.isEmpty());
}

void MainWindow::updateTitle()
{
    const QString name
        = m_document->filePath().isEmpty() ? tr("Untitled") : QFileInfo(m_document->filePath()).fileName();
    setWindowTitle(tr("%1[*] - VCT Studio").arg(name));
    setWindowModified(m_document->isModified());
}

void MainWindow::autosave()
{
    if (!m_document->isModified())
        return;
    QString error;
    // The recovery copy is written beside the settings, never over the user's file.
    // With the document's model root, as recoverProject() reads it back through openProject().
    if (!doc::ProjectFile::save(recoveryPath(), m_document->state(), &error, m_document->modelRoot()))
        statusBar()->showMessage(tr("Autosave failed: %1").arg(error), 5000);
}

} // namespace vct::ui
