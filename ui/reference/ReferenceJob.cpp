#include "ReferenceJob.h"

#include "imageio/ImageMetrics.h"
#include "reference/ReferenceRenderer.h"

#include <algorithm>
#include <chrono>
#include <exception>

namespace vct::ui {

ReferenceJob::ReferenceJob(QObject* parent)
    : QObject(parent)
{
}

ReferenceJob::~ReferenceJob()
{
    // Joined here, while the object is still whole: a worker may be emitting a signal right now.
    for (Worker& worker : m_workers)
        worker.thread.request_stop();
    m_workers.clear();
}

int ReferenceJob::start(ReferenceRequest request)
{
    cancel();
    reapFinished();
    const int jobId = ++m_jobId;
    auto done = std::make_shared<std::atomic<bool>>(false);
    m_workers.push_back(
        { std::jthread([this, jobId, done, request = std::move(request)](std::stop_token stop) {
             run(jobId, request, stop);
             done->store(true);
         }),
            done });
    return jobId;
}

void ReferenceJob::cancel()
{
    for (Worker& worker : m_workers)
        worker.thread.request_stop();
}

void ReferenceJob::reapFinished()
{
    std::erase_if(m_workers, [](const Worker& worker) { return worker.done->load(); });
}

void ReferenceJob::run(int jobId, const ReferenceRequest& request, std::stop_token stop)
{
    const auto start = std::chrono::steady_clock::now();
    const render::RadianceImage& vct = request.vctImage;
    try {
        render::ReferenceRenderer renderer(
            request.scene, request.camera, vct.width, vct.height, request.settings);
        const int target = std::max(1, request.targetSpp);
        while (renderer.samplesPerPixel() < target && !stop.stop_requested()) {
            const int done = renderer.samplesPerPixel();
            const int pass = std::min(std::max(std::max(1, request.firstPassSpp), done), target - done);
            const bool complete = renderer.render(
                pass, [&](double fraction) { emit progress(jobId, done, pass, fraction); }, stop);
            if (!complete)
                break;

            ReferenceUpdate update;
            update.jobId = jobId;
            update.reference = renderer.image();
            update.samplesPerPixel = renderer.samplesPerPixel();
            update.targetSpp = target;
            // Scored here rather than on the GUI thread: SSIM alone is ~w*h*121 multiply-adds.
            update.relativeMse = io::ImageMetrics::relativeMse(vct, update.reference);
            update.rmse = io::ImageMetrics::rmse(vct, update.reference);
            update.psnrDb = io::ImageMetrics::psnr(vct, update.reference, ReferenceUpdate::kPsnrPeak);
            update.ssim = io::ImageMetrics::ssim(vct, update.reference, request.exposure);
            update.heatmap = io::ImageMetrics::errorHeatmap(vct, update.reference);
            update.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            emit passFinished(update);
        }
        emit finished(jobId, renderer.samplesPerPixel() >= target, renderer.samplesPerPixel());
    } catch (const std::exception& e) {
        emit failed(jobId, QString::fromUtf8(e.what()));
    }
}

} // namespace vct::ui
