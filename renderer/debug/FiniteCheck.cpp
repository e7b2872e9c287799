#include "debug/FiniteCheck.h"

#include <algorithm>

namespace vct::render {

std::uint64_t FiniteCheck::count(const gl::Texture& texture, int level)
{
    const bool volume = texture.target() == GL_TEXTURE_3D;
    const gl::Program& program = volume ? *m_volume : *m_flat;
    const std::uint32_t zero = 0;
    m_counter.upload(&zero, sizeof zero);
    m_counter.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
    texture.bindUnit(0);
    program.use();
    program.set("uLevel", level);
    const int w = std::max(1, texture.width() >> level), h = std::max(1, texture.height() >> level);
    const int d = volume ? std::max(1, texture.depth() >> level) : 1;
    glDispatchCompute(GLuint((w + 3) / 4), GLuint((h + 3) / 4), GLuint((d + 3) / 4));
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    std::uint32_t result = 0;
    glGetNamedBufferSubData(m_counter.id(), 0, sizeof result, &result);
    return result;
}

std::vector<NonFiniteCount> FiniteCheck::run(
    const ShaderLibrary& shaders, const ScreenTargets& screen, const VoxelVolume& voxels)
{
    if (!m_flat) {
        m_flat = &shaders.program({ "count non-finite (2D)", { "check/CountNonFinite.comp" }, {} });
        m_volume
            = &shaders.program({ "count non-finite (3D)", { "check/CountNonFinite.comp" }, { "VOLUME" } });
        m_counter = gl::Buffer(sizeof(std::uint32_t), nullptr, GL_DYNAMIC_STORAGE_BIT);
    }
    std::vector<NonFiniteCount> counts;
    // 8-bit and integer targets cannot hold NaN or Inf, so only float ones are checked (the g-buffer's packed
    // normal is made finite before it is packed).
    const std::pair<const char*, const gl::Texture*> targets[] = { { "final", &screen.final },
        { "indirect diffuse", &screen.indirectDiffuse },
        { "indirect upsampling guide", &screen.indirectGuide }, { "specular", &screen.specular },
        { "area-light shadows", &screen.areaShadow }, { "area-light shadow guide", &screen.areaShadowGuide },
        { "specular upsampling guide", &screen.specularGuide }, { "voxel normal", &voxels.normal },
        { "voxel emission", &voxels.emission } };
    for (const auto& [name, texture] : targets)
        if (*texture)
            counts.push_back({ name, count(*texture, 0) });
    if (voxels.radiance)
        for (int level = 0; level < voxels.radiance.levels(); ++level)
            counts.push_back({ "radiance level " + std::to_string(level), count(voxels.radiance, level) });
    const std::pair<const char*, const gl::Texture*> cells[]
        = { { "voxel irradiance cache", &voxels.irradiance },
              { "voxel irradiance cache, back faces", &voxels.irradianceBack },
              { "voxel irradiance cell normals", &voxels.irradianceNormal },
              { "bounce cells", &voxels.bounceIrradiance },
              { "bounce cells, back faces", &voxels.bounceIrradianceBack },
              { "bounce cell normals", &voxels.bounceCellNormal } };
    for (const auto& [name, texture] : cells)
        if (*texture)
            counts.push_back({ name, count(*texture, 0) });
    if (voxels.bounced)
        for (int level = 0; level < voxels.bounced.levels(); ++level)
            counts.push_back(
                { "bounced radiance level " + std::to_string(level), count(voxels.bounced, level) });
    // The cone volume's box levels where it keeps none (made for this check by Renderer::countNonFinite).
    for (int level = 1; level < voxels.inspectionMips.levels(); ++level)
        counts.push_back(
            { "cone radiance box level " + std::to_string(level), count(voxels.inspectionMips, level) });
    for (const auto& [prefix, stack] :
        { std::pair { "directional radiance (six tiles) level ", &voxels.directional },
            std::pair { "bounced directional radiance (six tiles) level ", &voxels.bouncedDirectional } })
        if (*stack)
            for (int level = 0; level < stack->levels(); ++level) {
                // Appended piecewise: gcc 12 warns falsely (-Wrestrict) on literal + std::string chains.
                std::string name(prefix);
                name.append(std::to_string(level + 1));
                counts.push_back({ name, count(*stack, level) });
            }
    return counts;
}

} // namespace vct::render
