#pragma once

#include "scene/VoxelSceneNeeds.h"

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace vct::render {

/** What to show instead of the final image, for inspecting one term. */
enum class DebugView {
    Final,
    Direct,
    IndirectDiffuse,
    IndirectSpecular,
    AmbientOcclusion,
    Albedo,
    Normal,
    Emission
};

/** How the voxels cover the scene. */
enum class VoxelMode {
    Dense, ///< one grid of voxelResolution^3 fitted around the scene
    /// clipLevels nested grids of voxelResolution^3 each, the coarsest fitted around the scene, each finer
    /// one half as wide and centred on the camera (core/ClipmapLayout): voxelResolution * 2^(clipLevels - 1)
    /// cells per side near the camera for clipLevels times one grid's memory.
    Clipmap,
    /// One grid like Dense whose level-0 textures keep only the bricks of 8^3 voxels geometry can reach
    /// (core/BrickPool): empty space costs a table entry per brick. Needs anisotropic mips (a box mip chain
    /// would live in level 0's texture).
    Sparse,
};

/**
 * Every accuracy and feature setting of a frame. Angles in degrees, distances in metres unless noted.
 * set() parses the `key=value` form used by `vct-render --set` and the project files.
 */
struct RenderSettings {
    int voxelResolution = 128; ///< Grid cells per side, power of two, 8..512 (per level of a clipmap).
    VoxelMode voxelMode = VoxelMode::Dense;
    int clipLevels = 3; ///< Levels of a clipmap (2..6); a dense grid is one.
    /** How many grids the voxels take: clipLevels for a clipmap, else 1. */
    int gridLevels() const { return voxelMode == VoxelMode::Clipmap ? clipLevels : 1; }
    bool conservativeVoxelization = true;
    /// Triangles spanning a few voxels at most are voxelized by a compute shader, one invocation each, the
    /// others by the rasteriser (passes/VoxelizePass): the same voxels, for less time where a scene has many
    /// small triangles. Off is for comparison.
    bool smallTrianglesByCompute = true;
    /// Direction-dependent mips (six chains composited front to back along each axis) instead of one
    /// box-filtered chain: thin walls stay opaque to wide cones, at three lookups per coarse sample. On by
    /// default: with 30-degree cones it is the largest accuracy gain measured (docs/ACCURACY.md, "Recommended
    /// defaults and presets": relative MSE 0.37 -> 0.22 in the Cornell box, 0.26 -> 0.12 in the atrium).
    bool anisotropicMips = true;
    /// Light bounces the voxels carry. 1 = direct light and emission only (the cones add the one bounce seen
    /// per pixel). N >= 2: the voxels iterate N - 1 times L = L_direct + albedo * (light gathered from L)
    /// (VoxelBouncePass), so pixels see N bounces. kConvergedBounces (`bounces=converged`, the default)
    /// iterates until the estimated remaining change is under bounceTolerance: every bounce, as a closed room
    /// needs.
    int bounces = kConvergedBounces;
    static constexpr int kConvergedBounces = 0;
    static constexpr int kMaxBounces = 64; ///< also the most iterations `converged` runs
    /// Voxels per side of one cell of the bounce iteration's gather (2, 4 or 8). Light that has bounced once
    /// already varies slowly, so its cells can be coarser than the irradiance cache's; 8 takes a quarter off
    /// the bounce pass for a 7% worse atrium (docs/ACCURACY.md).
    int bounceCellSize = 4;
    /// Voxels per side of the cells that gather the bounces after the second (2, 4, 8 or 16; at least
    /// bounceCellSize, which is what equal means: every bounce on one grid of cells). A solve gathers the
    /// first-bounce light once on the bounce cells and each later iterate's light above it, which has bounced
    /// twice and varies more slowly still, on these (VoxelBouncePass, docs/DESIGN.md "Higher bounces").
    int higherBounceCellSize = 8;
    /** The bounce cells' side on a grid of @p resolution, and the higher bounces' (both capped at the grid).
     */
    int bounceCellVoxels(int resolution) const;
    int higherBounceCellVoxels(int resolution) const;
    /**
     * Whether a bounce solve on a grid of @p resolution gathers the bounces after the second on coarser
     * cells: they are coarser there and some iteration follows the first.
     */
    bool splitsHigherBounces(int resolution) const;
    /// `bounces=converged` stops when the relative change of the voxels' radiance, and the change still to
    /// come estimated from how fast it shrinks, are both under this, or when adding that change still to come
    /// has an estimated error under this (VoxelBouncePass).
    float bounceTolerance = 0.01f;
    /// Gather the diffuse cones once per surface voxel whenever the voxels' light changes
    /// (VoxelIrradiancePass), and give each pixel a normal-aware trilinear lookup of that instead of its own
    /// cones: a camera move then traces no diffuse cones at all. Pixels with no matching surface voxel nearby
    /// still trace their own. On by default: at 1280x720 on the atrium it makes full frames 10% and
    /// camera-only frames 3.5x faster and the error against the references slightly lower
    /// (docs/BENCHMARKS.md); it leaks more light through walls thinner than a voxel (docs/STABILITY.md), and
    /// small images' full frames cost more.
    bool irradianceCache = true;
    /// Voxels per side of one irradiance-cache cell (1, 2 or 4): one gather per cell that holds a surface.
    int irradianceCellSize = 2;
    int diffuseConeCount = 7; ///< 1..32; 2..9 = one along the normal and the rest tilted 45 degrees.
    /// Full cone angle of each diffuse cone. Wide cones gather more than the light around them where it is
    /// uneven (a point light's hot spot on a ceiling); seven cones of 22 degrees reach the references of all
    /// three scenes, where five of 30 read the point-lit box 12% bright once cones no longer leak through
    /// walls (docs/ACCURACY.md, "Back faces and the grid's faces").
    float diffuseApertureDeg = 22.0f;
    float specularApertureDeg = 15.0f; ///< Narrowest specular cone; glossier lobes are clamped to it.
    float stepFactor = 1.0f; ///< beta: step = cone diameter * beta.
    /// The bounce solve's gathers step this many times as far as the pixels' cones (step = cone diameter *
    /// beta * this). What they gather is looked up between cells and summed over bounces, so fewer, longer
    /// steps do not show: at 2 the solve's gathers take a fifth to a quarter less time and the references
    /// read within a few percent of 1 (docs/DESIGN.md, "The solve's gathers step twice as far").
    float bounceStepScale = 2.0f;
    /// The directional mips leave out voxels whose surface faces the way a cone travels (neither light nor
    /// opacity), so a surface no longer lights and shades the cones leaving it: ceilings beside a light's hot
    /// spot gathered twice the path tracer's light. The price: a one-sided surface with nothing behind it (a
    /// lone quad) is see-through to cones reaching it from behind (docs/ACCURACY.md, "Back faces and the
    /// grid's faces").
    bool dropBackFaces = true;
    /// In space no light can leave (a closed room: core/EnclosedSpace), each diffuse cone's light is scaled
    /// by 1 / its opacity: what the voxels let through there is a wall one voxel thick seen at a coarse
    /// level, not light leaving the scene, and a white furnace read 23% short of E / (1 - rho) without it
    /// (docs/DESIGN.md, "Enclosed space"). Not with a maxDistance set, which leaves out what lies beyond.
    bool enclosedSpace = true;
    /// The enclosed-space map's cells a side at most (a byte each: 2 MiB). On finer grids a cell spans
    /// several voxels, so an opening narrower than two cells (1/64 of the grid) may count as closed.
    static constexpr int kMaxEnclosureResolution = 128;
    float maxDistance = -1.0f; ///< Cone length in metres; negative = the grid's diagonal.
    /// Cone origins start this many voxels along the normal; on grids finer than 128^3 as far as on that grid
    /// (ConeTracingSetup::coneOffsetMetres).
    float coneOffsetVoxels = 1.5f;
    /// Indirect light is traced for one pixel in divisor x divisor (1, 2 or 4) and upsampled with depth- and
    /// normal-aware weights: indirect light varies slowly, and the cones are most of a frame's cost.
    /// Quarter resolution (4) costs no measurable accuracy against half or full (within 1.5%,
    /// docs/ACCURACY.md).
    int indirectDivisor = 4;
    /// The specular cone is traced for one pixel in divisor x divisor (1, 2, 4 or 8) and upsampled the same
    /// way. Specular cones are never narrower than specularApertureDeg, so what they see varies slowly over
    /// the screen except across edges, which the upsampling keeps; 8 halves the cone pass of the atrium's
    /// glossy floor for no measurable error (docs/ACCURACY.md).
    int specularDivisor = 8;
    /// The area lights' shadow cones are traced for one pixel in divisor x divisor (1, 2 or 4) and the share
    /// of light they let through is upsampled; the unshadowed irradiance stays exact per pixel. 2 keeps a
    /// blocker's penumbra within 10% of the path tracer's at a quarter of the cones
    /// (tests/gl/tst_AreaLights).
    int areaShadowDivisor = 2;
    bool direct = true;
    bool indirectDiffuse = true;
    bool indirectSpecular = true;
    bool ambientOcclusion = true; ///< Computed from the diffuse cones; shown by view=ao.
    bool emission = true;
    int shadowMapSize = 1024; ///< Texels per cube face / directional map side.
    /// The g-buffer and shadow maps draw only the triangle clusters a view can see, nearest first, and leave
    /// out the back faces of closed meshes seen from outside (core/GpuScene, core/ClosedSurface). The image
    /// is the same either way; off is for comparison.
    bool viewCulling = true;
    float exposure = 1.0f; ///< Multiplier applied before the filmic curve, 8-bit output only.
    DebugView view = DebugView::Final;
    /// Voxel textures may take at most this many MiB; validate() refuses a grid that needs more, instead of
    /// letting the GL fail (or llvmpipe page for minutes). 512^3 needs 12.1 GiB: raise this where the GPU has
    /// it.
    int voxelBudgetMiB = 4096;

    /** Applies one `key=value`; returns an empty string or a message saying what is wrong. */
    std::string set(const std::string& key, const std::string& value);
    /**
     * Applies several `key=value` together and validates the result once, so that their order does not
     * matter (`voxel_res=512` then `voxel_mode=sparse` is as valid as the other way round); nothing is
     * applied if any is wrong.
     */
    std::string setAll(const std::vector<std::pair<std::string, std::string>>& assignments);
    /** Checks ranges together; returns an empty string or the first problem. */
    std::string validate() const;
    /**
     * Bytes of every voxel texture the renderer allocates for this grid: albedo/normal/emission, the radiance
     * mip chain and, with anisotropic mips, six directional chains (the bounced volume's when bounces are
     * carried by the voxels), the opacity chain for a scene with area lights, and the bounce and cache cells.
     * Equals Renderer::voxelBytes() once a frame has been rendered (tested). The budget check counts what the
     * scene may add: the most the grid can need.
     */
    std::uint64_t voxelMemoryBytes(VoxelSceneNeeds scene = {}) const;
    /** (key, current value, meaning) for --help and --stats. */
    std::vector<std::vector<std::string>> describe() const;
};

const char* debugViewName(DebugView view);

} // namespace vct::render
