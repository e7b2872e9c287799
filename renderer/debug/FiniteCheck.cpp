#include "debug/FiniteCheck.h"

#include <algorithm>

namespace vct::render {

namespace {

/** Formats that can hold NaN or Inf: 8-bit, snorm and integer ones cannot. */
bool holdsFloats(GLenum format)
{
    return format == GL_RGBA16F || format == GL_RGBA32F || format == GL_R32F || format == GL_RG32F
        || format == GL_R11F_G11F_B10F;
}

} // namespace

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

std::vector<NonFiniteCount> FiniteCheck::run(const ShaderLibrary& shaders, const ResourceTable& resources)
{
    if (!m_flat) {
        m_flat = &shaders.program({ "count non-finite (2D)", { "check/CountNonFinite.comp" }, {} });
        m_volume
            = &shaders.program({ "count non-finite (3D)", { "check/CountNonFinite.comp" }, { "VOLUME" } });
        m_counter = gl::Buffer(sizeof(std::uint32_t), nullptr, GL_DYNAMIC_STORAGE_BIT);
    }
    std::vector<NonFiniteCount> counts;
    // 8-bit, depth and integer textures cannot hold NaN or Inf, so only float ones are checked (the
    // g-buffer's packed normal is made finite before it is packed): per-pixel targets, then every level of
    // every voxel texture (the directional stacks' level k is grid level k + 1), then the passes' own data.
    for (const ResourceGroup group :
        { ResourceGroup::Screen, ResourceGroup::Voxels, ResourceGroup::PassState })
        for (const ResourceTable::Entry& entry : resources.entries()) {
            const gl::Texture& texture = *entry.texture;
            if (entry.group != group || !texture || !holdsFloats(texture.format()))
                continue;
            if (group == ResourceGroup::Screen) {
                counts.push_back({ entry.name, count(texture, 0) });
                continue;
            }
            for (int level = 0; level < texture.levels(); ++level) {
                // Appended piecewise: gcc 12 warns falsely (-Wrestrict) on literal + std::string chains.
                std::string name(group == ResourceGroup::Voxels ? "voxel " : "");
                name.append(entry.name).append(", level ").append(std::to_string(level));
                counts.push_back({ name, count(texture, level) });
            }
        }
    return counts;
}

} // namespace vct::render
