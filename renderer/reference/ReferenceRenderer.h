#pragma once

#include "image/RadianceImage.h"
#include "reference/CameraRays.h"
#include "reference/PathTracer.h"
#include "reference/ReferenceSettings.h"
#include "reference/ReferenceStats.h"
#include "scene/Camera.h"
#include "scene/Scene.h"

#include <glm/vec3.hpp>

#include <functional>
#include <stop_token>
#include <vector>

namespace vct::render {

/**
 * The ground-truth image of a scene, rendered on the CPU by path tracing (PathTracer on Embree) and framed
 * exactly like the GL renderer's image. Rendering is progressive: each render() call adds samples to the
 * accumulated mean, so a viewer can show it converging. Every sample's random numbers derive from (seed,
 * pixel, sample index) only, so for the same calls the image is bit-identical whatever the thread count.
 *
 * Not thread-safe itself (one render() at a time); render() uses ReferenceSettings::threads worker threads.
 */
class ReferenceRenderer {
public:
    /** Called from worker threads, one call at a time, with the fraction of the current pass done in [0, 1].
     */
    using Progress = std::function<void(double fraction)>;

    /**
     * Copies what it needs from @p scene (Embree builds its hierarchy here). Throws std::runtime_error when
     * Embree fails. @p width and @p height are pixels (values below 1 count as 1).
     */
    ReferenceRenderer(
        const Scene& scene, const Camera& camera, int width, int height, ReferenceSettings settings = {});

    /**
     * Adds @p samplesPerPixel samples to every pixel. Returns false when @p stop was requested before the
     * pass finished; the unfinished pass is then dropped, so every pixel always has samplesPerPixel()
     * samples.
     */
    bool render(int samplesPerPixel, const Progress& progress = {}, std::stop_token stop = {});

    /** The mean radiance so far, W/(m^2 sr), rows top to bottom; black before the first pass. */
    RadianceImage image() const;
    int samplesPerPixel() const { return m_samplesPerPixel; }
    const ReferenceStats& stats() const { return m_stats; }
    /** Triangles the path tracer could not use: zero area or non-finite once transformed to world space. */
    std::size_t droppedTriangles() const { return m_tracer.geometry().droppedTriangles(); }
    const ReferenceSettings& settings() const { return m_settings; }
    int width() const { return m_width; }
    int height() const { return m_height; }

private:
    ReferenceSettings m_settings;
    int m_width;
    int m_height;
    PathTracer m_tracer;
    CameraRays m_cameraRays;
    std::vector<glm::dvec3> m_sum; ///< Radiance summed over all completed passes, per pixel.
    int m_samplesPerPixel = 0;
    ReferenceStats m_stats;
};

} // namespace vct::render
