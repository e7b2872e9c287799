#include "passes/ConeTracePass.h"

#include "core/ConeSampleCounter.h"
#include "core/FrameContext.h"
#include "core/FrameRules.h"
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

void ConeTracePass::execute(FrameContext& frame)
{
    const RenderSettings& settings = frame.settings;
    const VoxelVolume& v = frame.voxels;
    const bool anisotropic = settings.anisotropicMips && v.directional;
    const bool counting = frame.coneSampleCounter != nullptr;
    const bool cached = VoxelIrradiancePass::inUse(frame) && v.irradiance;
    gl::Program& program = m_programs[anisotropic ? 1 : 0][counting ? 1 : 0][cached ? 1 : 0];
    if (!program) {
        std::vector<std::string> defines;
        std::string name = "cone trace";
        for (const auto& [on, define, label] : {std::tuple{anisotropic, "ANISOTROPIC", " (anisotropic)"},
                 std::tuple{counting, "COUNT_SAMPLES", ", counting samples"},
                 std::tuple{cached, "IRRADIANCE_CACHE", ", irradiance cache"}})
            if (on) {
                defines.push_back(define);
                name += label;
            }
        program = frame.shaders.build({name, {"common/FullScreen.vert", "cone/ConeTrace.frag"}, defines});
    }
    if (cached) {
        v.irradiance.bindUnit(12);
        v.irradianceNormal.bindUnit(13);
        v.irradianceBack.bindUnit(14);
        program.set("uCells", v.irradiance.width());
        program.set("uCellSize", v.frame.extent / float(v.irradiance.width()));
    }
    if (counting)
        frame.coneSampleCounter->bind();
    if (!m_emptyVao)
        m_emptyVao = gl::VertexArray::create();
    ScreenTargets& s = frame.screen;
    ConeTracingSetup::apply(program, frame, anisotropic, true);
    program.set("uSpecularMinTanHalf", std::tan(glm::radians(settings.specularApertureDeg * 0.5f)));
    program.set("uDiffuseEnabled", FrameRules::diffuseConesNeeded(frame) ? 1 : 0);
    program.set("uSpecularEnabled", FrameRules::specularConesNeeded(frame) ? 1 : 0);
    program.set("uAoEnabled", FrameRules::ambientOcclusionNeeded(frame) ? 1 : 0);
    program.set("uAoDistance", 0.1f * frame.voxels.frame.extent);
    program.set("uCameraPosition", frame.camera.position);

    s.position.bindUnit(0);
    s.normal.bindUnit(1);
    frame.scene.bindMaterialTable(kMaterialTableUnit);
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
