#pragma once

#include "core/RenderPass.h"
#include "gl/Program.h"
#include "gl/VertexArray.h"

namespace vct::render {

/**
 * The area lights' shadows on a grid of their own (RenderSettings::areaShadowDivisor,
 * ScreenTargets::areaShadow): for each traced pixel, the share of its unshadowed area-light irradiance its
 * shadow cones let through, with the pixel's tangent plane as the upsampling guide. The composite then
 * multiplies each full-resolution pixel's exact unshadowed irradiance by the upsampled share. The shadow
 * cones are most of an area-lit pixel's cost and what they give varies slowly (a cone-traced penumbra).
 * Skipped when the scene has no area lights.
 */
class AreaLightPass final : public RenderPass {
public:
    const char* name() const override { return "area-light shadows"; }
    PassDeclaration declare() const override;
    std::vector<TextureSlot> textures(const FrameContext& frame) override;
    PassDecision plan(const FrameContext& frame) const override;
    void execute(FrameContext& frame) override;
    void invalidate() override { }

private:
    gl::VertexArray m_emptyVao;
};

} // namespace vct::render
