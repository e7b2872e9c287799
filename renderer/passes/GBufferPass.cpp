#include "passes/GBufferPass.h"

#include "core/FrameContext.h"

namespace vct::render {

void GBufferPass::execute(FrameContext& frame)
{
    if (!m_program)
        m_program = frame.shaders.build({"g-buffer", {"gbuffer/GBuffer.vert", "gbuffer/GBuffer.frag"}, {}});
    ScreenTargets& s = frame.screen;
    s.gbuffer.bind();
    glViewport(0, 0, s.width, s.height);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);
    const float zero[4] = {0, 0, 0, 0};
    for (int i = 0; i < 3; ++i)
        glClearNamedFramebufferfv(s.gbuffer.id(), GL_COLOR, i, zero);
    const float one = 1.0f;
    glClearNamedFramebufferfv(s.gbuffer.id(), GL_DEPTH, 0, &one);
    m_program.set("uViewProjection", frame.projection * frame.view);
    frame.scene.draw(m_program, MeshFilter::All, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

} // namespace vct::render
