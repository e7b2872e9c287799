#pragma once

#include "core/RenderPass.h"
#include "gl/Program.h"

#include <array>
#include <cstdint>

namespace vct::render {

/** Depth maps for every shadow-casting light: a cube per point light, an orthographic map per directional one. */
class ShadowMapPass final : public RenderPass {
public:
    const char* name() const override { return "shadow maps"; }
    PassDeclaration declare() const override { return {{}, {Resource::ShadowMaps}}; }
    PassDecision plan(const FrameContext& frame) override;
    void execute(FrameContext& frame) override;
    void invalidate() override { m_key = {}; }

private:
    gl::Program m_program;
    std::array<std::uint64_t, 4> m_key{};
};

} // namespace vct::render
