#include "passes/ConeTracePass.h"

#include "core/FrameContext.h"
#include "core/FrameRules.h"

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
    return {PassDecision::Action::Run, reason};
}

void ConeTracePass::execute(FrameContext& frame)
{
    const RenderSettings& settings = frame.settings;
    const VoxelVolume& v = frame.voxels;
    const bool anisotropic = settings.anisotropicMips && v.directional[0];
    gl::Program& program = anisotropic ? m_anisotropicProgram : m_program;
    if (!program)
        program = frame.shaders.build({anisotropic ? "cone trace (anisotropic)" : "cone trace",
            {"common/FullScreen.vert", "cone/ConeTrace.frag"}, anisotropic ? std::vector<std::string>{"ANISOTROPIC"} : std::vector<std::string>{}});
    if (!m_emptyVao)
        m_emptyVao = gl::VertexArray::create();
    ScreenTargets& s = frame.screen;
    const float voxel = v.frame.voxelSize();
    const float maxDistance = settings.maxDistance >= 0.0f ? settings.maxDistance : v.frame.extent * std::sqrt(3.0f);
    std::vector<glm::vec4> cones;
    for (int i = 0; i < frame.diffuseCones.size(); ++i)
        cones.emplace_back(frame.diffuseCones.directions()[std::size_t(i)], frame.diffuseCones.weights()[std::size_t(i)]);

    program.set("uGridOrigin", v.frame.origin);
    program.set("uGridExtent", v.frame.extent);
    program.set("uVoxelSize", voxel);
    program.set("uMaxLevel", float(v.radiance.levels() - 1));
    program.set("uStepFactor", settings.stepFactor);
    program.set("uMaxDistance", maxDistance);
    program.set("uConeOffset", settings.coneOffsetVoxels * voxel);
    program.set("uConeCount", frame.diffuseCones.size());
    program.set("uCones", cones);
    program.set("uDiffuseTanHalf", std::tan(glm::radians(settings.diffuseApertureDeg * 0.5f)));
    program.set("uSpecularMinTanHalf", std::tan(glm::radians(settings.specularApertureDeg * 0.5f)));
    program.set("uDiffuseEnabled", FrameRules::diffuseConesNeeded(frame) ? 1 : 0);
    program.set("uSpecularEnabled", FrameRules::specularConesNeeded(frame) ? 1 : 0);
    program.set("uAoEnabled", FrameRules::ambientOcclusionNeeded(frame) ? 1 : 0);
    program.set("uAoDistance", 0.1f * v.frame.extent);
    program.set("uCameraPosition", frame.camera.position);

    s.position.bindUnit(0);
    s.normal.bindUnit(1);
    s.specular.bindUnit(3);
    v.radiance.bindUnit(5);
    if (anisotropic)
        for (std::size_t d = 0; d < 6; ++d)
            v.directional[d].bindUnit(GLuint(6 + d));
    program.set("uDivisor", s.indirectDivisor);
    program.set("uFullSize", glm::ivec3(s.width, s.height, 0));
    s.indirectTarget.bind();
    glViewport(0, 0, s.indirectDiffuse.width(), s.indirectDiffuse.height());
    glDisable(GL_DEPTH_TEST);
    program.use();
    m_emptyVao.bind();
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

} // namespace vct::render
