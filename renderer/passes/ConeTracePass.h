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
        return {{Resource::GBuffer, Resource::VoxelMips, Resource::VoxelIrradiance}, {Resource::IndirectLight}};
    }
    PassDecision plan(const FrameContext& frame) override;
    void execute(FrameContext& frame) override;
    void invalidate() override {}

private:
    /// Shader variants, [anisotropic mips][COUNT_SAMPLES for vct-bench perf][irradiance cache lookup].
    gl::Program m_programs[2][2][2];
    gl::VertexArray m_emptyVao;
};

} // namespace vct::render
