#include "ReferenceCompareDock.h"

#include "ReferenceJob.h"
#include "ui/ImagePane.h"

#include "document/Document.h"
#include "imageio/ToneMapper.h"

#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <thread>

namespace vct::ui {

namespace {

constexpr int kDefaultLongSide = 256;
constexpr int kDefaultTargetSpp = 256;

QImage toDisplay(const render::RadianceImage& image, const io::ToneMapper& mapper)
{
    if (image.isEmpty())
        return {};
    const std::vector<std::uint8_t> rgb = mapper.toRgb8(image);
    return QImage(rgb.data(), image.width, image.height, 3 * image.width, QImage::Format_RGB888).copy();
}

QLabel* makeValueLabel(const QString& objectName, QWidget* parent)
{
    auto* label = new QLabel(QStringLiteral("—"), parent);
    label->setObjectName(objectName);
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    return label;
}

QString formatNumber(double value)
{
    return std::isfinite(value) ? QString::number(value, 'g', 4) : QString::number(value);
}

} // namespace

ReferenceCompareDock::ReferenceCompareDock(QWidget* parent)
    : QDockWidget(tr("Compare with reference"), parent)
    , m_job(std::make_unique<ReferenceJob>())
{
    setObjectName(QStringLiteral("ReferenceCompareDock"));
    auto* body = new QWidget(this);

    m_longSide = new QSpinBox(body);
    m_longSide->setObjectName(QStringLiteral("compareSizeBox"));
    m_longSide->setRange(8, 4096);
    m_longSide->setValue(kDefaultLongSide);
    m_longSide->setSuffix(tr(" px"));
    m_longSide->setToolTip(tr("Pixels along the longer side of the comparison; the other side follows the "
                              "viewport's aspect ratio. The path tracer's time grows with the pixel count."));
    m_targetSpp = new QSpinBox(body);
    m_targetSpp->setObjectName(QStringLiteral("compareTargetSppBox"));
    m_targetSpp->setRange(1, 1 << 20);
    m_targetSpp->setValue(kDefaultTargetSpp);
    m_targetSpp->setSuffix(tr(" spp"));
    m_targetSpp->setToolTip(tr("Samples per pixel at which the reference stops. Passes start at 4 spp and "
                               "double the total each time, so the picture refreshes early and often."));
    m_start = new QPushButton(tr("Compare"), body);
    m_start->setObjectName(QStringLiteral("compareStartButton"));
    m_start->setToolTip(tr("Render the current view with the cone tracer and the path tracer (Ctrl+R)"));
    m_cancel = new QPushButton(tr("Cancel"), body);
    m_cancel->setObjectName(QStringLiteral("compareCancelButton"));
    m_cancel->setEnabled(false);
    m_progress = new QProgressBar(body);
    m_progress->setObjectName(QStringLiteral("compareProgress"));
    m_progress->setRange(0, kDefaultTargetSpp);
    m_progress->setValue(0);
    m_progress->setFormat(tr("%v / %m spp"));

    auto* controls = new QHBoxLayout;
    controls->addWidget(new QLabel(tr("Long side"), body));
    controls->addWidget(m_longSide);
    controls->addWidget(new QLabel(tr("Target"), body));
    controls->addWidget(m_targetSpp);
    controls->addWidget(m_start);
    controls->addWidget(m_cancel);
    controls->addWidget(m_progress, 1);

    m_vctPane = new ImagePane(tr("VCT"), body);
    m_vctPane->setObjectName(QStringLiteral("compareVctPane"));
    m_referencePane = new ImagePane(tr("Reference"), body);
    m_referencePane->setObjectName(QStringLiteral("compareReferencePane"));
    m_heatmapPane = new ImagePane(tr("Relative error"), body);
    m_heatmapPane->setObjectName(QStringLiteral("compareHeatmapPane"));
    m_heatmapPane->setToolTip(
        tr("Per-pixel relative error: black 0, blue 25%, green 50%, yellow 75%, red 100% "
           "or more; magenta where a value is not finite"));
    auto* images = new QHBoxLayout;
    images->addWidget(m_vctPane);
    images->addWidget(m_referencePane);
    images->addWidget(m_heatmapPane);

    m_relMse = makeValueLabel(QStringLiteral("compareRelMseLabel"), body);
    m_rmse = makeValueLabel(QStringLiteral("compareRmseLabel"), body);
    m_psnr = makeValueLabel(QStringLiteral("comparePsnrLabel"), body);
    m_ssim = makeValueLabel(QStringLiteral("compareSsimLabel"), body);
    m_spp = makeValueLabel(QStringLiteral("compareSppLabel"), body);
    m_elapsed = makeValueLabel(QStringLiteral("compareElapsedLabel"), body);
    m_gpu = makeValueLabel(QStringLiteral("compareGpuLabel"), body);
    m_size = makeValueLabel(QStringLiteral("compareSizeLabel"), body);
    auto* form = new QFormLayout;
    form->addRow(tr("Relative MSE"), m_relMse);
    form->addRow(tr("RMSE"), m_rmse);
    form->addRow(tr("PSNR"), m_psnr);
    form->addRow(tr("SSIM"), m_ssim);
    form->addRow(tr("Reference"), m_spp);
    form->addRow(tr("Elapsed"), m_elapsed);
    form->addRow(tr("VCT frame"), m_gpu);
    form->addRow(tr("Size"), m_size);
    form->labelForField(m_relMse)->setToolTip(
        tr("Mean of (vct - ref)² / (ref² + 0.01) over pixels and channels"));
    form->labelForField(m_psnr)->setToolTip(tr("On linear radiance, full scale = radiance 1"));
    form->labelForField(m_ssim)->setToolTip(
        tr("Structural similarity of the tone-mapped images (1 = identical)"));
    form->labelForField(m_gpu)->setToolTip(
        tr("GPU time of the cone-traced frame; passes the renderer reused from its cache add nothing"));

    auto* results = new QHBoxLayout;
    results->addLayout(images, 1);
    results->addLayout(form);

    m_status = new QLabel(tr("Ctrl+R compares the current view with a path-traced reference."), body);
    m_status->setObjectName(QStringLiteral("compareStatusLabel"));
    m_status->setWordWrap(true);
    m_staleLabel
        = new QLabel(tr("Stale: the scene or the view changed after this comparison started."), body);
    m_staleLabel->setObjectName(QStringLiteral("compareStaleLabel"));
    m_staleLabel->setStyleSheet(QStringLiteral("color: #c07000; font-weight: bold"));
    m_staleLabel->setVisible(false);

    auto* layout = new QVBoxLayout(body);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(controls);
    layout->addLayout(results, 1);
    layout->addWidget(m_staleLabel);
    layout->addWidget(m_status);
    setWidget(body);

    connect(m_start, &QPushButton::clicked, this, &ReferenceCompareDock::startComparison);
    connect(m_cancel, &QPushButton::clicked, this, &ReferenceCompareDock::cancelComparison);
    // The job emits from its worker threads: these are queued connections to the GUI thread.
    connect(m_job.get(), &ReferenceJob::progress, this, &ReferenceCompareDock::onProgress);
    connect(m_job.get(), &ReferenceJob::passFinished, this, &ReferenceCompareDock::onPass);
    connect(m_job.get(), &ReferenceJob::finished, this, &ReferenceCompareDock::onFinished);
    connect(m_job.get(), &ReferenceJob::failed, this, &ReferenceCompareDock::onFailed);
}

ReferenceCompareDock::~ReferenceCompareDock()
{
    // Stops and joins the workers while this dock still exists; events they posted to it die with it.
    m_job.reset();
}

void ReferenceCompareDock::setDocument(doc::Document* document)
{
    if (m_document)
        disconnect(m_document, nullptr, this, nullptr);
    m_document = document;
    if (m_document)
        connect(m_document, &doc::Document::changed, this, &ReferenceCompareDock::onDocumentChanged);
}

void ReferenceCompareDock::setFrameSource(ViewAspect aspect, FrameRenderer renderer)
{
    m_viewAspect = std::move(aspect);
    m_renderFrame = std::move(renderer);
}

QSize ReferenceCompareDock::comparisonSize(int longSide, double aspect)
{
    longSide = std::max(1, longSide);
    if (!(aspect > 0.0) || !std::isfinite(aspect))
        aspect = 1.0;
    const int shortSide = std::max(1, int(std::lround(double(longSide) / std::max(aspect, 1.0 / aspect))));
    return aspect >= 1.0 ? QSize(longSide, shortSide) : QSize(shortSide, longSide);
}

void ReferenceCompareDock::startComparison()
{
    if (!m_document || !m_renderFrame) {
        m_status->setText(tr("Nothing to compare: no document or viewport."));
        return;
    }
    // Cancel first, so the old job's CPU time goes to the new one as soon as it notices.
    m_job->cancel();
    setRunning(false);

    const QSize size = comparisonSize(m_longSide->value(), m_viewAspect ? m_viewAspect() : 1.0);
    double gpuMs = -1.0;
    render::RadianceImage vct = m_renderFrame(size.width(), size.height(), gpuMs);
    if (vct.isEmpty() || vct.width != size.width() || vct.height != size.height()) {
        m_status->setText(tr("The viewport cannot render yet; try again once it shows the scene."));
        return;
    }

    ReferenceRequest request;
    request.scene = m_document->buildRenderScene();
    request.camera = m_document->state().camera;
    request.vctImage = vct;
    request.targetSpp = m_targetSpp->value();
    request.exposure = m_document->state().settings.exposure;
    // One core stays free for the interface and llvmpipe's viewport, so the editor stays responsive.
    request.settings.threads = std::max(1, int(std::thread::hardware_concurrency()) - 1);

    m_vct = std::move(vct);
    m_vctGpuMs = gpuMs;
    m_exposure = request.exposure;
    m_last = ReferenceUpdate {};
    m_vctPane->setImage(toDisplay(m_vct, io::ToneMapper(m_exposure)));
    m_referencePane->setImage({});
    m_heatmapPane->setImage({});
    m_referencePane->setCaption(tr("Reference"));
    clearNumbers();
    m_gpu->setText(m_vctGpuMs >= 0.0 ? tr("%1 ms GPU").arg(m_vctGpuMs, 0, 'f', 2) : QStringLiteral("—"));
    m_size->setText(tr("%1 × %2 px").arg(size.width()).arg(size.height()));
    m_progress->setRange(0, request.targetSpp);
    m_progress->setValue(0);
    setStale(false);

    m_jobId = m_job->start(std::move(request));
    m_clock.start();
    setRunning(true);
    m_status->setText(tr("Rendering the reference in the background…"));
}

void ReferenceCompareDock::cancelComparison()
{
    if (!m_running)
        return;
    m_job->cancel();
    m_cancel->setEnabled(false);
    m_status->setText(tr("Cancelling…"));
}

void ReferenceCompareDock::onDocumentChanged(const doc::ChangeEvent& event)
{
    // Renaming a node or flagging it dynamic changes no pixel.
    if (event.kind == doc::ChangeEvent::Kind::NodeProperty)
        return;
    if (m_running || !m_vct.isEmpty())
        setStale(true);
}

void ReferenceCompareDock::onProgress(int jobId, int doneSpp, int passSpp, double fraction)
{
    if (jobId != m_jobId || !m_running)
        return;
    m_progress->setValue(std::min(m_progress->maximum(), doneSpp + int(double(passSpp) * fraction)));
    showElapsed(double(m_clock.elapsed()) / 1000.0);
}

void ReferenceCompareDock::onPass(const ReferenceUpdate& update)
{
    if (update.jobId != m_jobId)
        return;
    m_last = update;
    m_referencePane->setImage(toDisplay(update.reference, io::ToneMapper(m_exposure)));
    m_referencePane->setCaption(tr("Reference, %1 spp").arg(update.samplesPerPixel));
    m_heatmapPane->setImage(toDisplay(update.heatmap, io::ToneMapper(1.0f, io::ToneMapper::Curve::Clamp)));
    m_relMse->setText(formatNumber(update.relativeMse));
    m_rmse->setText(formatNumber(update.rmse));
    m_psnr->setText(tr("%1 dB").arg(formatNumber(update.psnrDb)));
    m_ssim->setText(formatNumber(update.ssim));
    m_spp->setText(tr("%1 of %2 spp").arg(update.samplesPerPixel).arg(update.targetSpp));
    m_progress->setValue(std::min(m_progress->maximum(), update.samplesPerPixel));
    showElapsed(update.seconds);
}

void ReferenceCompareDock::onFinished(int jobId, bool completed, int samplesPerPixel)
{
    if (jobId != m_jobId)
        return;
    setRunning(false);
    const QString elapsed = m_elapsed->text();
    if (completed) {
        m_progress->setValue(m_progress->maximum());
        m_status->setText(tr("Done: %1 spp in %2.").arg(samplesPerPixel).arg(elapsed));
    } else if (samplesPerPixel > 0) {
        // The bar had moved on into the pass that was dropped: back to what the numbers are of.
        m_progress->setValue(std::min(m_progress->maximum(), samplesPerPixel));
        m_status->setText(
            tr("Cancelled at %1 spp; the last finished pass stays shown.").arg(samplesPerPixel));
    } else {
        m_status->setText(tr("Cancelled before the first pass finished."));
    }
    emit comparisonFinished(completed);
}

void ReferenceCompareDock::onFailed(int jobId, const QString& message)
{
    if (jobId != m_jobId)
        return;
    setRunning(false);
    m_status->setText(tr("The reference render failed: %1").arg(message));
    emit comparisonFailed(message);
}

void ReferenceCompareDock::setRunning(bool running)
{
    m_running = running;
    m_cancel->setEnabled(running);
    m_start->setText(running ? tr("Restart") : tr("Compare"));
}

void ReferenceCompareDock::setStale(bool stale)
{
    m_stale = stale;
    m_staleLabel->setVisible(stale);
}

void ReferenceCompareDock::clearNumbers()
{
    for (QLabel* label : { m_relMse, m_rmse, m_psnr, m_ssim, m_elapsed, m_gpu, m_size })
        label->setText(QStringLiteral("—"));
    m_spp->setText(tr("0 of %1 spp").arg(m_targetSpp->value()));
}

void ReferenceCompareDock::showElapsed(double seconds)
{
    m_elapsed->setText(tr("%1 s").arg(seconds, 0, 'f', seconds < 10.0 ? 2 : 1));
}

} // namespace vct::ui
