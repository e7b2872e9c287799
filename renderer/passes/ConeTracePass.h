#pragma once

#include "core/RenderPass.h"
#include "gl/Program.h"
#include "gl/VertexArray.h"

namespace vct::render {

/**
 * Indirect light of two grids of traced pixels, one pixel per indirect-divisor block of the screen for
 * diffuse light and one per specular-divisor block for the specular cone. On each grid a first draw
 * classifies every pixel into stencil classes (common/PixelClass.glsl) and writes the composite's upsampling
 * guide; on the diffuse grid it takes diffuse light from the irradiance cache where it can. Then the diffuse
 * cones run only on the pixels the cache could not serve (all of them without a cache), and the specular cone
 * only on glossy ones. llvmpipe runs all of a fragment shader's code on every pixel it is drawn on, branches
 * or not: the early stencil test is what keeps each shader off the pixels that do not need it.
 */
class ConeTracePass final : public RenderPass {
public:
    const char* name() const override { return "cone trace"; }
    PassDeclaration declare() const override;
    std::vector<TextureSlot> textures(const FrameContext& frame) override;
    PassDecision plan(const FrameContext& frame) const override;
    void execute(FrameContext& frame) override;
    void invalidate() override { }

private:
    gl::VertexArray m_emptyVao;
};

} // namespace vct::render
