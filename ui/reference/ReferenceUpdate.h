#pragma once

#include "image/RadianceImage.h"

namespace vct::ui {

/**
 * What a reference job reports after each finished pass: the reference so far and how far the cone-traced
 * image is from it. Plain values, copied across threads by queued signals.
 */
struct ReferenceUpdate {
    int jobId = 0;
    render::RadianceImage reference; ///< Mean radiance so far, W/(m^2 sr).
    render::RadianceImage heatmap; ///< ImageMetrics::errorHeatmap(vct, reference): display values in [0, 1].
    int samplesPerPixel = 0; ///< Samples in @c reference so far.
    int targetSpp = 0;
    double seconds = 0.0; ///< Wall clock since the job started, scene build included.
    double relativeMse = 0.0;
    double rmse = 0.0; ///< Radiance units.
    double psnrDb = 0.0; ///< Against a peak radiance of kPsnrPeak.
    double ssim = 0.0;

    /** Full-scale radiance of the PSNR: the Cornell walls' lit radiance is about 1. */
    static constexpr double kPsnrPeak = 1.0;
};

} // namespace vct::ui
