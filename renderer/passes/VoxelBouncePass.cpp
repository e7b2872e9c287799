#include "passes/VoxelBouncePass.h"

#include "core/ConeTracingSetup.h"
#include "core/FrameContext.h"
#include "core/LightUniforms.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace vct::render {

VoxelBouncePass::SolveKey VoxelBouncePass::keyOf(const FrameContext& frame)
{
    const RenderSettings& s = frame.settings;
    return { ConeTraceKey::of(frame), s.bounces, std::min(s.bounceCellSize, frame.voxels.frame.resolution),
        s.bounceTolerance, frame.voxels.materialsVersion };
}

int VoxelBouncePass::iterationLimit(const FrameContext& frame)
{
    const int bounces = frame.settings.bounces;
    return bounces == RenderSettings::kConvergedBounces ? RenderSettings::kMaxBounces : bounces - 1;
}

PassDecision VoxelBouncePass::plan(const FrameContext& frame)
{
    VoxelVolume& v = frame.voxels;
    if (!frame.shape.bounceVolume) {
        // Cones must go back to the first-bounce volume; the memory is not needed either.
        for (gl::Texture* t : { &v.bounced, &v.bouncedDirectional, &v.bounceIrradiance,
                 &v.bounceIrradianceBack, &v.bounceCellNormal })
            *t = gl::Texture();
        v.bounceProgress = {};
        m_radianceVersion = 0;
        return { PassDecision::Action::Skip,
            frame.settings.bounces == 1 ? "one bounce: the per-pixel cones gather it" : "no light" };
    }
    const bool sameSolve = v.bounced && v.radianceVersion == m_radianceVersion && keyOf(frame) == m_key;
    char text[160];
    if (sameSolve && m_done) {
        std::snprintf(text, sizeof text, "first-bounce radiance unchanged: %d iterations, residual %.2g",
            m_iterations, m_residual);
        return { PassDecision::Action::Reuse, text };
    }
    if (sameSolve) {
        std::snprintf(
            text, sizeof text, "converging: %d iterations so far, residual %.2g", m_iterations, m_residual);
        return { PassDecision::Action::Run, text };
    }
    return { PassDecision::Action::Run,
        v.bounced ? "first-bounce radiance or a bounce setting changed" : "no valid output yet" };
}

void VoxelBouncePass::allocate(VoxelVolume& v, int cells, int levels)
{
    const int res = v.frame.resolution;
    if (!v.bounced || v.bounced.width() != res || v.bounced.levels() != levels)
        v.bounced = gl::Texture::create3D(GL_RGBA16F, res, levels);
    if (!v.bounceIrradiance || v.bounceIrradiance.width() != cells)
        for (gl::Texture* t : { &v.bounceIrradiance, &v.bounceIrradianceBack, &v.bounceCellNormal }) {
            // Normals and sides fit 8-bit snorm (common/IrradianceLookup.glsl).
            *t = gl::Texture::create3D(t == &v.bounceCellNormal ? GL_RGBA8_SNORM : GL_RGBA16F, cells);
            t->setFilter(GL_NEAREST, GL_NEAREST);
        }
    if (!m_residualSums)
        m_residualSums = gl::Texture::create2D(GL_R32F, 2 * kResidualSlots, 1);
}

void VoxelBouncePass::buildMips(FrameContext& frame)
{
    VoxelVolume& v = frame.voxels;
    if (frame.settings.anisotropicMips)
        m_builder.buildDirectional(frame.shaders, v.bounced, v.frame.resolution, v.bouncedDirectional);
    else
        m_builder.buildBox(frame.shaders, v.bounced);
}

void VoxelBouncePass::startFromFirstBounce(FrameContext& frame)
{
    // The first-bounce volume is kept at level 0 only (MipmapPass): its light becomes the first iterate here,
    // filtered into the bounced volume's own levels, and the first gather reads it from there.
    VoxelVolume& v = frame.voxels;
    const int res = v.frame.resolution;
    glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    glCopyImageSubData(
        v.radiance.id(), GL_TEXTURE_3D, 0, 0, 0, 0, v.bounced.id(), GL_TEXTURE_3D, 0, 0, 0, 0, res, res, res);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    buildMips(frame);
}

