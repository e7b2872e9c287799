#include "cli/TargetsBenchmark.h"

#include "Renderer.h"
#include "cli/CameraOrbit.h"
#include "imageio/ImageMetrics.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

namespace vct::cli {

namespace {

constexpr float kOrbitStepDeg = 0.5f;

struct Pairs {
    std::vector<double> naive, fast, ratios;
    void add(double naiveMs, double fastMs)
    {
        naive.push_back(naiveMs);
        fast.push_back(fastMs);
        ratios.push_back(fastMs > 0.0 ? naiveMs / fastMs : 0.0);
    }
};

// One frame of each path; the order alternates (ABBA) so neither side always runs first after a pause.
void framePair(Pairs& pairs, int index, render::Renderer& naive, render::Renderer& fast,
    const render::Camera& camera, int width, int height, bool full)
{
    const auto frame = [&](render::Renderer& renderer) {
        if (full)
            renderer.invalidate();
        return renderer.renderFrame(camera, width, height).totalGpuMs;
    };
    double naiveMs = 0.0, fastMs = 0.0;
    if (index % 2 == 0) {
        naiveMs = frame(naive);
        fastMs = frame(fast);
    } else {
        fastMs = frame(fast);
        naiveMs = frame(naive);
    }
    pairs.add(naiveMs, fastMs);
}

std::optional<double> errorAgainst(const render::RadianceImage& frame, const render::RadianceImage* reference)
{
    if (!reference)
        return std::nullopt;
    if (frame.width == reference->width && frame.height == reference->height)
        return io::ImageMetrics::relativeMse(frame, *reference);
    const int factor = frame.width / reference->width;
    if (factor < 1 || reference->width * factor != frame.width || reference->height * factor != frame.height)
        throw std::invalid_argument("the reference is " + std::to_string(reference->width) + "x"
            + std::to_string(reference->height) + ": the frame size must be an integer multiple of it");
    return io::ImageMetrics::relativeMse(io::ImageMetrics::downsampleBox(frame, factor), *reference);
}

} // namespace

TargetsResult TargetsBenchmark::run(render::Renderer& naive, render::Renderer& fast,
    const render::Camera& camera, int width, int height, int previewWidth, int previewHeight, int frames,
    const render::RadianceImage* reference)
{
    TargetsResult result;
    result.width = width;
    result.height = height;
    result.previewWidth = previewWidth;
    result.previewHeight = previewHeight;
    result.frames = std::max(1, frames);

    // Warm-up: shaders compiled, targets and voxel textures allocated.
    for (render::Renderer* renderer : { &naive, &fast })
        renderer->renderFrame(camera, width, height);
    Pairs full;
    for (int i = 0; i < result.frames; ++i)
        framePair(full, i, naive, fast, camera, width, height, true);
    // Both last rendered a full frame at the base camera: those are the images the error is taken on.
    result.naiveRelativeMse = errorAgainst(naive.readFrame(), reference);
    result.fastRelativeMse = errorAgainst(fast.readFrame(), reference);

    render::Camera moving = camera;
    orbitCamera(moving, kOrbitStepDeg);
    for (render::Renderer* renderer : { &naive, &fast })
        renderer->renderFrame(moving, width, height); // warm-up of the camera-only path
    Pairs cameraOnly;
    for (int i = 0; i < result.frames; ++i) {
        orbitCamera(moving, kOrbitStepDeg);
        framePair(cameraOnly, i, naive, fast, moving, width, height, false);
    }

    // The preview: the fast path only, camera-only frames at the reduced size (its own warm-up first, as
    // the new size reallocates the screen targets).
    std::vector<double> preview;
    fast.renderFrame(moving, previewWidth, previewHeight);
    for (int i = 0; i < result.frames; ++i) {
        orbitCamera(moving, kOrbitStepDeg);
        preview.push_back(fast.renderFrame(moving, previewWidth, previewHeight).totalGpuMs);
    }

    result.naiveFullMs = median(full.naive);
    result.fastFullMs = median(full.fast);
    result.fullRatio = median(full.ratios);
    result.fullRatioMin = *std::min_element(full.ratios.begin(), full.ratios.end());
    result.fullRatioMax = *std::max_element(full.ratios.begin(), full.ratios.end());
    result.naiveCameraMs = median(cameraOnly.naive);
    result.fastCameraMs = median(cameraOnly.fast);
    result.cameraRatio = median(cameraOnly.ratios);
    result.cameraRatioMin = *std::min_element(cameraOnly.ratios.begin(), cameraOnly.ratios.end());
    result.cameraRatioMax = *std::max_element(cameraOnly.ratios.begin(), cameraOnly.ratios.end());
    result.previewMs = median(preview);
    return result;
}

std::string TargetsBenchmark::markdown(const TargetsResult& r)
{
    std::string text;
    char line[512];
    const auto add = [&text, &line](int n) {
        text.append(line, std::size_t(std::max(0, std::min(n, int(sizeof line) - 1))));
    };
    add(std::snprintf(line, sizeof line,
        "Output %d×%d, %d timed frame pairs per mode; GPU ms are medians, ratios are medians of the per-pair "
        "ratios (min–max).\n\n",
        r.width, r.height, r.frames));
    text += "| target | naive ms | fast ms | ratio (min–max) | goal | met |\n|---|---|---|---|---|---|\n";
    add(std::snprintf(line, sizeof line,
        "| full frame (every pass re-run) | %.1f | %.1f | **%.1f×** (%.1f–%.1f) | ≥ 15× | %s |\n",
        r.naiveFullMs, r.fastFullMs, r.fullRatio, r.fullRatioMin, r.fullRatioMax,
        r.fullRatio >= 15.0 ? "yes" : "no"));
    add(std::snprintf(line, sizeof line,
        "| camera-only frame | %.1f | %.1f | **%.1f×** (%.1f–%.1f) | ≥ 40× | %s |\n", r.naiveCameraMs,
        r.fastCameraMs, r.cameraRatio, r.cameraRatioMin, r.cameraRatioMax,
        r.cameraRatio >= 40.0 ? "yes" : "no"));
    const double fps = r.previewMs > 0.0 ? 1000.0 / r.previewMs : 0.0;
    add(std::snprintf(line, sizeof line,
        "| interactive preview %d×%d, camera-only | | %.1f | **%.1f fps** | ≥ 5 fps | %s |\n", r.previewWidth,
        r.previewHeight, r.previewMs, fps, fps >= 5.0 ? "yes" : "no"));
    if (r.naiveRelativeMse && r.fastRelativeMse) {
        const double worse = *r.naiveRelativeMse > 0.0 ? *r.fastRelativeMse / *r.naiveRelativeMse - 1.0 : 0.0;
        add(std::snprintf(line, sizeof line,
            "| relative MSE against the reference (full frames) | %.4f | %.4f | %+.1f%% | ≤ +10%% | %s |\n",
            *r.naiveRelativeMse, *r.fastRelativeMse, 100.0 * worse, worse <= 0.10 ? "yes" : "no"));
    }
    return text;
}

} // namespace vct::cli
