#pragma once

#include "CameraHistory.h"
#include "GizmoController.h"
#include "InspectorSettings.h"

#include "core/FrameStats.h"
#include "image/RadianceImage.h"
#include "scene/Aabb.h"
#include "scene/Camera.h"

#include <QElapsedTimer>
#include <QOpenGLWidget>
#include <QSet>
#include <QTimer>

#include <memory>
#include <optional>
#include <utility>

namespace vct::doc {
class Document;
}
namespace vct::render {
class Renderer;
}
namespace vct::sync {
class SceneSync;
}

namespace vct::ui {

class NonFiniteOverlay;
class ViewportOverlay;

/**
 * The 3D view: hosts the renderer in a QOpenGLWidget, navigates the camera (the left button orbits about the
 * surface point under the cursor, else the selection's centre, else the look-at point; pan with the middle
 * button or Shift, wheel zoom, WASD/QE fly, F frames the selection), picks nodes with a click and moves the
 * selected node with Ctrl+drag (hold X, Y or Z to keep to that axis). Each completed camera gesture leaves
 * the camera before it in a short history that undoView() walks back. While anything moves it renders at
 * reduced resolution and refines to full resolution once idle. With the inspector on, the right half shows
 * the voxels of one mip level as instanced cubes seen by the same camera.
 */
class ViewportWidget : public QOpenGLWidget {
    Q_OBJECT

public:
    explicit ViewportWidget(doc::Document* document, QWidget* parent = nullptr);
    ~ViewportWidget() override;