void VoxelBouncePass::iterate(FrameContext& frame, bool compare, int slot)
{
    VoxelVolume& v = frame.voxels;
    const bool anisotropic = frame.settings.anisotropicMips;
    const int res = v.frame.resolution;
    const int cellSize = std::min(frame.settings.bounceCellSize, res);
    const int cells = res / cellSize;

    // Gather: the irradiance cache's shader, over every occupied cell, from the current iterate.
    const gl::Program& gather = frame.shaders.program(
        { anisotropic ? "bounce cells (anisotropic)" : "bounce cells", { "irradiance/GatherCells.comp" },
            anisotropic ? std::vector<std::string> { "ANISOTROPIC" } : std::vector<std::string> {} });
    ConeTracingSetup::applyCellGather(gather, frame, anisotropic, cellSize, false, v.bounceIrradiance,
        v.bounceIrradianceBack, v.bounceCellNormal);
    gather.use();
    m_cells.dispatchOverCells();
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);

    // Reinject: L = L_direct + albedo * gathered, over the occupied voxels, with the residual's sums.
    const float zero[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
    if (!compare) // stale voxels of an earlier occupancy must not stay lit
        glClearTexImage(v.bounced.id(), 0, GL_RGBA, GL_FLOAT, zero);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    m_reinject->use();
    m_reinject->set("uGridOrigin", v.frame.origin);
    m_reinject->set("uVoxelSize", v.frame.voxelSize());
    m_reinject->set("uCellVoxels", cellSize);
    m_reinject->set("uCells", cells);
    m_reinject->set("uCellSize", v.frame.extent / float(cells));
    m_reinject->set("uCompare", compare ? 1 : 0);
    m_reinject->set("uResidualSlot", slot);
    v.albedo.bindUnit(0);
    v.normal.bindUnit(1);
    v.radiance.bindUnit(2);
    v.bounceIrradiance.bindUnit(kIrradianceUnit);
    v.bounceCellNormal.bindUnit(kCellNormalUnit);
    v.bounceIrradianceBack.bindUnit(kIrradianceBackUnit);
    v.bounced.bindImage(0, 0, GL_READ_WRITE);
    m_residualSums.bindImage(1, 0, GL_READ_WRITE);
    for (const OccupiedCellList* voxels : v.occupiedVoxels(frame.scene.hasDynamicMeshes()))
        voxels->dispatchOverCells();
    glMemoryBarrier(
        GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
    buildMips(frame);
}

std::vector<double> VoxelBouncePass::readResiduals(int count)
{
    std::vector<float> sums(std::size_t(2 * kResidualSlots));
    glGetTextureImage(
        m_residualSums.id(), 0, GL_RED, GL_FLOAT, GLsizei(sums.size() * sizeof(float)), sums.data());
    std::vector<double> residuals;
    for (int k = 0; k < count; ++k) {
        const float change = sums[std::size_t(2 * k)], total = sums[std::size_t(2 * k + 1)];
        residuals.push_back(total > 0.0f ? double(change) / double(total) : 0.0);
    }
    return residuals;
}

void VoxelBouncePass::execute(FrameContext& frame)
{
    VoxelVolume& v = frame.voxels;
    if (!m_reinject)
        m_reinject = &frame.shaders.program({ "bounce reinjection", { "bounce/ReinjectBounce.comp" }, {} });
    const int res = v.frame.resolution;
    const int cellSize = std::min(frame.settings.bounceCellSize, res);
    const int cells = res / cellSize;
    const bool converging = frame.settings.bounces == RenderSettings::kConvergedBounces;
    const bool progressive = frame.bounceIterationsPerFrame > 0 && converging;
    const bool sameSolve = v.bounced && v.radianceVersion == m_radianceVersion && keyOf(frame) == m_key;
    const int levels = frame.shape.coneVolumeLevels;
    const bool voxelsChanged = !v.bounced || v.materialsVersion != m_listedMaterials
        || v.bounced.width() != res || v.bounced.levels() != levels || !v.bounceIrradiance
        || v.bounceIrradiance.width() != cells;
    allocate(v, cells, levels);
    if (voxelsChanged) {
        m_cells.build(frame.shaders, v.albedo, VoxelRegion::whole(cells), cellSize);
        m_builder.listCells(
            frame.shaders, res, v.frame.levelCount(), v.occupiedVoxels(frame.scene.hasDynamicMeshes()));
        m_listedMaterials = v.materialsVersion;
    }
    // An interactive view starts a new solve from the last one where the voxels are the same, so that a light
    // edit brightens or dims the bounces smoothly instead of starting again from one bounce.
    bool warm = sameSolve || (progressive && !voxelsChanged && m_iterations > 0);
    if (!warm)
        startFromFirstBounce(frame);
    if (!sameSolve) {
        m_iterations = 0;
        m_residual = m_previousResidual = 0.0;
        m_done = false;
    }
    const int limit = iterationLimit(frame);
    const int budget = progressive ? frame.bounceIterationsPerFrame : limit;
    // Iterations run in batches with one readback of their residuals after each: a frame of the interactive
    // view runs its whole budget and then waits once, instead of stalling after every iteration; a frame that
    // converges fully decides after each one, so that it stops where the change is small enough.
    for (int ran = 0; ran < budget && !m_done;) {
        const int batch = std::min(
            { converging && progressive ? kResidualSlots : 1, budget - ran, limit - m_iterations });
        const float zero[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
        glClearTexImage(m_residualSums.id(), 0, GL_RED, GL_FLOAT, zero);
        for (int slot = 0; slot < batch; ++slot) {
            // The first iteration of a cold start gathers from the first-bounce light; its reinjection then
            // overwrites every occupied voxel, and the clear before it every other.
            iterate(frame, warm, slot);
            warm = true;
        }
        ran += batch;
        const std::vector<double> residuals
            = converging ? readResiduals(batch) : std::vector<double>(std::size_t(batch), 0.0);
        for (const double residual : residuals) {
            ++m_iterations;
            if (converging) {
                m_previousResidual = m_residual;
                m_residual = residual;
                // The change shrinks geometrically (by the scene's average albedo times what a gather
                // captures): the change still to come is about residual * q / (1 - q).
                const double q = m_iterations >= 3 && m_previousResidual > 0.0
                    ? std::min(m_residual / m_previousResidual, 0.99)
                    : 0.5;
                const double tolerance = double(frame.settings.bounceTolerance);
                m_done = m_done
                    || (m_iterations >= 2 && m_residual < tolerance
                        && m_residual * q / (1.0 - q) < tolerance);
            }
            m_done = m_done || m_iterations >= limit;
        }
    }
    // With anisotropic mips cones read level 0 and the directional chains only; the inspector filters box
    // levels of its own (VoxelVolume::inspectionMips).
    if (!frame.settings.anisotropicMips)
        v.bouncedDirectional = gl::Texture();
    v.bounceProgress = { m_iterations, m_residual, m_done };
    m_radianceVersion = v.radianceVersion;
    m_key = keyOf(frame);
    ++v.bouncedVersion;
}

} // namespace vct::render
