#pragma once

#include "core/OccupiedCellList.h"
#include "core/RenderPass.h"
#include "gl/Program.h"
#include "passes/VoxelMipBuilder.h"

#include <cstdint>
#include <tuple>

namespace vct::render {

/**
 * With bounces = 2: every surface voxel gathers a second bounce through the diffuse cones from the
 * first-bounce mips, into a volume of its own (VoxelVolume::bounced) that is then filtered like the first;
 * per-pixel cones trace that volume. Runs only when the first-bounce radiance or a gather parameter
 * changed: a camera move reuses it, and with one bounce the pass is skipped and its volume released.
 */
class VoxelBouncePass final : public RenderPass {
public:
    const char* name() const override { return "second bounce"; }
    PassDeclaration declare() const override { return {{Resource::VoxelMaterials, Resource::VoxelMips}, {Resource::VoxelMips}}; }
    PassDecision plan(const FrameContext& frame) override;
    void execute(FrameContext& frame) override;
    void invalidate() override { m_radianceVersion = 0; }

private:
    /** Everything the gather's result depends on besides the radiance itself. */
    using GatherKey = std::tuple<bool, int, float, float, float, float, int>;
    static GatherKey keyOf(const FrameContext& frame);
    gl::Program m_program;
    gl::Program m_anisotropicProgram;
    VoxelMipBuilder m_builder;
    std::uint64_t m_radianceVersion = 0;
    GatherKey m_key{};
};

} // namespace vct::render
