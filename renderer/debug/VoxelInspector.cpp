#include "debug/VoxelInspector.h"

#include "common/Bindings.glsl"

#include <algorithm>
#include <bit>

namespace vct::render {

namespace {

struct GpuEntry {
    glm::ivec4 coord;
    glm::vec4 value;
};

} // namespace

const VoxelListing& VoxelInspector::list(
    const ShaderLibrary& shaders, const VoxelVolume& volume, int level, VoxelChannel channel, int grid)
{
    if (!volume.radiance)
        return m_listing = VoxelListing {};
    // The light cones trace: the bounced volume when bounces are carried by the voxels, with its box levels
    // (made for the inspector when the volume keeps none: VoxelVolume::inspectionMips).
    const gl::Texture& radiance = volume.inspectionMips ? volume.inspectionMips : volume.coneRadiance();
    level = std::clamp(level, 0, radiance.levels() - 1);
    const std::array<std::uint64_t, 10> key { std::uint64_t(grid), std::uint64_t(level),
        std::uint64_t(channel), volume.materialsVersion, volume.radianceVersion, volume.bouncedVersion,
        std::uint64_t(volume.frame.resolution), std::bit_cast<std::uint32_t>(volume.frame.origin.x),
        std::bit_cast<std::uint32_t>(volume.frame.origin.y),
        std::bit_cast<std::uint32_t>(volume.frame.origin.z) };
    if (m_valid && key == m_key)
        return m_listing;
    if (!m_compact) {
        m_compact = &shaders.program({ "inspector compact", { "inspector/CompactVoxels.comp" }, {} });
        m_counter = gl::Buffer(sizeof(std::uint32_t), nullptr, GL_DYNAMIC_STORAGE_BIT);
    }
    const int size = std::max(1, volume.frame.resolution >> level);
    const std::size_t capacity = std::size_t(size) * std::size_t(size) * std::size_t(size);
    if (m_entries.size() < capacity * sizeof(GpuEntry))
        m_entries = gl::Buffer(capacity * sizeof(GpuEntry), nullptr, GL_DYNAMIC_STORAGE_BIT);
    const std::uint32_t zero = 0;
    m_counter.upload(&zero, sizeof zero);
    const gl::Texture& channelTexture = channel == VoxelChannel::Normal ? volume.normal
        : channel == VoxelChannel::Emission                             ? volume.emission
                                                                        : volume.albedo;
    radiance.bindUnit(0);
    channelTexture.bindUnit(1);
    volume.albedo.bindUnit(2);
    if (volume.sparse) // level 0 of albedo, normal and emission through its bricks (common/VoxelBricks.glsl)
        volume.brickTable.bindUnit(BRICK_TABLE_UNIT);
    m_entries.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
    m_counter.bindBase(GL_SHADER_STORAGE_BUFFER, 1);
    m_compact->use();
    m_compact->set("uLevel", level);
    m_compact->set("uChannelKind", int(channel));
    m_compact->set("uLevelSize", size);
    m_compact->set("uCapacity", unsigned(capacity));
    const GLuint groups = GLuint((size + 3) / 4);
    glDispatchCompute(groups, groups, groups);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);

    std::uint32_t count = 0;
    glGetNamedBufferSubData(m_counter.id(), 0, sizeof count, &count);
    count = std::min<std::uint32_t>(count, std::uint32_t(capacity));
    std::vector<GpuEntry> entries(count);
    if (count)
        glGetNamedBufferSubData(m_entries.id(), 0, GLsizeiptr(count * sizeof(GpuEntry)), entries.data());
    m_listing = VoxelListing { grid, level, channel, volume.frame.origin,
        volume.frame.voxelSize() * float(1 << level), {} };
    m_listing.samples.reserve(count);
    for (const GpuEntry& e : entries)
        m_listing.samples.push_back({ glm::ivec3(e.coord), e.value });
    m_key = key;
    m_valid = true;
    return m_listing;
}

std::size_t VoxelInspector::draw(
    const ShaderLibrary& shaders, const glm::mat4& viewProjection, float exposure)
{
    if (!m_valid || m_listing.samples.empty())
        return 0;
    if (!m_cubes) {
        m_cubes = &shaders.program(
            { "inspector cubes", { "inspector/VoxelCube.vert", "inspector/VoxelCube.frag" }, {} });
        m_emptyVao = gl::VertexArray::create();
    }
    m_cubes->use();
    m_cubes->set("uViewProjection", viewProjection);
    m_cubes->set("uGridOrigin", m_listing.origin);
    m_cubes->set("uCellSize", m_listing.cellSize);
    m_cubes->set("uChannelKind", int(m_listing.channel));
    m_cubes->set("uExposure", exposure);
    m_entries.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
    m_emptyVao.bind();
    glDrawArraysInstanced(GL_TRIANGLES, 0, 36, GLsizei(m_listing.samples.size()));
    glBindVertexArray(0);
    return m_listing.samples.size();
}

} // namespace vct::render
