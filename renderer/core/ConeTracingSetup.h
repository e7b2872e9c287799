#pragma once

#include "core/VoxelGridFrame.h"
#include "gl/Program.h"
#include "gl/Texture.h"

#include <string>
#include <vector>

namespace vct::render {

struct FrameContext;

/**
 * Sets what common/ConeTracing.glsl reads (grid placement, step and distance limits, the diffuse cone set)
 * and binds the volume the cones trace through, so the per-pixel cone pass and the per-voxel bounce gather
 * trace with the same parameters: the bounced volume when there is one (VoxelVolume::coneRadiance).
 */
class ConeTracingSetup {
public:
    static void apply(const gl::Program& program, const FrameContext& frame, bool anisotropic);
    /** The shader defines apply() needs: CLIP_LEVELS for a clipmap's coarser levels (core/ClipLevelPass). */
    static void addDefines(std::vector<std::string>& defines, const FrameContext& frame);
    /**
     * How far along the normal cones (and the area lights' shadow cones) start, metres: cone_offset voxels,
     * and on a grid finer than kOffsetGrid^3 as far as on that one. On finer grids a start a fixed number of
     * voxels out lets the first, finest samples find the surface being left: the reference Cornell boxes read
     * 10% too bright at 256^3 (docs/ACCURACY.md, "Finer grids").
     */
    static float coneOffsetMetres(const FrameContext& frame);
    /** The same for cones starting in @p grid (a clipmap's level). */
    static float coneOffsetMetres(const FrameContext& frame, const VoxelGridFrame& grid);
    static constexpr int kOffsetGrid = 128;
    /**
     * What common/CacheBand.glsl reads: in a clipmap, the finest level, the scene's grid and the band along
     * the finest level's moving faces where pixels trace their own cones; no band for a dense grid.
     */
    static void applyCacheBand(const gl::Program& program, const FrameContext& frame);
    /**
     * A clipmap's coarser levels as the shaders take them, finest first: per level its corner and side
     * (@p boxes) and its voxel, top mip level and cone offset in metres (@p grids). Empty for a dense grid.
     */
    static void clipLevelFrames(
        const FrameContext& frame, std::vector<glm::vec4>& boxes, std::vector<glm::vec4>& grids);
    /**
     * apply() and what irradiance/GatherCells.comp reads besides: cells of @p cellSize^3 voxels, written to
     * @p front, @p back and @p normals (the irradiance cache's layout), ambient visibility only with @p ao.
     * Shared by the irradiance cache and the bounce iteration, which gather cells the same way.
     */
    static void applyCellGather(const gl::Program& program, const FrameContext& frame, bool anisotropic,
        int cellSize, bool ao, const gl::Texture& front, const gl::Texture& back, const gl::Texture& normals);
    /**
     * Binds @p sampler on every unit apply() binds a volume cones read to, which then filter as it says;
     * 0 gives them back their textures' own filtering.
     */
    static void bindVolumeSampler(const FrameContext& frame, GLuint sampler);
};

} // namespace vct::render
