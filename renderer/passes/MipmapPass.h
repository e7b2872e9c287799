#pragma once

#include "core/RenderPass.h"
#include "core/VoxelMipBuilder.h"

#include <cstdint>

namespace vct::render {

/**
 * Filters the radiance volume into the levels cones read: the six direction-dependent chains with anisotropic
 * mips, otherwise levels 1..N of the volume itself by 2x2x2 box filtering, each level from the one below.
 * When bounces are carried by the voxels, cones trace the bounced volume instead, and the radiance volume
 * keeps level 0 alone.
 */
class MipmapPass final : public RenderPass {
public:
    const char* name() const override { return "mipmaps"; }
    PassDeclaration declare() const override;
    std::vector<TextureSlot> textures(const FrameContext& frame) override;
    PassDecision plan(const FrameContext& frame) const override;
    void execute(FrameContext& frame) override;
    void invalidate() override { m_radianceVersion = 0; }

private:
    VoxelMipBuilder m_builder;
    std::uint64_t m_radianceVersion = 0;
    bool m_dropBackFaces = false;
    bool m_anisotropic = false;
    bool m_levelZeroOnly = false; ///< the bounce volume is in use: radiance keeps level 0 only
};

} // namespace vct::render
