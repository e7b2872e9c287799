#pragma once

#include "core/RenderPass.h"
#include "gl/Program.h"
#include "gl/VertexArray.h"

namespace vct::render {

/** Sums emission, shadowed direct light and the indirect terms into the frame's linear radiance. */
class CompositePass final : public RenderPass {
public:
    const char* name() const override { return "composite"; }
    PassDeclaration declare() const override
    {
        return {{Resource::GBuffer, Resource::IndirectLight, Resource::ShadowMaps}, {Resource::FinalImage}};
    }
    PassDecision plan(const FrameContext&) override { return {PassDecision::Action::Run, "per-frame"}; }
    void execute(FrameContext& frame) override;
    void invalidate() override {}

private:
    gl::Program m_program;
    gl::VertexArray m_emptyVao;
};

} // namespace vct::render
