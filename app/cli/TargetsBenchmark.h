#pragma once

#include "cli/Statistics.h"
#include "image/RadianceImage.h"
#include "scene/Camera.h"

#include <optional>
#include <string>
#include <vector>

namespace vct::render {
class Renderer;
}

namespace vct::cli {

/** What `vct-bench targets` measures: issue 7's ratios, each from frames interleaved in one run. */
struct TargetsResult {
    int width = 0, height = 0;
    int previewWidth = 0, previewHeight = 0;
    int frames = 0;
    // GPU ms per frame, medians over the timed frames.
    double naiveFullMs = 0.0, fastFullMs = 0.0;
    double naiveCameraMs = 0.0, fastCameraMs = 0.0;
    double previewMs = 0.0;
    // Medians of the per-pair ratios naive / fast: each pair ran back to back, so a slow spell of a shared
    // machine slows both sides of a pair and cancels out of its ratio.
    double fullRatio = 0.0, cameraRatio = 0.0;
    double fullRatioMin = 0.0, fullRatioMax = 0.0, cameraRatioMin = 0.0, cameraRatioMax = 0.0;
    std::optional<double> naiveRelativeMse, fastRelativeMse; ///< against the reference, when one was given
};

/**
 * `vct-bench targets`: the naive path and the fast path (two renderers on one context) render the same
 * scene in alternating frames: full frames (every pass re-run), then camera-only frames (the camera turns
 * 0.5 degrees before each), then the fast path's interactive preview (camera-only frames at the reduced
 * size the editor's viewport uses while the view moves). With a reference image, both paths' full frames
 * are also compared with it (box-downsampled to its size when the frame is an integer multiple of it).
 */
class TargetsBenchmark {
public:
    /** Both renderers current on the same context, each with its settings and the scene set. */
    static TargetsResult run(render::Renderer& naive, render::Renderer& fast, const render::Camera& camera,
        int width, int height, int previewWidth, int previewHeight, int frames,
        const render::RadianceImage* reference);
    /** The result as Markdown: the table of ratios against the targets. */
    static std::string markdown(const TargetsResult& result);
};

} // namespace vct::cli
