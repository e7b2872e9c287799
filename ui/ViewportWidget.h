#pragma once

#include "InspectorSettings.h"

#include "core/FrameStats.h"
#include "image/RadianceImage.h"
#include "scene/Camera.h"

#include <QElapsedTimer>
#include <QOpenGLWidget>
#include <QSet>
#include <QTimer>

#include <memory>

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

/**
 * The 3D view: hosts the renderer in a QOpenGLWidget, navigates the camera (orbit with the left button,
 * pan with the middle button or Shift, wheel zoom, WASD/QE fly, F frames the selection), picks nodes with a
 * click and moves the selected node with Ctrl+drag (hold X, Y or Z to keep to that axis). While anything
 * moves it renders at reduced resolution and refines to full resolution once idle. With the inspector on, the
 * right half shows the voxels of one mip level as instanced cubes seen by the same camera.
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

public slots:
    void frameSelected();

signals:
    void frameRendered(const vct::render::FrameStats& stats);
    void cubesDrawn(int count, int levelCount);
    void voxelHovered(const QString& text);
    void rendererFailed(const QString& message);

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

private:
    void releaseGl();
    void startInteraction();
    void setCamera(const render::Camera& camera);
    void flyStep();
    void hoverVoxel(const QPoint& position);
    /** World ray through a widget position (in the cone-traced half when the inspector splits the view). */
    bool rayThrough(
        const QPoint& position, glm::vec3& origin, glm::vec3& direction, bool inspectorHalf) const;
    QRect traceRect() const;
    QRect inspectorRect() const;

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
    QSet<int> m_flyKeys;
    QPoint m_lastMouse;
    QPoint m_pressPosition;
    Qt::MouseButton m_dragButton = Qt::NoButton;
    bool m_movingNode = false;
    std::size_t m_lastCubeCount = 0;
    int m_levelCount = 0;
    QString m_error;
    int m_contextGeneration = 0;
    bool m_nonFiniteCheck = false;
    NonFiniteOverlay* m_nonFiniteOverlay;
};

} // namespace vct::ui
