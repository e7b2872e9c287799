#pragma once

#include "ReferenceUpdate.h"

#include "image/RadianceImage.h"

#include <QDockWidget>
#include <QElapsedTimer>

#include <functional>
#include <memory>

class QLabel;
class QProgressBar;
class QPushButton;
class QSpinBox;

namespace vct::doc {
class Document;
struct ChangeEvent;
} // namespace vct::doc

namespace vct::ui {

class ImagePane;
class ReferenceJob;

/**
 * "Compare with reference": renders the cone-traced image of the current view at a comparison size, runs the
 * CPU path tracer on the same scene and camera in the background, pass after pass (4 spp, then doubling up to
 * a target), and after each pass shows VCT | reference | error heatmap side by side with relative MSE, RMSE,
 * PSNR, SSIM, samples so far and time. Cancel keeps the last finished pass on screen; starting again cancels
 * the running job first.
 *
 * The comparison works on a snapshot of the document taken when it starts. Edits and camera moves made while
 * it runs do not stop it (the snapshot is still a valid comparison, and stopping would throw away minutes of
 * samples over a stray click); they mark the result stale with a label until the next start.
 *
 * Knows no GL and no viewport: the window hands it a function that renders the VCT frame (setFrameSource).
 */
class ReferenceCompareDock : public QDockWidget {
    Q_OBJECT

public:
    /**
     * Renders the current view with the cone tracer at @p width x @p height pixels and returns its linear
     * radiance, or an empty image when nothing can render yet; sets @p gpuMs to the frame's GPU time in ms,
     * or leaves it negative when unknown. Called on the GUI thread.
     */
    using FrameRenderer = std::function<render::RadianceImage(int width, int height, double& gpuMs)>;
    /** The current view's aspect ratio, width / height (> 0). */
    using ViewAspect = std::function<double()>;

    explicit ReferenceCompareDock(QWidget* parent = nullptr);
    ~ReferenceCompareDock() override;

    void setDocument(doc::Document* document);
    void setFrameSource(ViewAspect aspect, FrameRenderer renderer);

    /** The comparison size: @p longSide pixels along the longer axis, the other from @p aspect (w / h). */
    static QSize comparisonSize(int longSide, double aspect);

    bool isRunning() const { return m_running; }
    /** The document changed after the shown comparison started. */
    bool isStale() const { return m_stale; }
    /** Linear radiance of what is shown: the cone-traced frame, the reference so far, and the heatmap. */
    const render::RadianceImage& vctImage() const { return m_vct; }
    const render::RadianceImage& referenceImage() const { return m_last.reference; }
    const render::RadianceImage& heatmapImage() const { return m_last.heatmap; }
    /** The scores and sample count of the last finished pass (samplesPerPixel 0 before the first). */
    const ReferenceUpdate& lastUpdate() const { return m_last; }
    /** GPU time of the VCT frame in ms, negative when unknown. */
    double vctGpuMs() const { return m_vctGpuMs; }

    QSpinBox* longSideBox() const { return m_longSide; }
    QSpinBox* targetSppBox() const { return m_targetSpp; }
    QPushButton* startButton() const { return m_start; }
    QPushButton* cancelButton() const { return m_cancel; }
    QProgressBar* progressBar() const { return m_progress; }
    ImagePane* vctPane() const { return m_vctPane; }
    ImagePane* referencePane() const { return m_referencePane; }
    ImagePane* heatmapPane() const { return m_heatmapPane; }
    QLabel* relativeMseLabel() const { return m_relMse; }
    QLabel* statusLabel() const { return m_status; }
    QLabel* staleLabel() const { return m_staleLabel; }

public slots:
    /** Renders the VCT frame now and starts the reference in the background (cancelling a running one). */
    void startComparison();
    /** Asks the running job to stop; the last finished pass stays shown. */
    void cancelComparison();

signals:
    /** The current comparison ended: @p completed when it reached the target spp, false when cancelled. */
    void comparisonFinished(bool completed);
    void comparisonFailed(const QString& message);

private:
    void onDocumentChanged(const doc::ChangeEvent& event);
    void onProgress(int jobId, int doneSpp, int passSpp, double fraction);
    void onPass(const ReferenceUpdate& update);
    void onFinished(int jobId, bool completed, int samplesPerPixel);
    void onFailed(int jobId, const QString& message);
    void setRunning(bool running);
    void setStale(bool stale);
    void clearNumbers();
    void showElapsed(double seconds);

    doc::Document* m_document = nullptr;
    ViewAspect m_viewAspect;
    FrameRenderer m_renderFrame;
    std::unique_ptr<ReferenceJob> m_job;
    int m_jobId = 0;
    bool m_running = false;
    bool m_stale = false;
    float m_exposure = 1.0f; ///< The document's exposure when the comparison started.
    render::RadianceImage m_vct;
    double m_vctGpuMs = -1.0;
    ReferenceUpdate m_last;
    QElapsedTimer m_clock;

    QSpinBox* m_longSide;
    QSpinBox* m_targetSpp;
    QPushButton* m_start;
    QPushButton* m_cancel;
    QProgressBar* m_progress;
    ImagePane* m_vctPane;
    ImagePane* m_referencePane;
    ImagePane* m_heatmapPane;
    QLabel* m_relMse;
    QLabel* m_rmse;
    QLabel* m_psnr;
    QLabel* m_ssim;
    QLabel* m_spp;
    QLabel* m_elapsed;
    QLabel* m_gpu;
    QLabel* m_size;
    QLabel* m_status;
    QLabel* m_staleLabel;
};

} // namespace vct::ui
