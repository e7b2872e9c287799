#pragma once

#include "core/RenderPass.h"
#include "gl/Program.h"

namespace vct::render {

/** Rasterises the visible surfaces: position, normal, albedo, specular and emission per pixel. */
class GBufferPass final : public RenderPass {
public:
    const char* name() const override { return "g-buffer"; }
    PassDeclaration declare() const override;
    std::vector<TextureSlot> textures(const FrameContext& frame) override;
    PassDecision plan(const FrameContext&) const override
    {
        return { PassDecision::Action::Run, "per-frame" };
    }
    void execute(FrameContext& frame) override;
    void invalidate() override { }

private:
};

} // namespace vct::render
