#include "reference/ReferenceRenderer.h"

#include "reference/Pcg32.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <mutex>
#include <thread>

namespace vct::render {

namespace {

/** SplitMix64's finaliser: neighbouring inputs give unrelated outputs. */
std::uint64_t mix(std::uint64_t x)
{
    x += 0x9e3779b97f4a7c15ull;
    x = (x ^ (x >> 30u)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27u)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31u);
}

bool isFinite(const glm::vec3& v)
{
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

/**
 * The scene, camera and lights moved so that the scene's bounds are centred on the origin, and scaled to a
 * diagonal of one. Radiance does not change with either (point intensities scale with the square of the
 * length, so irradiance stays), but the ray offsets that keep a path off its own surface (RayOffset) are
 * counted in units of the last place away from the origin and in a fixed step near it: a room 1e5 m out
 * started its rays two metres off the walls and came out 40% darker, and one scaled to 1e-4 m leaked light
 * through its corners (its walls 15 ulps-steps of 1.5e-5 apart). A corner and the centre of similar magnitude
 * subtract exactly.
 */
struct LocalFrame {
    glm::vec3 origin { 0.0f };
    float scale = 1.0f;
    Aabb bounds; ///< the scene's bounds in the frame

    explicit LocalFrame(const Scene& scene)
    {
        const Aabb world = scene.bounds();
        if (world.isEmpty())
            return;
        const float diagonal = glm::length(world.size());
        origin = isFinite(world.center()) ? world.center() : glm::vec3(0.0f);
        scale = diagonal > 0.0f && std::isfinite(diagonal) ? 1.0f / diagonal : 1.0f;
        bounds = Aabb { toLocal(world.min), toLocal(world.max) };
    }
    glm::vec3 toLocal(const glm::vec3& p) const { return (p - origin) * scale; }

    Scene toLocal(const Scene& scene) const
    {
        Scene local = scene;
        // The translation moves first: a far-out vertex of an untransformed model then meets its offset in
        // one addition of similar magnitudes, which is exact; the uniform scale keeps every normal's
        // direction.
        for (Mesh& mesh : local.meshes) {
            mesh.transform[3] -= glm::vec4(origin, 0.0f);
            mesh.transform = glm::mat4(glm::mat3(scale)) * mesh.transform;
        }
        for (PointLight& light : local.pointLights) {
            light.position = toLocal(light.position);
            light.intensity *= scale * scale;
            light.radius *= scale;
        }
        // Radiance does not change with scale; the shape does.
        for (SurfaceLight& light : local.surfaceLights) {
            light.centre = toLocal(light.centre);
            light.width *= scale;
            light.height *= scale;
        }
        return local;
    }

    Camera toLocal(const Camera& camera) const
    {
        Camera local = camera;
        local.position = toLocal(camera.position);
        local.lookAt = toLocal(camera.lookAt);
        local.nearPlane *= scale;
        return local;
    }
};

CameraRays localRays(const Scene& scene, const Camera& camera, int width, int height)
{
    const LocalFrame frame(scene);
    return CameraRays(frame.toLocal(camera), width, height, frame.bounds);
}

} // namespace

ReferenceRenderer::ReferenceRenderer(
    const Scene& scene, const Camera& camera, int width, int height, ReferenceSettings settings)
    : m_settings(settings)
    , m_width(std::max(1, width))
    , m_height(std::max(1, height))
    , m_tracer(LocalFrame(scene).toLocal(scene), settings)
    , m_cameraRays(localRays(scene, camera, m_width, m_height))
    , m_sum(std::size_t(m_width) * std::size_t(m_height), glm::dvec3(0.0))
{
}

bool ReferenceRenderer::render(int samplesPerPixel, const Progress& progress, std::stop_token stop)
{
    if (samplesPerPixel <= 0)
        return true;
    const auto start = std::chrono::steady_clock::now();
    const int tileSize = std::max(1, m_settings.tileSize);
    const int tilesX = (m_width + tileSize - 1) / tileSize, tilesY = (m_height + tileSize - 1) / tileSize;
    const int tileCount = tilesX * tilesY;
    const int threadCount = std::clamp(m_settings.threads, 1, tileCount);
    const int firstSample = m_samplesPerPixel;

    std::vector<glm::dvec3> passSum(m_sum.size(), glm::dvec3(0.0));
    std::atomic<int> nextTile { 0 };
    std::atomic<int> tilesFinished { 0 };
    std::atomic<std::uint64_t> rays { 0 }, nonFinite { 0 };
    std::mutex progressMutex;
    int tilesDone = 0;
    std::exception_ptr failure;

    auto work = [&] {
        try {
            std::uint64_t threadRays = 0, threadNonFinite = 0;
            for (int tile = nextTile++; tile < tileCount && !stop.stop_requested(); tile = nextTile++) {
                const int x0 = (tile % tilesX) * tileSize, y0 = (tile / tilesX) * tileSize;
                const int x1 = std::min(x0 + tileSize, m_width), y1 = std::min(y0 + tileSize, m_height);
                int y = y0;
                for (; y < y1 && !stop.stop_requested(); ++y)
                    for (int x = x0; x < x1; ++x) {
                        const std::uint64_t pixel
                            = std::uint64_t(y) * std::uint64_t(m_width) + std::uint64_t(x);
                        // Samples are summed in index order, so the result is independent of scheduling.
                        glm::dvec3 sum(0.0);
                        for (int s = firstSample; s < firstSample + samplesPerPixel; ++s) {
                            Pcg32 random(mix(mix(m_settings.seed ^ mix(pixel)) + std::uint64_t(s)), pixel);
                            const glm::vec2 jitter(random.nextFloat(), random.nextFloat());
                            const glm::vec3 radiance
                                = m_tracer.radiance(m_cameraRays.ray(x, y, jitter), random, threadRays);
                            if (isFinite(radiance))
                                sum += glm::dvec3(radiance);
                            else
                                ++threadNonFinite;
                        }
                        passSum[pixel] = sum;
                    }
                if (y < y1)
                    break; // stopped part-way
                ++tilesFinished;
                if (progress) {
                    const std::lock_guard lock(progressMutex);
                    progress(double(++tilesDone) / double(tileCount));
                }
            }
            rays += threadRays;
            nonFinite += threadNonFinite;
        } catch (...) {
            const std::lock_guard lock(progressMutex);
            if (!failure)
                failure = std::current_exception();
        }
    };
    std::vector<std::thread> workers;
    for (int i = 1; i < threadCount; ++i)
        workers.emplace_back(work);
    work(); // the calling thread is a worker too
    for (std::thread& worker : workers)
        worker.join();
    if (failure)
        std::rethrow_exception(failure);

    m_stats.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    m_stats.rays += rays;
    if (tilesFinished < tileCount)
        return false;
    for (std::size_t i = 0; i < m_sum.size(); ++i)
        m_sum[i] += passSum[i];
    m_samplesPerPixel += samplesPerPixel;
    m_stats.samples += std::uint64_t(samplesPerPixel) * m_sum.size();
    m_stats.nonFiniteSamples += nonFinite;
    return true;
}

RadianceImage ReferenceRenderer::image() const
{
    RadianceImage result(m_width, m_height);
    if (m_samplesPerPixel == 0)
        return result;
    // Non-finite samples are dropped but still counted in the divisor: dropping is a (rare) bias towards
    // zero, whereas dividing by fewer would make the result depend on which samples failed.
    const double scale = 1.0 / double(m_samplesPerPixel);
    for (std::size_t i = 0; i < m_sum.size(); ++i)
        result.pixels[i] = glm::vec3(m_sum[i] * scale);
    return result;
}

} // namespace vct::render
