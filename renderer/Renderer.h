#pragma once

#include "core/BrickOccupancy.h"
#include "core/FrameStats.h"
#include "core/NonFiniteCount.h"
#include "core/VoxelChannel.h"
#include "core/VoxelTextureMemory.h"
#include "gl/GlLoader.h"
#include "image/RadianceImage.h"
#include "scene/RenderSettings.h"
#include "scene/Scene.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace vct::render {

class ShaderLibrary;

/**
 * The voxel cone tracing renderer: owns every GL object and runs the pass pipeline. All calls need the same
 * GL 4.5 context current. The public API uses std and GLM types only, so Qt widgets, EGL and OSMesa hosts
 * drive it alike.
 */
class Renderer {
public:
    /** Loads GL through getProcAddress (glad); throws std::runtime_error when 4.5 core or a needed extension
     * is missing. */
    explicit Renderer(gl::ProcAddressFunction getProcAddress);
    /** For tests and hot reload: shaders from a custom library. */
    Renderer(gl::ProcAddressFunction getProcAddress, std::unique_ptr<ShaderLibrary> shaders);
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    /** Uploads a whole new scene; the grid is refitted to its bounds. */
    void setScene(const Scene& scene);
    /**
     * Fits the voxel grid around `bounds` instead of the scene's bounds (an empty box restores the default).
     * For a region of interest in a large scene, and for tests that need voxels at known places.
     */
    void setGridBounds(const Aabb& bounds);
    /** Applies settings; only what they affect is rebuilt. Throws std::invalid_argument if invalid. */
    void setSettings(const RenderSettings& settings);
    const RenderSettings& settings() const { return m_settings; }
    /** Moves one mesh. Moving a dynamic mesh re-voxelizes dynamic meshes only. */
    void setMeshTransform(std::size_t mesh, const glm::mat4& transform);
    /**
     * Shows or hides one mesh without uploading the scene again: the voxels and shadow maps are redone (the
     * geometry and with it the grid's bounds change), the buffers and textures stay.
     */
    void setMeshVisible(std::size_t mesh, bool visible);
    /** How many times setScene() has uploaded a scene, for tests of what an edit reuses. */
    std::uint64_t sceneUploads() const;
    void setMaterial(std::size_t index, const Material& material);
    /** Replaces the lights; lights equal to the current ones (a renamed light) change nothing. */
    void setLights(const std::vector<PointLight>& points, const std::vector<DirectionalLight>& directionals,
        const std::vector<SurfaceLight>& surfaces);

