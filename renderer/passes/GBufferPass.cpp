#include "passes/GBufferPass.h"

#include "core/FrameContext.h"
#include "core/ResourceNames.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace vct::render {

using namespace resource;

PassDeclaration GBufferPass::declare() const
{
    return { {}, { kSurface, kDepth } };
}

std::vector<TextureSlot> GBufferPass::textures(const FrameContext& frame)
{
    using gl::TextureDesc;
    ScreenTargets& s = frame.screen;
    return { { kSurface, ResourceGroup::Screen, &s.surface,
                 TextureDesc::plane(GL_RGBA32UI, s.width, s.height).sampled(TextureDesc::Sampling::Nearest) },
        { kDepth, ResourceGroup::Screen, &s.depth,
            TextureDesc::plane(GL_DEPTH32F_STENCIL8, s.width, s.height) } };
}

void GBufferPass::execute(FrameContext& frame)
{
    const gl::Program* programs[2] = {
        &frame.shaders.program({ "g-buffer", { "gbuffer/GBuffer.vert", "gbuffer/GBuffer.frag" }, {} }),
        &frame.shaders.program(
            { "g-buffer (textured)", { "gbuffer/GBuffer.vert", "gbuffer/GBuffer.frag" }, { "TEXTURED" } }),
    };
    ScreenTargets& s = frame.screen;
    s.gbuffer.follow({ &s.surface }, &s.depth);
    s.gbuffer.bind();
    glViewport(0, 0, s.width, s.height);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);
    const GLuint none[4] = { 0, 0, 0, 0 };
    glClearNamedFramebufferuiv(s.gbuffer.id(), GL_COLOR, 0, none);
    // Depth 1 and stencil 0: no surface, until the nearest one writes its pixel class.
    glClearNamedFramebufferfi(s.gbuffer.id(), GL_DEPTH_STENCIL, 0, 1.0f, 0);
    glEnable(GL_STENCIL_TEST);
    glStencilMask(0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    // Only what the camera can see, nearest first, and solids without the faces they turn away: early depth
    // testing then rejects most hidden fragments before they are shaded.
    // Relative to the eye: the world matrix loses the far plane's precision in a scene far from the origin.
    const Camera& camera = frame.camera;
    const glm::mat4 eyeViewProjection
        = frame.projection * glm::lookAt(glm::vec3(0.0f), camera.lookAt - camera.position, camera.up);
    const Frustum view(eyeViewProjection, camera.position);
    const glm::mat4& p = frame.projection;
    const float nearPlane
        = p[3][2] / (p[2][2] - 1.0f); // glm::perspective's matrix, solved for its near plane
    const Viewpoint eye { camera.position,
        1.01f * nearPlane * std::sqrt(1.0f + 1.0f / (p[0][0] * p[0][0]) + 1.0f / (p[1][1] * p[1][1])) };
    DrawOptions options;
    if (frame.settings.viewCulling) {
        options.visibleIn = &view;
        options.from = &eye;
    }
    options.stencilPixelClass = true;
    for (const bool textured : { false, true }) {
        programs[textured]->set("uViewProjection", eyeViewProjection);
        programs[textured]->set("uCameraPosition", camera.position);
        programs[textured]->set("uCameraForward", glm::normalize(camera.lookAt - camera.position));
        options.materials = [textured](const Material& m) { return (m.albedoTexture >= 0) == textured; };
        frame.scene.draw(*programs[textured], options, 0);
    }
    glDisable(GL_STENCIL_TEST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

} // namespace vct::render
