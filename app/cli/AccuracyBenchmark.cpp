#include "cli/AccuracyBenchmark.h"

#include "Renderer.h"
#include "cli/Statistics.h"
#include "imageio/ImageMetrics.h"
#include "reference/ReferenceRenderer.h"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <fstream>
#include <string_view>

namespace vct::cli {

namespace {

constexpr std::string_view kConePassName = "cone trace";

double elapsedMs(std::chrono::steady_clock::time_point since)
{
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - since).count();
}

/** CPU time of every thread of this process so far, ms. */
double processCpuMs()
{
    timespec t {};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

/** "model name" of the first CPU in /proc/cpuinfo, or "CPU" where there is none (not Linux). */
std::string cpuModel()
{
    std::ifstream cpuinfo("/proc/cpuinfo");
    for (std::string line; std::getline(cpuinfo, line);)
        if (line.rfind("model name", 0) == 0)
            if (const std::size_t colon = line.find(':');
                colon != std::string::npos && colon + 2 <= line.size())
                return line.substr(colon + 2);
    return "CPU";
}

} // namespace

AccuracyBenchmark::AccuracyBenchmark(const render::RadianceImage& reference)
    : m_reference(reference)
{
}

AccuracyRow AccuracyBenchmark::measureVct(render::Renderer& renderer, const render::Camera& camera,
    const SweepPoint& point, int frames, std::vector<std::string>& warnings) const
{
    const int width = m_reference.width, height = m_reference.height;
    renderer.setSettings(point.settings);
    renderer.invalidate();
    renderer.renderFrame(camera, width, height); // warm-up: shaders compiled, textures allocated
    std::vector<double> totals, cones, walls, cpus, cameraOnly;
    for (int i = 0; i < frames; ++i) {
        renderer.invalidate();
        const auto start = std::chrono::steady_clock::now();
        const double cpuStart = processCpuMs();
        const render::FrameStats stats = renderer.renderFrame(camera, width, height);
        // renderFrame reads its timer queries back, so the frame has finished when it returns.
        walls.push_back(elapsedMs(start));
        cpus.push_back(processCpuMs() - cpuStart);
        totals.push_back(stats.totalGpuMs);
        double cone = 0.0;
        for (const render::PassStats& pass : stats.passes)
            if (pass.name == kConePassName)
                cone += pass.gpuMs;
        cones.push_back(cone);
    }
    const render::RadianceImage image = renderer.readFrame();
    // Nothing changes between these frames: the plan reuses shadow maps, voxels and mips, as when only the
    // camera moves, and re-runs the camera-dependent passes.
    for (int i = 0; i < frames; ++i)
        cameraOnly.push_back(renderer.renderFrame(camera, width, height).totalGpuMs);

    AccuracyRow row;
    row.kind = "vct";
    row.label = point.label;
    row.setting = point.setting;
    row.value = point.value;
    row.gpuMs = median(totals);
    row.coneMs = median(cones);
    row.cameraMs = median(cameraOnly);
    row.wallMs = median(walls);
    row.cpuMs = median(cpus);
    row.width = width;
    row.height = height;
    if (const std::size_t bad = io::ImageMetrics::nonFiniteCount(image))
        warnings.push_back(
            point.label + ": " + std::to_string(bad) + " non-finite channel values in the image");
    for (const std::string& message : renderer.takeGlErrors())
        warnings.push_back(point.label + ": GL: " + message);
    measureError(image, row);
    return row;
}

AccuracyRow AccuracyBenchmark::measurePathTracer(const render::Scene& scene, const render::Camera& camera,
    int spp, const render::ReferenceSettings& settings, std::vector<std::string>& warnings) const
{
    render::ReferenceRenderer tracer(scene, camera, m_reference.width, m_reference.height, settings);
    const double cpuStart = processCpuMs();
    tracer.render(spp);
    const double cpuMs = processCpuMs() - cpuStart;
    const render::RadianceImage image = tracer.image();
    AccuracyRow row;
    row.kind = "reference";
    row.label = std::to_string(spp) + " spp";
    row.setting = "spp";
    row.value = std::to_string(spp);
    row.spp = spp;
    row.wallMs = tracer.stats().seconds * 1e3;
    row.cpuMs = cpuMs;
    row.width = m_reference.width;
    row.height = m_reference.height;
    const int threads = std::max(1, settings.threads);
    row.machine = cpuModel() + ", " + std::to_string(threads) + (threads == 1 ? " thread" : " threads");
    if (tracer.stats().nonFiniteSamples)
        warnings.push_back(
            row.label + ": " + std::to_string(tracer.stats().nonFiniteSamples) + " non-finite paths dropped");
    measureError(image, row);
    return row;
}

void AccuracyBenchmark::measureError(const render::RadianceImage& image, AccuracyRow& row) const
{
    row.relMse = io::ImageMetrics::relativeMse(image, m_reference);
    row.rmse = io::ImageMetrics::rmse(image, m_reference);
    row.psnr = io::ImageMetrics::psnr(image, m_reference, 1.0);
    row.ssim = io::ImageMetrics::ssim(image, m_reference);
    const double referenceMean = io::ImageMetrics::meanLuminance(m_reference);
    row.meanRatio
        = referenceMean > 0.0 ? io::ImageMetrics::meanLuminance(image) / referenceMean : AccuracyRow::kNone;
}

} // namespace vct::cli