    /** Forgets every cached pass output: the next frame runs every pass (benchmarks, forced-full
     * comparisons). */
    void invalidate();
    /**
     * Rebuilds every shader program with the text of the shaders/ folder `folder` (a file it lacks keeps its
     * built-in text: the editor's F5) and runs every pass on the next frame. A program that fails to compile
     * keeps its last good build; the failures come back, one message each (program, file, driver log).
     */
    std::vector<std::string> reloadShaders(const std::string& folder);
    /** Renders one frame into the internal HDR target. */
    FrameStats renderFrame(const Camera& camera, int width, int height);
    /**
     * Tone-maps the last frame (exposure, filmic curve, sRGB) into the rectangle x, y, width, height (GL
     * window coordinates, origin bottom left) of a framebuffer: 0 or a widget's framebuffer object.
     */
    void present(unsigned framebuffer, int x, int y, int width, int height, float exposure);
    /**
     * The non-empty voxels of a mip level in a channel of grid @p grid (gridCount(); 0 = the finest);
     * rebuilt only when they or the request change.
     */
    const VoxelListing& listVoxels(int level, VoxelChannel channel, int grid = 0);
    /**
     * Draws listVoxels(level, channel, grid) as instanced cubes, seen by camera, into a rectangle of a
     * framebuffer (cleared first); returns the number of cubes drawn.
     */
    std::size_t drawVoxelCubes(const Camera& camera, int level, VoxelChannel channel, unsigned framebuffer,
        int x, int y, int width, int height, float exposure, int grid = 0);
    /** NaN/Inf texel counts of every float render target and voxel level (a readback per resource). */
    std::vector<NonFiniteCount> countNonFinite();
    /**
     * With @p previousFrame, renderFrame() reports the GPU times of the frame before and never waits for the
     * one it issued (an interactive host); by default it waits for exact figures of the frame it rendered.
     */
    void setTimesFromPreviousFrame(bool previousFrame);
    /**
     * With bounces=converged: at most @p iterations bounce iterations per frame, each new solve starting from
     * the last (an interactive host renders frames until FrameStats::lightConverged); 0 (the default) runs
     * them all in the frame, from the first-bounce light, so a frame depends on its inputs alone.
     */
    void setBounceIterationsPerFrame(int iterations);
    /**
     * Adds the phases of the passes that time them (the bounce solve's gathers, reinjections and filterings)
     * to FrameStats::passes, after every pass's own line ("bounces: reinjections"; each a part of its pass's
     * time). Reading them waits for the GPU to finish the pass: off (the default) for an interactive view.
     */
    void setPhaseTimes(bool on);
    /**
     * Splits a full rebuild over frames: voxelizing the whole grid and injecting its light run in frames of
     * their own, while the last complete image is shown (FrameStats::deferred; an interactive host renders
     * again until it is false). Off (the default): every frame is a complete image.
     */
    void setStagedRebuilds(bool staged);
    /** Mip levels of the radiance volume (0 before the first frame); every grid of a clipmap has as many. */
    int voxelLevelCount() const;
    /**
     * Grids the voxels are held in: a clipmap's levels, 0 the finest (around the camera) and the last the
     * scene's grid; 1 for a dense grid.
     */
    int gridCount() const;
    /** The last frame's linear radiance, read back from the GPU (top row first). */
    RadianceImage readFrame() const;
    /**
     * Reads one level of a voxel channel for tests and the inspector: "albedo", "normal", "emission",
     * "radiance", "bounced", or with anisotropic mips "radiance+x", "radiance-x", ... "radiance-z" (levels
     * 1..N), and "bounced+x" ... "bounced-z" (the bounced volume's chains, which cones trace when the voxels
     * carry bounces); the bounce solve's cells ("bounce cells", "bounce cells, back faces", "bounce cell
     * normals", a texel per cell); of grid @p grid (gridCount()).
     */
    std::vector<float> readVoxels(const std::string& channel, int level, int& size, int grid = 0) const;

    const Scene& scene() const;
    /** Grid placement in use (valid after the first frame): a clipmap's finest level, which follows the
     * camera. */
    float voxelSize() const;
    int voxelResolution() const;
    glm::vec3 gridOrigin() const;
    std::size_t voxelBytes() const;
    /** Every 3D texture of the voxel grid with its bytes per mip level (empty before the first frame). */
    std::vector<VoxelTextureMemory> voxelMemory() const;
    /**
     * Per grid (gridCount()), the bricks of @p brickSize^3 voxels that hold a surface: what sparse storage
     * would allocate. Reads the grids' occupied-voxel lists back; for statistics (issue 19's plan).
     */
    std::vector<BrickOccupancy> brickOccupancy(int brickSize) const;
    /**
     * Benchmarks only: while on, the cone pass runs a variant that counts its 3D texture fetches. It is
     * slower than the normal pass, so do not time frames drawn with it.
     */
    void setConeSampleCounting(bool enabled);
    /** Fetches the cone pass made in the last frame while counting was on; 0 otherwise or if it did not run.
     */
    std::uint64_t coneSampleCount() const;
    /** GL errors and KHR_debug messages since the last call. */
    std::vector<std::string> takeGlErrors();

private:
    /** Hands the timing and staging modes to the pipeline and the clip levels' own. */
    void applyPipelineModes();
    struct State;
    std::unique_ptr<State> m_state;
    RenderSettings m_settings;
};

} // namespace vct::render