    void setInspector(const InspectorSettings& settings);
    const InspectorSettings& inspector() const { return m_inspector; }
    /**
     * Renders the current view at full resolution now and returns its linear radiance (export, tests, the
     * reference comparison). @p stats, if given, receives that frame's figures (GPU ms of the passes that
     * ran).
     */
    render::RadianceImage renderFullFrame(int width, int height, render::FrameStats* stats = nullptr);
    /** Cubes drawn in the last frame by the inspector. */
    std::size_t lastCubeCount() const { return m_lastCubeCount; }
    /** Mip levels the renderer has (0 before the first frame). */
    int voxelLevelCount() const { return m_levelCount; }
    /** Grids the renderer holds its voxels in (a clipmap's levels; 1 for a dense grid). */
    int voxelGridCount() const { return m_gridCount; }
    /** Voxels of level 0 whose opacity is non-zero, counted from the renderer's albedo volume. */
    std::size_t occupiedVoxelCount();
    QString lastError() const { return m_error; }
    /** How many times a GL context was set up for this widget (it is recreated when the window changes). */
    int contextGeneration() const { return m_contextGeneration; }
    bool isInteractive() const { return m_interactive; }
    /** The NaN/Inf overlay: while on, each frame ends with a count of non-finite texels in every target. */
    void setNonFiniteCheck(bool enabled);
    bool nonFiniteCheck() const { return m_nonFiniteCheck; }
    const NonFiniteOverlay* nonFiniteOverlay() const { return m_nonFiniteOverlay; }
    /** Selection box, light icons and the last frame's figures, over the image. */
    const ViewportOverlay* overlay() const { return m_overlay; }
    /** The handles shown for the selection: W move, E rotate, R scale, Q none (keys over the view). */
    GizmoMode gizmoMode() const { return m_gizmo.mode(); }
    void setGizmoMode(GizmoMode mode);
    /**
     * The keys and mouse gestures the view handles itself rather than through a QAction, as (keys, what they
     * do): Help > Keyboard shortcuts lists them beside the actions' shortcuts.
     */
    static QList<std::pair<QString, QString>> inputBindings();
    /**
     * Rebuilds every shader program from the shaders/ folder `folder` and redraws. A program whose new text
     * does not compile keeps its last good build: the failures come back, one message each; empty when all
     * rebuilt (or there is no renderer yet, which reads the folder when it starts: nothing to rebuild).
     */
    QStringList reloadShaders(const QString& folder);

public slots:
    /** Frames the selected node, or with nothing selected, the whole scene as frameAll() does. */
    void frameSelected();
    /** Frames every visible node; from inside the scene's bounds it turns to their centre (CameraController).
     */
    void frameAll();
    /** Back to the document's own camera, as opened or last saved. */
    void resetCamera();
    /** To bookmark `index` of the document, as one step of Undo view. */
    void goToBookmark(int index);
    /** Back to the camera before the last completed orbit, pan, zoom, fly, frame or reset. */
    void undoView();
    /** The light the gizmo takes while no node is selected (the scene tree's current light), or -1. */
    void setSelectedLight(int light);

signals:
    void frameRendered(const vct::render::FrameStats& stats);
    void cubesDrawn(int count, int levelCount, int gridCount);
    void voxelHovered(const QString& text);
    void rendererFailed(const QString& message);
    /** Whether undoView() has a camera to go back to. */
    void viewHistoryChanged(bool canUndo);
    /** A click on light @p light's icon: the Scene panel makes it the current row. */
    void lightClicked(int light);

protected:
    void initializeGL() override;
    void paintGL() override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void keyReleaseEvent(QKeyEvent* event) override;
    void focusOutEvent(QFocusEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void enterEvent(QEnterEvent* event) override;

private:
    void releaseGl();
    /** The inspector's mip level and grid, within what the renderer has. */
    int inspectedLevel() const;
    int inspectedGrid() const;
    void startInteraction();
    void setCamera(const render::Camera& camera);
    /** A camera change in one step (frame, reset): recorded as a gesture of its own. */
    void jumpTo(const render::Camera& camera);
    void beginGesture();
    /** Ends the gesture in progress, if any, once no drag, wheel burst or fly is still part of it. */
    void endGestureIfIdle();
    void endGesture();
    /**
     * Picks the centre of the orbit just begun from the press position: the surface there (bringing the
     * look-at point to its depth), else the selection's centre, else the look-at point.
     */
    void startOrbit();
    /** World bounds of the visible nodes' meshes, or of node @p only alone when it is >= 0. */
    render::Aabb visibleBounds(int only = -1) const;
    void flyStep();
    void hoverVoxel(const QPoint& position);
    /** World ray through a widget position (in the cone-traced half when the inspector splits the view). */
    bool rayThrough(
        const QPoint& position, glm::vec3& origin, glm::vec3& direction, bool inspectorHalf) const;
    QRect traceRect() const;
    QRect inspectorRect() const;
    /** How world points map to the image the overlay draws on, for the gizmo. */
    ViewProjection viewProjection() const;
    /** Hands the overlay the gizmo as the selection, camera and mode now place it. */
    void refreshGizmo();
    /** Starts flying if a fly key is held while the right button looks around. */
    void startFlying();
    bool flyKeyHeld() const;

    doc::Document* m_document;
    std::unique_ptr<render::Renderer> m_renderer;
    std::unique_ptr<sync::SceneSync> m_sync;
    InspectorSettings m_inspector;
    static constexpr float kInteractiveScale = 0.35f; ///< share of the resolution while the view moves
    /// Bounce iterations a frame of the view runs (Renderer::setBounceIterationsPerFrame); frames follow one
    /// another until the light has converged.
    static constexpr int kBounceIterationsPerFrame = 2;
    bool m_interactive = false;
    QTimer m_refineTimer;
    QTimer m_flyTimer;
    QElapsedTimer m_flyClock;
    float m_flySpeed = 1.0f; ///< metres per second of the flight under way
    QSet<int> m_flyKeys;
    QPoint m_lastMouse;
    QPoint m_pressPosition;
    Qt::MouseButton m_dragButton = Qt::NoButton;
    bool m_movingNode = false;
    std::optional<glm::vec3> m_pivot; ///< the orbit's centre for the drag in progress, once it has started
    CameraHistory m_history;
    std::optional<render::Camera> m_gestureStart;
    /// A wheel burst is one zoom gesture: it ends once the wheel has been still this long.
    QTimer m_wheelGestureTimer;
    /// The camera as this view last knew it: a reset to another one means another scene, whose history this
    /// is not.
    render::Camera m_knownCamera;
    std::size_t m_lastCubeCount = 0;
    int m_levelCount = 0;
    int m_gridCount = 1;
    QString m_error;
    int m_contextGeneration = 0;
    bool m_nonFiniteCheck = false;
    NonFiniteOverlay* m_nonFiniteOverlay;
    ViewportOverlay* m_overlay;
    GizmoController m_gizmo;
    int m_gizmoHover = -1; ///< the gizmo part under the cursor, -1 for none
};

} // namespace vct::ui
