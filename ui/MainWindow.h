#pragma once

#include "document/SceneLoader.h"

#include <QMainWindow>
#include <QTimer>

class QMenu;

namespace vct::doc {
class Document;
}

namespace vct::ui {

class AccuracyChartDock;
class LightDock;
class MaterialDock;
class ReferenceCompareDock;
class RenderSettingsDock;
class SceneGraphDock;
class StatsDock;
class TransformDock;
class ViewportWidget;
class VoxelInspectorDock;

/**
 * The editor's main window: the viewport in the centre, one dock per panel (listed in the View menu, layout
 * restored on the next start), File and Edit menus with undo/redo, recent files, autosave to a recovery file
 * and drag-and-drop import. The composition root wires the panels to the one Document.
 */
class MainWindow : public QMainWindow {
    Q_OBJECT

public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    /**
     * Opens a project (.vctproj) or starts from a scene spec; offers recovery after a crash first.
     * `unitScale` is metres per unit of a model file.
     */
    void openInitial(const QString& specOrProject, float unitScale = 1.0f,
        doc::SceneLoader::UpAxis up = doc::SceneLoader::UpAxis::Y);
    doc::Document* document() const { return m_document; }
    ViewportWidget* viewport() const { return m_viewport; }
    MaterialDock* materialDock() const { return m_materialDock; }
    TransformDock* transformDock() const { return m_transformDock; }
    RenderSettingsDock* renderSettingsDock() const { return m_settingsDock; }
    VoxelInspectorDock* inspectorDock() const { return m_inspectorDock; }
    SceneGraphDock* sceneGraphDock() const { return m_sceneDock; }
    LightDock* lightDock() const { return m_lightDock; }
    StatsDock* statsDock() const { return m_statsDock; }
    ReferenceCompareDock* referenceCompareDock() const { return m_compareDock; }
    AccuracyChartDock* accuracyChartDock() const { return m_accuracyDock; }
    /** Where autosave writes (beside the settings, per user). */
    static QString recoveryPath();

    /**
     * Opens the autosaved document as recovered work (untitled, modified). The recovery file stays until the
     * work is saved elsewhere or the user discards it on closing, so a second crash loses nothing either.
     */
    bool recoverAutosave();
    /** Writes the recovery copy now if the document has unsaved changes (the timer calls this every minute).
     */
    void autosave();

    bool openProject(const QString& path);
    bool saveProjectAs(const QString& path);
    /** Imports on a worker thread behind a progress dialog; `unitScale` is metres per model unit. */
    bool importModel(const QString& path, float unitScale = 1.0f,
        doc::SceneLoader::UpAxis up = doc::SceneLoader::UpAxis::Y);
    /** Renders at `size` pixels (empty: the view's own) with converged light and writes `path`. */
    bool exportImage(const QString& path, QSize size = {});
    /**
     * Render > Reload shaders (F5): rebuilds every shader from ShaderFolder::forReload() and says in the
     * status bar what came of it; the failures (each program keeps its last good build) also go to the log.
     * False when there is no folder or a program failed.
     */
    bool reloadShaders();

protected:
    void closeEvent(QCloseEvent* event) override;
    void showEvent(QShowEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private:
    void buildMenus();
    void buildDocks();
    bool maybeSave();
    /** Asks the metres in one unit of the model at `path` (1 without dialogs); false if cancelled. */
    bool askUnitScale(const QString& path, float* unitScale);
    /** Asks which axis of the model at `path` points up (Y without dialogs); false if cancelled. */
    bool askUpAxis(const QString& path, doc::SceneLoader::UpAxis* up);
    /** File > Import model and a dropped model: asks the unit, then imports. */
    void importModelAskingUnit(const QString& path);
    bool save();
    bool saveAs();
    void showError(const QString& title, const QString& message);
    void addRecentFile(const QString& path);
    void rebuildRecentMenu();
    void updateTitle();
    /** View > Bookmarks: one entry per bookmark (Ctrl+1 to Ctrl+9 for the first nine), and Remove. */
    void rebuildBookmarksMenu();

    doc::Document* m_document;
    ViewportWidget* m_viewport;
    SceneGraphDock* m_sceneDock = nullptr;
    MaterialDock* m_materialDock = nullptr;
    TransformDock* m_transformDock = nullptr;
    LightDock* m_lightDock = nullptr;
    RenderSettingsDock* m_settingsDock = nullptr;
    VoxelInspectorDock* m_inspectorDock = nullptr;
    StatsDock* m_statsDock = nullptr;
    ReferenceCompareDock* m_compareDock = nullptr;
    AccuracyChartDock* m_accuracyDock = nullptr;
    QMenu* m_viewMenu = nullptr;
    QMenu* m_bookmarksMenu = nullptr;
    bool m_dockWidthsFixed = false;
    QMenu* m_recentMenu = nullptr;
    QTimer m_autosaveTimer;
};

} // namespace vct::ui
