#include "passes/CompositePass.h"

#include "core/FrameContext.h"
#include "core/FrameRules.h"
#include "core/LightUniforms.h"

namespace vct::render {

void CompositePass::execute(FrameContext& frame)
{
    if (!m_program) {
        m_program = frame.shaders.build({"composite", {"common/FullScreen.vert", "composite/Composite.frag"}, {}});
        m_emptyVao = gl::VertexArray::create();
    }
    const RenderSettings& settings = frame.settings;
    ScreenTargets& s = frame.screen;
    m_program.use();
    applyLightUniforms(m_program, frame.scene.scene(), frame.shadows);
    m_program.set("uCameraPosition", frame.camera.position);
    m_program.set("uDirectEnabled", settings.direct ? 1 : 0);
    // The indirect targets hold this frame's light only when the cone pass ran for them.
    m_program.set("uIndirectDiffuseEnabled", settings.indirectDiffuse && FrameRules::diffuseConesNeeded(frame) ? 1 : 0);
    m_program.set("uIndirectSpecularEnabled", FrameRules::specularConesNeeded(frame) ? 1 : 0);
    m_program.set("uAoAvailable", FrameRules::ambientOcclusionNeeded(frame) ? 1 : 0);
    m_program.set("uEmissionEnabled", settings.emission ? 1 : 0);
    m_program.set("uView", int(settings.view));
    m_program.set("uDivisor", s.indirectDivisor);
    // Half a voxel clears the surface's own depth in the shadow map at any grazing angle we care about.
    m_program.set("uShadowOffset", 0.5f * frame.voxels.frame.voxelSize());
    s.position.bindUnit(0);
    s.normal.bindUnit(1);
    s.albedo.bindUnit(2);
    s.specular.bindUnit(3);
    s.emission.bindUnit(4);
    s.indirectDiffuse.bindUnit(5);
    s.indirectSpecular.bindUnit(6);
    s.finalTarget.bind();
    glViewport(0, 0, s.width, s.height);
    glDisable(GL_DEPTH_TEST);
    m_emptyVao.bind();
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

} // namespace vct::render
