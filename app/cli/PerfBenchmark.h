#pragma once

#include "cli/PerfResult.h"
#include "debug/TrilinearRateProbe.h"
#include "scene/RenderSettings.h"
#include "scene/Scene.h"

#include <map>
#include <tuple>
#include <utility>
#include <vector>

namespace vct::render {
class Renderer;
}

namespace vct::cli {

/** The three scaling curves of `vct-bench perf` and how many frames to time. */
struct PerfOptions {
    std::vector<std::pair<int, int>> sizes { { 320, 180 }, { 640, 360 },
        { 1280, 720 } }; ///< output width, height
    std::vector<int> grids { 32, 64, 128, 256 };
    std::vector<int> triangleFactors { 1, 4, 16 };
    int baseWidth = 640, baseHeight = 360; ///< output size of the grid and triangle curves
    int baseGrid = 128; ///< grid of the size and triangle curves
    int frames = 5; ///< timed frames per mode, after one warm-up frame
};

/**
 * `vct-bench perf`: per-pass GPU time of full frames (every pass re-run) and of camera-only frames (the
 * plan reuses voxels), voxel memory per 3D texture level, and how close the cone pass comes to the peak
 * trilinear sampling rate of the machine (TrilinearRateProbe on the same context, in the same run).
 */
class PerfBenchmark {
public:
    /**
     * Configurations of the three curves, each listed once even when curves share it (the base point is on
     * all three), ordered by triangle factor so each subdivided scene is built and uploaded once.
     */
    static std::vector<PerfConfig> configurations(const PerfOptions& options);

    /** `renderer` must be current; `settings` are the base settings (the grid is set per configuration). */
    PerfBenchmark(render::Renderer& renderer, const render::Scene& scene,
        const render::RenderSettings& settings, int frames);

    /**
     * Warm-up frame, `frames` full frames, a warm-up and `frames` camera-only frames, one untimed frame
     * counting cone samples, then the probe at the cone pass's size (cached per size and grid).
     */
    PerfResult measure(const PerfConfig& config);

private:
    render::Renderer& m_renderer;
    const render::Scene& m_scene;
    render::RenderSettings m_settings;
    int m_frames;
    int m_uploadedFactor = 0; ///< triangle factor of the scene the renderer has now (0: none yet)
    std::size_t m_uploadedTriangles = 0;
    render::TrilinearRateProbe m_probe;
    std::map<std::tuple<int, int, int>, render::TrilinearRate> m_peaks; ///< by traced width, height, grid
};

} // namespace vct::cli
