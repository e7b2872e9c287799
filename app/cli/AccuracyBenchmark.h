#pragma once

#include "cli/AccuracyRow.h"
#include "cli/AccuracySweep.h"
#include "image/RadianceImage.h"
#include "reference/ReferenceSettings.h"
#include "scene/Camera.h"
#include "scene/Scene.h"

#include <string>
#include <vector>

namespace vct::render {
class Renderer;
}

namespace vct::cli {

/**
 * Measures one point of `vct-bench accuracy` against a reference image: a VCT setting (GPU time of full
 * frames and the error of the image) or the path tracer at some samples per pixel (wall-clock time and
 * error). Images are rendered at the reference's size with the given camera.
 */
class AccuracyBenchmark {
public:
    /** @p reference is linear radiance; it must outlive the benchmark. */
    explicit AccuracyBenchmark(const render::RadianceImage& reference);

    /**
     * Applies the point's settings, renders a warm-up frame, then @p frames full frames
     * (Renderer::invalidate() before each: every pass re-run) and @p frames camera-only frames; the error is
     * of the last full frame. The renderer's context must be current and its scene set. GL messages and
     * non-finite pixels are appended to @p warnings.
     */
    AccuracyRow measureVct(render::Renderer& renderer, const render::Camera& camera, const SweepPoint& point,
        int frames, std::vector<std::string>& warnings) const;

    /**
     * One independent path-traced image at @p spp with @p settings (give it a seed other than the
     * reference's); the time is ReferenceRenderer::render() alone, not Embree's scene build.
     */
    AccuracyRow measurePathTracer(const render::Scene& scene, const render::Camera& camera, int spp,
        const render::ReferenceSettings& settings, std::vector<std::string>& warnings) const;

    /** Fills the error columns of @p row from @p image against the reference. */
    void measureError(const render::RadianceImage& image, AccuracyRow& row) const;

private:
    const render::RadianceImage& m_reference;
};

} // namespace vct::cli
