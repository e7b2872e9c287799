#include "cli/PerfBenchmark.h"

#include "Renderer.h"
#include "cli/CameraOrbit.h"
#include "cli/SceneSubdivider.h"

#include <algorithm>
#include <chrono>

namespace vct::cli {

namespace {

// Small enough that every camera-only frame sees nearly the same pixels as the full frames.
constexpr float kOrbitStepDeg = 0.5f;
const char* const kConePassName = "cone trace";

TimingSpread spread(std::vector<double> values)
{
    if (values.empty())
        return {};
    std::sort(values.begin(), values.end());
    const std::size_t mid = values.size() / 2;
    const double median = values.size() % 2 ? values[mid] : 0.5 * (values[mid - 1] + values[mid]);
    return { median, values.front(), values.back() };
}

struct TimedFrame {
    render::FrameStats stats;
    double wallMs = 0.0;
};

TimedFrame timedFrame(render::Renderer& renderer, const render::Camera& camera, int width, int height)
{
    const auto start = std::chrono::steady_clock::now();
    TimedFrame frame { renderer.renderFrame(camera, width, height), 0.0 };
    frame.wallMs
        = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return frame;
}

ModeTiming summarize(const std::vector<TimedFrame>& frames)
{
    ModeTiming timing;
    if (frames.empty())
        return timing;
    std::vector<double> gpu, wall;
    for (const TimedFrame& f : frames) {
        gpu.push_back(f.stats.totalGpuMs);
        wall.push_back(f.wallMs);
    }
    timing.frameGpuMs = spread(gpu);
    timing.frameWallMs = spread(wall);
    const std::vector<render::PassStats>& last = frames.back().stats.passes;
    for (std::size_t p = 0; p < last.size(); ++p) {
        std::vector<double> ms;
        for (const TimedFrame& f : frames)
            ms.push_back(p < f.stats.passes.size() ? f.stats.passes[p].gpuMs : 0.0);
        timing.passes.push_back({ last[p].name, last[p].action, spread(ms) });
    }
    return timing;
}

} // namespace

std::vector<PerfConfig> PerfBenchmark::configurations(const PerfOptions& o)
{
    std::vector<PerfConfig> list;
    const auto add = [&list](int width, int height, int grid, int factor, unsigned sweep) {
        for (PerfConfig& c : list)
            if (c.width == width && c.height == height && c.grid == grid && c.triangleFactor == factor) {
                c.sweeps |= sweep;
                return;
            }
        list.push_back({ width, height, grid, factor, sweep });
    };
    for (const auto& [w, h] : o.sizes)
        add(w, h, o.baseGrid, 1, kSizeSweep);
    for (int grid : o.grids)
        add(o.baseWidth, o.baseHeight, grid, 1, kGridSweep);
    for (int factor : o.triangleFactors)
        add(o.baseWidth, o.baseHeight, o.baseGrid, factor, kTriangleSweep);
    std::stable_sort(list.begin(), list.end(), [](const PerfConfig& a, const PerfConfig& b) {
        return std::tuple(a.triangleFactor, a.grid, a.width * a.height)
            < std::tuple(b.triangleFactor, b.grid, b.width * b.height);
    });
    return list;
}

PerfBenchmark::PerfBenchmark(render::Renderer& renderer, const render::Scene& scene,
    const render::RenderSettings& settings, int frames)
    : m_renderer(renderer)
    , m_scene(scene)
    , m_settings(settings)
    , m_frames(std::max(1, frames))
{
}

PerfResult PerfBenchmark::measure(const PerfConfig& config)
{
    if (config.triangleFactor != m_uploadedFactor) {
        const render::Scene scene = config.triangleFactor == 1
            ? m_scene
            : SceneSubdivider::subdivide(m_scene, config.triangleFactor);
        m_renderer.setScene(scene);
        m_uploadedFactor = config.triangleFactor;
        m_uploadedTriangles = scene.triangleCount();
    }
    render::RenderSettings settings = m_settings;
    settings.voxelResolution = config.grid;
    m_renderer.setSettings(settings);
    const render::Camera base = m_scene.camera;
    const int w = config.width, h = config.height;

    PerfResult result;
    result.gridLevels = settings.gridLevels();
    result.config = config;
    result.triangles = m_uploadedTriangles;
    result.frames = m_frames;

    m_renderer.invalidate();
    m_renderer.renderFrame(base, w, h); // warm-up: shaders compiled, targets and voxel textures allocated
    std::vector<TimedFrame> full;
    for (int i = 0; i < m_frames; ++i) {
        m_renderer.invalidate();
        full.push_back(timedFrame(m_renderer, base, w, h));
    }
    result.full = summarize(full);

    render::Camera moving = base;
    orbitCamera(moving, kOrbitStepDeg);
    m_renderer.renderFrame(moving, w, h); // warm-up of the camera-only path
    std::vector<TimedFrame> cameraOnly;
    for (int i = 0; i < m_frames; ++i) {
        orbitCamera(moving, kOrbitStepDeg);
        cameraOnly.push_back(timedFrame(m_renderer, moving, w, h));
    }
    result.cameraOnly = summarize(cameraOnly);
    result.memory = m_renderer.voxelMemory();
    result.occupiedVoxels = cameraOnly.empty() ? 0 : cameraOnly.back().stats.occupiedVoxels;

    // Counted on its own frame, at the full frames' camera: the counting shader is slower and is not timed.
    m_renderer.setConeSampleCounting(true);
    m_renderer.renderFrame(base, w, h);
    result.coneSamples = m_renderer.coneSampleCount();
    m_renderer.setConeSampleCounting(false);
    for (const PassTiming& p : result.full.passes)
        if (p.pass == kConePassName)
            result.coneMs = p.ms.median;

    const int divisor = std::max(1, m_settings.indirectDivisor);
    result.tracedWidth = (w + divisor - 1) / divisor;
    result.tracedHeight = (h + divisor - 1) / divisor;
    const auto key = std::tuple(result.tracedWidth, result.tracedHeight, config.grid);
    auto peak = m_peaks.find(key);
    if (peak == m_peaks.end())
        peak = m_peaks
                   .emplace(key,
                       m_probe.measure(
                           result.tracedWidth, result.tracedHeight, config.grid, std::max(3, m_frames)))
                   .first;
    result.peak = peak->second;
    return result;
}

} // namespace vct::cli
