#pragma once

#include "core/RenderPass.h"
#include "gl/Program.h"
#include "gl/Texture.h"
#include "gl/VertexArray.h"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace vct::render {

/**
 * Sums emission, shadowed direct light and the indirect terms into the frame's linear radiance: one draw per
 * pixel class the scene's meshes have (common/PixelClass.glsl), each with the shader variant for that class
 * and a stencil test that keeps it to its own pixels.
 */
class CompositePass final : public RenderPass {
public:
    const char* name() const override { return "composite"; }
    PassDeclaration declare() const override;
    std::vector<TextureSlot> textures(const FrameContext& frame) override;
    PassDecision plan(const FrameContext&) const override
    {
        return { PassDecision::Action::Run, "per-frame" };
    }
    void execute(FrameContext& frame) override;
    void invalidate() override { }

private:
    /** The compile-time shape of this frame's composite for pixels of @p pixelClass
     * (shaders/composite/Composite.frag). */
    static std::vector<std::string> variantDefines(const FrameContext& frame, std::uint32_t pixelClass);

    /** Fills the glossy lobe's fits (scene/PhongLtcTable) into textures the pipeline made anew. */
    void uploadPhongLtc();

    gl::VertexArray m_emptyVao;
    gl::Texture m_phongLtc; ///< M^-1 per grid point (rgba32f)
    gl::Texture m_phongLtcAlbedo; ///< the lobe's albedo per grid point (r32f)
    std::uint64_t m_phongLtcUploaded = 0; ///< the serial of the texture last filled
};

} // namespace vct::render
