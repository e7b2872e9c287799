#pragma once

#include "core/OccupiedCellList.h"
#include "core/RenderPass.h"
#include "core/VoxelRegion.h"
#include "gl/Framebuffer.h"
#include "gl/Program.h"

#include <cstdint>

namespace vct::render {

/**
 * Rasterises the triangles into the voxel grid (dominant-axis projection in a geometry shader, conservative
 * by default) averaging albedo/opacity, normal and emission in place (common/VoxelWords.glsl). Static meshes
 * are voxelized into their own layer when they change; dynamic meshes are redone on top of it whenever they
 * move.
 */
class VoxelizePass final : public RenderPass {
public:
    const char* name() const override { return "voxelize"; }
    PassDeclaration declare() const override { return { {}, { Resource::VoxelMaterials } }; }
    PassDecision plan(const FrameContext& frame) override;
    void execute(FrameContext& frame) override;
    void invalidate() override { m_staticGeometry = m_staticMaterials = m_dynamicVersion = 0; }

private:
    void ensureResources(FrameContext& frame);
    /** Clears the region of the layer about to be voxelized, or copies the static layer there (merging). */
    void prepare(FrameContext& frame, bool mergeStatic, bool intoStaticLayer, const VoxelRegion& region);
    /** Averages the fragments of one layer's meshes into the region, listing each voxel reached into @p
     * touched. */
    void accumulate(FrameContext& frame, bool dynamicMeshes, bool intoStaticLayer, const VoxelRegion& region,
        OccupiedCellList& touched);
    /** Marks the voxels reached as resolved (voxelize/Resolve.comp). */
    void resolve(FrameContext& frame, bool intoStaticLayer, const OccupiedCellList& touched);

    const gl::Program* m_voxelize = nullptr;
    const gl::Program* m_voxelizeEmissive
        = nullptr; ///< the EMISSIVE variant, for meshes whose material emits
    const gl::Program* m_resolve = nullptr;
    OccupiedCellList m_editedVoxels; ///< the static voxels a material edit redid
    gl::Framebuffer m_framebuffer;
    std::uint64_t m_staticGeometry = 0;
    std::uint64_t m_staticMaterials = 0;
    std::uint64_t m_dynamicVersion = 0;
};

} // namespace vct::render
