#pragma once

#include "core/GpuScene.h"
#include "core/OccupiedCellList.h"
#include "core/RenderPass.h"
#include "core/VoxelGridFrame.h"
#include "core/VoxelRegion.h"
#include "gl/Framebuffer.h"
#include "gl/Program.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace vct::render {

/**
 * Rasterises the triangles into the voxel grid (dominant-axis projection in a geometry shader, conservative
 * by default) averaging albedo/opacity, normal and emission in place (common/VoxelWords.glsl). A change of
 * the static meshes rebuilds the grid; a moving object or a material edit rebuilds the region around it; a
 * grid that stepped with the camera moves the voxels it keeps and voxelizes the slabs it newly covers.
 */
class VoxelizePass final : public RenderPass {
public:
    const char* name() const override { return "voxelize"; }
    PassDeclaration declare() const override;
    std::vector<TextureSlot> textures(const FrameContext& frame) override;
    PassDecision plan(const FrameContext& frame) const override;
    void execute(FrameContext& frame) override;
    bool redoesWholeGrid(const FrameContext& frame) const override;
    void invalidate() override { m_staticGeometry = m_staticMaterials = m_dynamicVersion = 0; }

private:
    void ensureResources(FrameContext& frame);
    /** voxel_mode=sparse: allocates the bricks the meshes reach (all after a static change, the dynamic
     * ones' new bricks after a move) and sizes the pool. */
    void updateBricks(const FrameContext& frame);
    /** Throws, naming the figures, when a sparse grid's pools of @p pool bricks would take the voxel
     * textures over budget. */
    static void refuseOverBudget(const FrameContext& frame, const glm::ivec3& pool);
    /** How many voxels the grid stepped by since the last rewrite when that is all that changed (a clip
     * level following the camera), or nothing. */
    std::optional<glm::ivec3> gridStep(const FrameContext& frame) const;
    /** Moves the voxels and the static list with a grid that stepped; returns the slabs it newly covers. */
    std::vector<VoxelRegion> moveWithGrid(FrameContext& frame, const glm::ivec3& step);
    /** Empties the region's albedo, normal and emission, which the voxelizer then averages into. */
    void clear(FrameContext& frame, const VoxelRegion& region);
    /** Averages the fragments of one layer's meshes into the region, listing each voxel reached first into
     * @p touched, emptied first unless @p appendToTouched. */
    void accumulate(FrameContext& frame, MeshFilter layer, const VoxelRegion& region,
        OccupiedCellList& touched, bool appendToTouched = false);
    /** Marks the voxels reached as resolved (voxelize/Resolve.comp). */
    void resolve(FrameContext& frame, const OccupiedCellList& touched);

    struct VoxelizerVariant {
        bool emissive; ///< for meshes whose material emits
        bool textured; ///< for meshes whose material has an albedo texture
        bool conservative; ///< triangles enlarged by the pixel square in the shader
        /// The compute shader for triangles of a few pixels, which lists the others for the rasteriser
        /// (voxelize/VoxelizeSmall.comp), instead of the geometry shader and the rasteriser.
        bool smallByCompute;
    };
    /** The voxelizer's program for a variant, into a grid with an emission volume or without. */
    static const gl::Program& voxelizer(FrameContext& frame, const VoxelizerVariant& variant);
    /** Whether the voxelization's settings differ from the last full rebuild's. */
    bool modeChanged(const FrameContext& frame) const;

    /// Storage buffers of the mesh's vertices and indices for the compute path, then of the triangles it
    /// lists (the occupied list takes 0 and 1).
    static constexpr GLuint kVertexBinding = 2;
    static constexpr GLuint kTriangleGroupSize = 64; ///< VoxelizeSmall.comp's local_size_x

    const gl::Program* m_resolve = nullptr;
    OccupiedCellList m_regionStaticVoxels; ///< the static voxels a partial update redid
    OccupiedCellList m_movedStaticVoxels; ///< the static list before a step, read while it is moved
    gl::Framebuffer m_framebuffer;
    std::uint64_t m_staticGeometry = 0;
    std::uint64_t m_staticMaterials = 0;
    std::uint64_t m_dynamicVersion = 0;
    std::uint64_t m_albedoSerial = 0; ///< the albedo texture m_framebuffer was made for
    bool m_conservative = false; ///< the voxelization mode of the last full rebuild
    bool m_smallByCompute = false; ///< and whether its small triangles went through the compute path
    ListedTriangles m_largeTriangles; ///< what the compute path left to the rasteriser, per draw
    /// Where the grid was: a clip level follows the camera (core/ClipmapLayout) and is redone when it moves.
    VoxelGridFrame m_grid;
    VoxelGridFrame m_brickGrid; ///< the grid the bricks were allocated for
    std::uint64_t m_brickStatic = 0;
    std::uint64_t m_brickDynamic = 0;
    int m_brickBudget = 0; ///< voxel_budget_mb the pool was last checked against
    float m_brickReach = 0.0f;
};

} // namespace vct::render
