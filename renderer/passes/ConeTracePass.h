#pragma once

#include "core/RenderPass.h"
#include "gl/Program.h"
#include "gl/VertexArray.h"

namespace vct::render {

/** Per-pixel diffuse cones (indirect diffuse and ambient occlusion) and the specular cone for glossy pixels. */
class ConeTracePass final : public RenderPass {
public:
    const char* name() const override { return "cone trace"; }
    PassDeclaration declare() const override
    {
        return {{Resource::GBuffer, Resource::VoxelMips}, {Resource::IndirectLight}};
    }
    PassDecision plan(const FrameContext& frame) override;
    void execute(FrameContext& frame) override;
    void invalidate() override {}

private:
    gl::Program m_program;            ///< box-filtered mips
    gl::Program m_anisotropicProgram; ///< direction-dependent mips
    gl::Program m_countingPrograms[2]; ///< COUNT_SAMPLES variants for vct-bench perf: [0] box mips, [1] anisotropic
    gl::VertexArray m_emptyVao;
};

} // namespace vct::render
