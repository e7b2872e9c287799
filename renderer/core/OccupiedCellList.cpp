#include "core/OccupiedCellList.h"

#include "core/ShaderLibrary.h"

#include <algorithm>
#include <cstdint>

namespace vct::render {

void OccupiedCellList::build(const ShaderLibrary& shaders, const gl::Texture& albedo,
    const VoxelRegion& region, int cellSize, const gl::Texture* clearTarget, glm::vec4 clearValue)
{
    if (!m_program)
        m_program = &shaders.program({ "occupied cells", { "common/ListOccupied.comp" }, {} });
    if (clearTarget && !region.isEmpty()) {
        const glm::ivec3 lo = region.lo, size = region.size();
        glClearTexSubImage(clearTarget->id(), 0, lo.x, lo.y, lo.z, size.x, size.y, size.z, GL_RGBA, GL_FLOAT,
            &clearValue[0]);
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    }
    albedo.bindUnit(0);
    m_program->set("uCellSize", cellSize);
    buildWith(*m_program, region);
}

void OccupiedCellList::reset(std::size_t capacity, unsigned binding)
{
    if (!m_dispatch)
        m_dispatch = gl::Buffer(4 * sizeof(std::uint32_t), nullptr, GL_DYNAMIC_STORAGE_BIT);
    const std::size_t bytes
        = std::max<std::size_t>(std::min(capacity, m_capacityCap), 1) * sizeof(std::uint32_t);
    if (m_cells.size() < bytes)
        m_cells = gl::Buffer(bytes, nullptr, 0);
    const std::uint32_t empty[4] = { 0, 1, 1, 0 };
    m_dispatch.upload(empty, sizeof empty);
    m_dispatch.bindBase(GL_SHADER_STORAGE_BUFFER, binding);
    m_cells.bindBase(GL_SHADER_STORAGE_BUFFER, binding + 1);
}

void OccupiedCellList::bindForAppending(unsigned binding) const
{
    m_dispatch.bindBase(GL_SHADER_STORAGE_BUFFER, binding);
    m_cells.bindBase(GL_SHADER_STORAGE_BUFFER, binding + 1);
}

void OccupiedCellList::assignShifted(const ShaderLibrary& shaders, const OccupiedCellList& source,
    const glm::ivec3& shift, const VoxelRegion& kept, std::size_t capacity)
{
    if (!m_shiftProgram)
        m_shiftProgram = &shaders.program({ "shift occupied cells", { "common/ShiftCells.comp" }, {} });
    reset(capacity, 2);
    if (!source.m_dispatch)
        return;
    m_shiftProgram->use();
    m_shiftProgram->set("uShift", shift);
    m_shiftProgram->set("uKeptLo", kept.lo);
    m_shiftProgram->set("uKeptHi", kept.hi);
    m_shiftProgram->set("uGroupSize", kGroupSize);
    source.dispatchOverCells();
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
}

void OccupiedCellList::buildWith(const gl::Program& lister, const VoxelRegion& region)
{
    const glm::ivec3 size = region.size();
    reset(std::size_t(size.x) * std::size_t(size.y) * std::size_t(size.z));
    if (region.isEmpty())
        return;
    lister.use();
    lister.set("uRegionOrigin", region.lo);
    lister.set("uRegionSize", size);
    lister.set("uGroupSize", kGroupSize);
    // The lister's own work-group size: on llvmpipe each group costs a fixed overhead, so 8^3 groups list a
    // grid far faster than 4^3 (docs/DESIGN.md, "Measured choices").
    GLint local[3] = { 1, 1, 1 };
    glGetProgramiv(lister.id(), GL_COMPUTE_WORK_GROUP_SIZE, local);
    const glm::ivec3 groupSize(local[0], local[1], local[2]);
    const glm::ivec3 groups = (size + groupSize - 1) / groupSize;
    glDispatchCompute(GLuint(groups.x), GLuint(groups.y), GLuint(groups.z));
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
}

void OccupiedCellList::dispatchOverCells() const
{
    m_dispatch.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
    m_cells.bindBase(GL_SHADER_STORAGE_BUFFER, 1);
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, m_dispatch.id());
    glDispatchComputeIndirect(0);
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
}

std::size_t OccupiedCellList::count() const
{
    if (!m_dispatch)
        return 0;
    std::uint32_t command[4] = { 0, 0, 0, 0 };
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glGetNamedBufferSubData(m_dispatch.id(), 0, sizeof command, command);
    return command[3];
}

std::vector<glm::ivec3> OccupiedCellList::cells() const
{
    const std::size_t n = count();
    std::vector<std::uint32_t> codes(n);
    if (n > 0)
        glGetNamedBufferSubData(m_cells.id(), 0, GLsizeiptr(n * sizeof(std::uint32_t)), codes.data());
    // Packed as common/AppendCell.glsl packs them: 10 bits per axis.
    std::vector<glm::ivec3> cells;
    cells.reserve(n);
    for (const std::uint32_t code : codes)
        cells.emplace_back(int(code & 1023u), int((code >> 10) & 1023u), int(code >> 20));
    return cells;
}

} // namespace vct::render
