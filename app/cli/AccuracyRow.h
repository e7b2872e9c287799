#pragma once

#include <limits>
#include <string>

namespace vct::cli {

/**
 * One measured point of `vct-bench accuracy`: a VCT setting (kind "vct") or the path tracer at some samples
 * per pixel (kind "reference"). Figures that do not apply to a kind are NaN and written as empty CSV fields.
 * Times in milliseconds; errors against the study's reference image, on linear radiance.
 */
struct AccuracyRow {
    static constexpr double kNone = std::numeric_limits<double>::quiet_NaN();

    int point = -1; ///< Job index (--only-point K); unique within a study.
    std::string kind; ///< "vct" or "reference"
    std::string label; ///< Shown next to the point in the plot: "voxel_res=32", "fast", "16 spp"
    std::string setting; ///< The swept key, "base", "preset" or "spp"
    std::string value; ///< The swept value, or a preset's assignments separated by spaces
    double gpuMs = kNone; ///< VCT: median GPU ms of a full frame (every pass re-run)
    double coneMs = kNone; ///< VCT: median GPU ms of the cone-trace pass in those frames
    double cameraMs = kNone; ///< VCT: median GPU ms of a camera-only frame (voxels and mips reused)
    double relMse = kNone; ///< mean of (x - ref)^2 / (ref^2 + 1e-2) over pixels and channels
    double rmse = kNone; ///< radiance units
    double psnr = kNone; ///< dB, peak radiance 1
    double ssim = kNone; ///< of the tone-mapped images, exposure 1
    double meanRatio = kNone; ///< mean luminance of the image / mean luminance of the reference
    int spp = 0; ///< reference: samples per pixel; 0 for VCT
    double wallMs = kNone; ///< VCT: median CPU wall-clock ms of a full frame; reference: render() time
    /// CPU time of all the process's threads over the same interval as wallMs (llvmpipe's and the path
    /// tracer's worker threads included): on shared cores it does not grow with other processes' load as wall
    /// time does.
    double cpuMs = kNone;
    int width = 0;
    int height = 0;
    int jobs = 0; ///< Points in the whole study, so a merge can tell which are missing.
    std::string machine; ///< VCT: the GL renderer; reference: the CPU and thread count
    /// 1-minute load average after the point: on shared cores, how loaded the machine was.
    double loadAverage = kNone;

    bool isVct() const { return kind == "vct"; }
    /** The time the plot puts on its x axis: GPU ms for VCT, wall-clock ms for the path tracer. */
    double timeMs() const { return isVct() ? gpuMs : wallMs; }
};

} // namespace vct::cli
