#include "passes/ConeTracePass.h"

#include "core/ConeSampleCounter.h"
#include "core/FrameContext.h"
#include "core/FrameRules.h"
#include "core/PixelClass.h"
#include "passes/ConeTracingSetup.h"
#include "passes/VoxelIrradiancePass.h"

#include <tuple>

#include <glm/trigonometric.hpp>

#include <cmath>

namespace vct::render {

PassDecision ConeTracePass::plan(const FrameContext& frame)
{
    const bool diffuse = FrameRules::diffuseConesNeeded(frame);
    const bool specular = FrameRules::specularConesNeeded(frame);
    if (!diffuse && !specular) {
        if (!FrameRules::hasLightSources(frame))
            return {PassDecision::Action::Skip, "no lights and no emission: no indirect light at all"};
        return {PassDecision::Action::Skip, "indirect diffuse off, no glossy material, AO not shown"};
    }
    std::string reason = "per-frame: ";
    reason += diffuse ? (specular ? "diffuse and specular cones" : "diffuse cones") : "specular cones";
    if (!specular)
        reason += frame.settings.indirectSpecular ? " (no glossy material: no specular cones)" : " (specular off)";
    if (diffuse && !FrameRules::ambientOcclusionNeeded(frame))
        reason += ", no AO";
    if (diffuse && VoxelIrradiancePass::inUse(frame))
        reason += ", diffuse looked up in the irradiance cache";
    return {PassDecision::Action::Run, reason};
}

namespace {

gl::Program buildVariant(const ShaderLibrary& shaders, const char* name, const char* file, bool anisotropic, bool counting)
{
    std::vector<std::string> defines;
    std::string label = name;
    if (anisotropic) {
        defines.emplace_back("ANISOTROPIC");
        label += " (anisotropic)";
    }
    if (counting) {
        defines.emplace_back("COUNT_SAMPLES");
        label += ", counting samples";
    }
    return shaders.build({label, {"common/FullScreen.vert", file}, defines});
}

void drawFullScreen()
{
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

} // namespace

void ConeTracePass::execute(FrameContext& frame)
{
    const RenderSettings& settings = frame.settings;
    const VoxelVolume& v = frame.voxels;
    const bool anisotropic = settings.anisotropicMips && v.directional;
    const bool counting = frame.coneSampleCounter != nullptr;
    const bool cached = VoxelIrradiancePass::inUse(frame) && v.irradiance;
    const bool diffuse = FrameRules::diffuseConesNeeded(frame);
    const bool specular = FrameRules::specularConesNeeded(frame);
    gl::Program& classify = m_classify[cached ? 1 : 0];
    if (!classify)
        classify = frame.shaders.build({cached ? "cone trace: classify pixels, irradiance cache" : "cone trace: classify pixels",
            {"common/FullScreen.vert", "cone/ClassifyPixels.frag"}, cached ? std::vector<std::string>{"IRRADIANCE_CACHE"} : std::vector<std::string>{}});
    gl::Program& diffuseCones = m_diffuse[anisotropic ? 1 : 0][counting ? 1 : 0];
    if (diffuse && !diffuseCones)
        diffuseCones = buildVariant(frame.shaders, "cone trace: diffuse cones", "cone/DiffuseCones.frag", anisotropic, counting);
    gl::Program& specularCone = m_specular[anisotropic ? 1 : 0][counting ? 1 : 0];
    if (specular && !specularCone)
        specularCone = buildVariant(frame.shaders, "cone trace: specular cone", "cone/SpecularCone.frag", anisotropic, counting);
    if (!m_emptyVao)
        m_emptyVao = gl::VertexArray::create();

    ScreenTargets& s = frame.screen;
    s.position.bindUnit(0);
    s.surface.bindUnit(1);
    frame.scene.bindMaterialTable(kMaterialTableUnit);
    if (cached) {
        v.irradiance.bindUnit(12);
        v.irradianceNormal.bindUnit(13);
        v.irradianceBack.bindUnit(14);
    }
    if (counting)
        frame.coneSampleCounter->bind();
    s.indirectTarget.bind();
    glViewport(0, 0, s.indirectDiffuse.width(), s.indirectDiffuse.height());
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_STENCIL_TEST);
    m_emptyVao.bind();
    // Pixels no specular cone reaches read as no specular light in the composite's upsampling.
    const float none[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearNamedFramebufferfv(s.indirectTarget.id(), GL_COLOR, 1, none);

    // Classify: the shader's own stencil value (ARB_shader_stencil_export) replaces whatever was there.
    s.indirectTarget.drawTo({0, 2});
    glStencilMask(0xFF);
    glStencilFunc(GL_ALWAYS, 0, 0xFF);
    glStencilOp(GL_REPLACE, GL_REPLACE, GL_REPLACE);
    classify.use();
    classify.set("uDivisor", s.indirectDivisor);
    classify.set("uFullSize", glm::ivec3(s.width, s.height, 0));
    classify.set("uGridOrigin", v.frame.origin);
    classify.set("uCameraPosition", frame.camera.position);
    classify.set("uDiffuseEnabled", diffuse ? 1 : 0);
    classify.set("uSpecularEnabled", specular ? 1 : 0);
    if (cached) {
        classify.set("uCells", v.irradiance.width());
        classify.set("uCellSize", v.frame.extent / float(v.irradiance.width()));
    }
    drawFullScreen();

    glStencilMask(0x00);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    if (diffuse) {
        s.indirectTarget.drawTo({0});
        glStencilFunc(GL_EQUAL, PIXEL_NEEDS_CONES, PIXEL_NEEDS_CONES);
        ConeTracingSetup::apply(diffuseCones, frame, anisotropic, true);
        diffuseCones.set("uAoEnabled", FrameRules::ambientOcclusionNeeded(frame) ? 1 : 0);
        diffuseCones.set("uAoDistance", 0.1f * frame.voxels.frame.extent);
        diffuseCones.set("uDivisor", s.indirectDivisor);
        diffuseCones.set("uFullSize", glm::ivec3(s.width, s.height, 0));
        diffuseCones.use();
        drawFullScreen();
    }
    if (specular) {
        s.indirectTarget.drawTo({1});
        glStencilFunc(GL_EQUAL, PIXEL_GLOSSY, PIXEL_GLOSSY);
        ConeTracingSetup::apply(specularCone, frame, anisotropic, true);
        specularCone.set("uSpecularMinTanHalf", std::tan(glm::radians(settings.specularApertureDeg * 0.5f)));
        specularCone.set("uCameraPosition", frame.camera.position);
        specularCone.set("uAoEnabled", 0);
        specularCone.set("uDivisor", s.indirectDivisor);
        specularCone.set("uFullSize", glm::ivec3(s.width, s.height, 0));
        specularCone.use();
        drawFullScreen();
    }
    glStencilMask(0xFF);
    glDisable(GL_STENCIL_TEST);
    s.indirectTarget.drawTo({0, 1, 2});
    glBindVertexArray(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

} // namespace vct::render
