#include "passes/AreaLightPass.h"

#include "core/ConeTracingSetup.h"
#include "core/FrameContext.h"
#include "core/LightUniforms.h"
#include "core/ResourceNames.h"

#include <string>

namespace vct::render {

using namespace resource;

PassDeclaration AreaLightPass::declare() const
{
    return { { kSurface, kOpacity }, { kAreaShadow, kAreaShadowGuide, kAreaShadowStencil } };
}

std::vector<TextureSlot> AreaLightPass::textures(const FrameContext& frame)
{
    ScreenTargets& s = frame.screen;
    return s.tracedGrid({ kAreaShadow, kAreaShadowGuide, kAreaShadowStencil }, s.areaShadow,
        s.areaShadowGuide, s.areaShadowStencil, s.areaDivisor, frame.shape.areaLights > 0);
}

PassDecision AreaLightPass::plan(const FrameContext& frame) const
{
    const int lights = frame.shape.areaLights;
    if (lights == 0)
        return { PassDecision::Action::Skip, "no area lights" };
    return { PassDecision::Action::Run,
        "per-frame: " + std::to_string(lights) + " area lights, one traced pixel in "
            + std::to_string(frame.screen.areaDivisor * frame.screen.areaDivisor) };
}

void AreaLightPass::execute(FrameContext& frame)
{
    const int lights = frame.shape.areaLights;
    std::vector<std::string> defines { "AREA_LIGHT_COUNT " + std::to_string(lights) };
    addAreaShadowDefines(defines, frame);
    const gl::Program& program = frame.shaders.program(
        { "area-light shadows", { "common/FullScreen.vert", "composite/AreaShadows.frag" }, defines });
    if (!m_emptyVao)
        m_emptyVao = gl::VertexArray::create();
    ScreenTargets& s = frame.screen;
    s.areaShadowTarget.follow({ &s.areaShadow, &s.areaShadowGuide }, &s.areaShadowStencil);
    s.areaShadowTarget.bind();
    glViewport(0, 0, s.areaShadow.width(), s.areaShadow.height());
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
    program.use();
    program.set("uDivisor", s.areaDivisor);
    program.set("uFullSize", glm::ivec3(s.width, s.height, 0));
    program.set("uCameraPosition", frame.camera.position);
    program.set("uPixelToRay", frame.pixelToRay);
    program.set("uAreaShadowOffset", ConeTracingSetup::coneOffsetMetres(frame));
    applyAreaLightUniforms(program, frame);
    s.surface.bindUnit(1);
    m_emptyVao.bind();
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

} // namespace vct::render
