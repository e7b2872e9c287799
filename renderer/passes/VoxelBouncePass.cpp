#include "passes/VoxelBouncePass.h"

#include "core/ConeTracingSetup.h"
#include "core/FrameContext.h"
#include "core/LightUniforms.h"
#include "core/ResourceNames.h"
#include "core/VolumeShift.h"
#include "scene/DirectionalStackLayout.h"

#include "bounce/BounceSums.glsl"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <stdexcept>
#include <vector>

namespace vct::render {

namespace {

const char* const kFilterPhase = "filterings into the mip chains";

} // namespace

VoxelBouncePass::SolveKey VoxelBouncePass::keyOf(const FrameContext& frame)
{
    const RenderSettings& s = frame.settings;
    // The cones' key holds a clipmap's coarser levels' light: a level solved against a coarser level's light
    // still converging (an interactive view after a light edit) goes on when that light changes.
    const int res = frame.voxels.frame.resolution;
    return { ConeTraceKey::of(frame), s.bounces, s.bounceCellVoxels(res), s.higherBounceCellVoxels(res),
        s.bounceTolerance, s.bounceStepScale, frame.voxels.materialsVersion };
}

bool VoxelBouncePass::splitsBounces(const FrameContext& frame)
{
    // One iteration (bounces=2) gathers the first-bounce light only: nothing for coarser cells to take.
    return frame.settings.splitsHigherBounces(frame.voxels.frame.resolution);
}

int VoxelBouncePass::iterationLimit(const FrameContext& frame)
{
    const int bounces = frame.settings.bounces;
    return bounces == RenderSettings::kConvergedBounces ? RenderSettings::kMaxBounces : bounces - 1;
}

PassDecision VoxelBouncePass::plan(const FrameContext& frame) const
{
    const VoxelVolume& v = frame.voxels;
    if (!frame.shape.bounceVolume)
        return { PassDecision::Action::Skip,
            frame.settings.bounces == 1 ? "one bounce: the per-pixel cones gather it" : "no light" };
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
    if (v.bounced && v.radianceVersion == m_radianceVersion) {
        SolveKey key = keyOf(frame);
        key.cones.coarserLight = m_key.cones.coarserLight;
        if (key == m_key)
            return { PassDecision::Action::Run, "a coarser level's light changed" };
    }
    return { PassDecision::Action::Run,
        v.bounced ? "first-bounce radiance or a bounce setting changed" : "no valid output yet" };
}

PassDeclaration VoxelBouncePass::declare() const
{
    using namespace resource;
    return { { kAlbedo, kNormal, kEmission, kRadiance, kEnclosure },
        { kBounced, kBouncedDirectional, kBounceCells, kBounceCellsBack, kBounceCellNormals,
            kHigherBounceCells, kHigherBounceCellsBack, kHigherBounceCellNormals, kHigherBounceBase,
            kHigherBounceBaseBack, kHigherBounceChange, kHigherBounceChangeBack, kHigherBounceCellSums,
            kBounceCellMarks, kBounceSums } };
}

std::vector<TextureSlot> VoxelBouncePass::textures(const FrameContext& frame)
{
    using gl::TextureDesc;
    using namespace resource;
    VoxelVolume& v = frame.voxels;
    // Only while the voxels carry bounces: otherwise cones go back to the first-bounce volume.
    const bool used = frame.shape.bounceVolume;
    const int res = v.frame.resolution;
    const int cells = res / frame.settings.bounceCellVoxels(res);
    const auto ifUsed = [used](const TextureDesc& desc) { return used ? desc : TextureDesc {}; };
    // Normals and sides fit 8-bit snorm (common/IrradianceLookup.glsl).
    const auto cellDesc
        = [](int n) { return TextureDesc::volume(GL_RGBA16F, n).sampled(TextureDesc::Sampling::Nearest); };
    const auto cellNormalDesc = [](int n) {
        return TextureDesc::volume(GL_RGBA8_SNORM, n).sampled(TextureDesc::Sampling::Nearest);
    };
    const TextureDesc cell = cellDesc(cells);
    const TextureDesc cellNormal = cellNormalDesc(cells);
    const int higherCells = res / frame.settings.higherBounceCellVoxels(res);
    const auto ifSplit = [split = used && splitsBounces(frame)](
                             const TextureDesc& desc) { return split ? desc : TextureDesc {}; };
    return { { kBounced, ResourceGroup::Voxels, &v.bounced,
                 ifUsed(v.level0(GL_RGBA16F, frame.shape.coneVolumeLevels)) },
        { kBouncedDirectional, ResourceGroup::Voxels, &v.bouncedDirectional,
            frame.settings.anisotropicMips ? ifUsed(VoxelMipBuilder::directionalDesc(res)) : TextureDesc {} },
        { kBounceCells, ResourceGroup::Voxels, &v.bounceIrradiance, ifUsed(cell) },
        { kBounceCellsBack, ResourceGroup::Voxels, &v.bounceIrradianceBack, ifUsed(cell) },
        { kBounceCellNormals, ResourceGroup::Voxels, &v.bounceCellNormal, ifUsed(cellNormal) },
        { kHigherBounceCells, ResourceGroup::Voxels, &v.higherBounceIrradiance,
            ifSplit(cellDesc(higherCells)) },
        { kHigherBounceCellsBack, ResourceGroup::Voxels, &v.higherBounceIrradianceBack,
            ifSplit(cellDesc(higherCells)) },
        { kHigherBounceCellNormals, ResourceGroup::Voxels, &v.higherBounceCellNormal,
            ifSplit(cellNormalDesc(higherCells)) },
        { kHigherBounceBase, ResourceGroup::Voxels, &v.higherBounceBase, ifSplit(cellDesc(higherCells)) },
        { kHigherBounceBaseBack, ResourceGroup::Voxels, &v.higherBounceBaseBack,
            ifSplit(cellDesc(higherCells)) },
        { kHigherBounceChange, ResourceGroup::Voxels, &v.higherBounceChange, ifSplit(cellDesc(higherCells)) },
        { kHigherBounceChangeBack, ResourceGroup::Voxels, &v.higherBounceChangeBack,
            ifSplit(cellDesc(higherCells)) },
        // Seven r32ui sums per cell, in the octants of a volume of twice the cells a side (GatherCells.comp).
        { kHigherBounceCellSums, ResourceGroup::Voxels, &m_higherCellSums,
            ifSplit(TextureDesc::volume(GL_R32UI, 2 * higherCells).sampled(TextureDesc::Sampling::Nearest)) },
        { kBounceCellMarks, ResourceGroup::Voxels, &m_builder.marks(),
            ifUsed(VoxelMipBuilder::marksDesc(res)) },
        { kBounceSums, ResourceGroup::PassState, &m_sums,
            ifUsed(TextureDesc::plane(GL_R32F, BOUNCE_SUMS_PER_ITERATION * BOUNCE_SUMS_ITERATIONS, 1)) } };
}

void VoxelBouncePass::release(FrameContext& frame)
{
    frame.voxels.bounceProgress = {};
    m_radianceVersion = 0;
}

void VoxelBouncePass::buildMips(FrameContext& frame)
{
    const PhaseTimes::Scope timed = m_phases.time(kFilterPhase);
    filterMips(frame);
}

void VoxelBouncePass::filterMips(FrameContext& frame)
{
    VoxelVolume& v = frame.voxels;
    if (frame.settings.anisotropicMips)
        m_builder.buildDirectional(frame.shaders, v.bounced,
            frame.settings.dropBackFaces ? &v.normal : nullptr, v.frame.resolution, v.bouncedDirectional);
    else
        m_builder.buildBox(frame.shaders, v.bounced);
}

void VoxelBouncePass::startFromFirstBounce(FrameContext& frame)
{
    // The first-bounce volume is kept at level 0 only (MipmapPass): its light is the first iterate here. With
    // anisotropic mips its directional chains are filtered into the bounced volume's, and the first gather
    // reads level 0 from the first-bounce volume itself; box mips live in the volume's own chain, so level 0
    // is copied into the bounced volume and filtered there.
    VoxelVolume& v = frame.voxels;
    const int res = v.frame.resolution;
    const PhaseTimes::Scope timed = m_phases.time(kFilterPhase);
    glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    if (frame.settings.anisotropicMips) {
        m_builder.buildDirectional(frame.shaders, v.radiance,
            frame.settings.dropBackFaces ? &v.normal : nullptr, res, v.bouncedDirectional);
        return;
    }
    glCopyImageSubData(
        v.radiance.id(), GL_TEXTURE_3D, 0, 0, 0, 0, v.bounced.id(), GL_TEXTURE_3D, 0, 0, 0, 0, res, res, res);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    filterMips(frame);
}

void VoxelBouncePass::gather(FrameContext& frame, CellGrid& grid, const gl::Texture& front,
    const gl::Texture& back, const gl::Texture& normals, bool fromFirstBounce, int sumsIteration,
    bool firstGather, GatherExtra extra)
{
    const PhaseTimes::Scope timed = m_phases.time(
        &grid == &m_cells ? "gathers on the bounce cells" : "gathers on the higher-bounce cells");
    const bool shiftIterate = extra == GatherExtra::ShiftIterate;
    const bool writeChange = extra == GatherExtra::WriteChange;
    // The irradiance cache's shader, over every occupied cell. Its first run on these voxels finds each
    // cell's normal and sides; later ones read them back.
    VoxelVolume& v = frame.voxels;
    const bool anisotropic = frame.settings.anisotropicMips;
    const bool sums = sumsIteration >= 0;
    std::vector<std::string> defines;
    std::string name = "bounce cells";
    if (anisotropic) {
        defines.emplace_back("ANISOTROPIC");
        name += " (anisotropic)";
    }
    if (grid.geometryKnown) {
        defines.emplace_back("CACHED_GEOMETRY");
        name += ", cell geometry known";
    }
    // The bounce cells' first gather over these voxels sums their surface into the higher bounces' cells,
    // which then read those sums instead of their voxels (GatherCells.comp).
    const bool parentSums = &grid == &m_cells && !grid.geometryKnown && m_higherCells.cellSize > grid.cellSize
        && m_higherCellSums;
    const bool childSums = &grid == &m_higherCells && m_cellSumsReady;
    if (parentSums) {
        defines.emplace_back("PARENT_SUMS");
        name += ", parents' sums";
        const GLuint zero[4] = { 0, 0, 0, 0 };
        glClearTexImage(m_higherCellSums.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, zero);
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
    }
    if (childSums) {
        defines.emplace_back("CHILD_SUMS");
        name += ", from the bounce cells' sums";
    }
    if (sums) {
        defines.emplace_back("CHANGE_SUMS");
        name += ", change sums";
    }
    if (shiftIterate) {
        defines.emplace_back("SHIFT_ITERATE");
        name += ", iterate shifted";
    }
    if (writeChange) {
        defines.emplace_back("WRITE_CHANGE");
        name += ", change kept";
    }
    ConeTracingSetup::addDefines(defines, frame);
    const gl::Program& program = frame.shaders.program({ name, { "irradiance/GatherCells.comp" }, defines });
    const gl::Program& backSides = frame.shaders.program({ name + ", back sides",
        { "irradiance/GatherCells.comp" }, BackSideCells::backSideDefines(defines) });
    // Both dispatches read and write the same: the first every cell's front (its only side if one-sided), the
    // second the back sides of the two-sided cells the first listed.
    const auto setUp = [&](const gl::Program& gather, bool geometryKnown) {
        ConeTracingSetup::applyCellGather(
            gather, frame, anisotropic, grid.cellSize, false, front, back, normals);
        // Longer steps than the pixels' cones take (RenderSettings::bounceStepScale): what the gathers find
        // is looked up between cells and summed over bounces, so fewer samples along a cone do not show.
        gather.set("uStepFactor", frame.settings.stepFactor * frame.settings.bounceStepScale);
        if (geometryKnown)
            normals.bindUnit(2);
        if (parentSums) {
            m_higherCellSums.bindImage(4, 0, GL_READ_WRITE);
            gather.set("uParentRatio", m_higherCells.cellSize / grid.cellSize);
        }
        if (childSums)
            m_higherCellSums.bindUnit(4);
        if (fromFirstBounce && anisotropic) // its level 0 (startFromFirstBounce)
            v.radiance.bindUnit(5);
        if (sums) {
            front.bindImage(0, 0, GL_READ_WRITE);
            back.bindImage(1, 0, GL_READ_WRITE);
            m_sums.bindImage(3, 0, GL_READ_WRITE);
            gather.set("uIteration", sumsIteration);
            gather.set("uFirstGather", firstGather ? 1 : 0);
        }
        if (shiftIterate) {
            front.bindImage(0, 0, GL_READ_WRITE);
            back.bindImage(1, 0, GL_READ_WRITE);
            v.higherBounceIrradiance.bindImage(4, 0, GL_READ_WRITE);
            v.higherBounceIrradianceBack.bindImage(5, 0, GL_READ_WRITE);
        }
        if (writeChange) {
            front.bindImage(0, 0, GL_READ_WRITE);
            back.bindImage(1, 0, GL_READ_WRITE);
            v.higherBounceChange.bindImage(6, 0, GL_WRITE_ONLY);
            v.higherBounceChangeBack.bindImage(7, 0, GL_WRITE_ONLY);
        }
        gather.use();
    };
    // The solve's gathers read one mip level a sample, the nearest, where the pixels' cones blend two: what
    // they gather is looked up between cells and summed over bounces, so a sample's footprint rounded to a
    // level does not show, and the gathers take a fifth to a third less time (docs/DESIGN.md, "The solve's
    // gathers read the nearest mip level"). The pixels' own cache, read that way, showed steps between cells.
    if (!m_nearestLevel)
        m_nearestLevel = gl::Sampler::createNearestLevel();
    ConeTracingSetup::bindVolumeSampler(frame, m_nearestLevel.id());
    const std::size_t cells = std::size_t(v.frame.resolution / grid.cellSize);
    setUp(program, grid.geometryKnown);
    m_backSides.bindForGather(program, cells * cells * cells);
    grid.list->dispatchOverCells();
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT
        | GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
    setUp(backSides, true);
    m_backSides.dispatch();
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    ConeTracingSetup::bindVolumeSampler(frame, 0);
    grid.geometryKnown = true;
    m_cellSumsReady = m_cellSumsReady || parentSums;
}

void VoxelBouncePass::iterate(FrameContext& frame, bool compare, int iteration)
{
    VoxelVolume& v = frame.voxels;
    const bool converging = frame.settings.bounces == RenderSettings::kConvergedBounces;
    // When converging the gather also sums how much it changed.
    gather(frame, m_cells, v.bounceIrradiance, v.bounceIrradianceBack, v.bounceCellNormal, !compare,
        converging ? iteration : -1, !compare);
    reinject(frame, compare ? Reinjection::OverIterate : Reinjection::FromCleared, iteration);
}

void VoxelBouncePass::iterateSplit(FrameContext& frame, bool compare, bool firstOfSolve, int iteration)
{
    VoxelVolume& v = frame.voxels;
    const bool converging = frame.settings.bounces == RenderSettings::kConvergedBounces;
    const int sums = converging ? iteration : -1;
    if (!firstOfSolve) {
        // Only in a solve from a cold start, whose gathers of the iterate grow from their base's and whose
        // sum is never clamped: a solve going on from an earlier one under new light can clamp its first sum
        // where a gather under the new light falls below the base of the old (a coarser level's dimmed far
        // field), and changes added to that clamped sum kept its excess (1.1% over its limit, tst_Clipmap).
        // Each change added also rounds the iterate to half-float once more, and a change below its rounding
        // step is lost: a long solve (a closed room's) takes the whole sum again after the first few.
        const bool increment = m_coldSolve && iteration <= kIncrementalIterations;
        gather(frame, m_higherCells, v.higherBounceIrradiance, v.higherBounceIrradianceBack,
            v.higherBounceCellNormal, false, sums, false,
            increment ? GatherExtra::WriteChange : GatherExtra::None);
        reinject(frame, increment ? Reinjection::AddHigherChange : Reinjection::OverIterate, iteration);
        return;
    }
    // A solve starting from an earlier one gathers that iterate first, before the first-bounce light takes
    // its place in the volume: the iteration goes on from it under the new first-bounce light. Its first
    // reinjection adds the earlier solve's higher bounces (that iterate's gather less the earlier
    // first-bounce light's): the new light's gather moves the iterate's by what it changed. Taken against the
    // new light's gather instead, the first frame after a light edit was 4 times as far from the converged
    // image, after a dragged object's move twice as far (tst_RenderPlan). Not after a step of the grid, whose
    // earlier gathers are of other places.
    if (compare) {
        gather(frame, m_higherCells, v.higherBounceIrradiance, v.higherBounceIrradianceBack,
            v.higherBounceCellNormal, false, sums, false);
        startFromFirstBounce(frame);
    }
    // The bounce cells first: their first gather over these voxels sums the higher cells' surfaces.
    gather(frame, m_cells, v.bounceIrradiance, v.bounceIrradianceBack, v.bounceCellNormal, true, -1, true);
    // A cold start's change is what the first gather found, as in iterate(), at the higher bounces' scale
    // that every later change of this solve is measured at.
    gather(frame, m_higherCells, v.higherBounceBase, v.higherBounceBaseBack, v.higherBounceCellNormal, true,
        compare ? -1 : sums, true, compare && m_baseInPlace ? GatherExtra::ShiftIterate : GatherExtra::None);
    if (!compare) {
        // The first iterate is the first-bounce light itself: its gather is the base's.
        const int n = v.higherBounceBase.width();
        glCopyImageSubData(v.higherBounceBase.id(), GL_TEXTURE_3D, 0, 0, 0, 0, v.higherBounceIrradiance.id(),
            GL_TEXTURE_3D, 0, 0, 0, 0, n, n, n);
        glCopyImageSubData(v.higherBounceBaseBack.id(), GL_TEXTURE_3D, 0, 0, 0, 0,
            v.higherBounceIrradianceBack.id(), GL_TEXTURE_3D, 0, 0, 0, 0, n, n, n);
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    }
    // A cold start's iterate is the first-bounce light, whose higher bounces are nothing yet.
    m_coldSolve = !compare;
    reinject(frame, compare ? Reinjection::FromCleared : Reinjection::FirstBounceOnly, iteration);
}

void VoxelBouncePass::reinject(FrameContext& frame, Reinjection how, int iteration)
{
    VoxelVolume& v = frame.voxels;
    std::optional<PhaseTimes::Scope> timed(m_phases.time("reinjections"));
    if (frame.settings.bounces == RenderSettings::kConvergedBounces) {
        const gl::Program& decide
            = frame.shaders.program({ "bounce tail decision", { "bounce/DecideTail.comp" }, {} });
        decide.use();
        decide.set("uIteration", iteration);
        decide.set("uTolerance", frame.settings.bounceTolerance);
        decide.set("uLargestRatio", float(kLargestRatio));
        m_sums.bindImage(1, 0, GL_READ_WRITE);
        glDispatchCompute(1, 1, 1);
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    }

    // L = L_direct + albedo * gathered, over the occupied voxels, with the residual's sums.
    const bool compare = how == Reinjection::OverIterate || how == Reinjection::AddHigherChange;
    // A change is added to the iterate it was gathered from, which a clear would lose: the whole sum instead.
    if (how == Reinjection::AddHigherChange && m_staleVoxels)
        how = Reinjection::OverIterate;
    const float zero[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
    if (!compare || m_staleVoxels) // stale voxels of an earlier occupancy must not stay lit
        glClearTexImage(v.bounced.id(), 0, GL_RGBA, GL_FLOAT, zero);
    m_staleVoxels = false;
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    const int res = v.frame.resolution;
    const int cells = res / m_cells.cellSize;
    const bool split = splitsBounces(frame);
    const bool increment = how == Reinjection::AddHigherChange;
    const bool higherBounces = split && how != Reinjection::FirstBounceOnly && !increment;
    std::vector<std::string> defines;
    std::string name = "bounce reinjection";
    if (increment) {
        defines.emplace_back("INCREMENT");
        name += ", higher bounces' change added";
    }
    if (higherBounces) {
        defines.emplace_back("HIGHER_BOUNCES");
        name += ", higher bounces";
    }
    // A block of 2^3 voxels shares the eight cells its voxels interpolate between only where cells are 4^3
    // voxels or more (bounce/ReinjectBounce.comp); cells of 2^3 are looked up voxel by voxel. The higher
    // bounces' cells, coarser than the bounce cells, always are.
    if (m_cells.cellSize >= 4) {
        defines.emplace_back("BLOCK_CELLS");
        name += ", cells by blocks";
    }
    if (split && m_higherCells.cellSize < 4)
        throw std::logic_error("the higher bounces' cells are coarser than the bounce cells");
    // The reinjection writes the first mip level above the voxels it lights (bounce/ReinjectBounce.comp).
    const bool anisotropic = frame.settings.anisotropicMips;
    const bool filterDirectional = anisotropic && bool(VoxelMipBuilder::directionalDesc(res));
    const bool filterBox = !anisotropic && v.bounced.levels() > 1;
    if (filterDirectional) {
        defines.emplace_back("FILTER_DIRECTIONAL");
        name += ", directional filter";
        if (frame.settings.dropBackFaces) {
            defines.emplace_back("DROP_BACK_FACES");
            name += " without back faces";
        }
        m_builder.prepareDirectional(res, v.bouncedDirectional);
        v.bouncedDirectional.bindImage(2, 0, GL_WRITE_ONLY);
    }
    if (filterBox) {
        defines.emplace_back("FILTER_BOX");
        name += ", box filter";
        glClearTexImage(v.bounced.id(), 1, GL_RGBA, GL_FLOAT, zero);
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
        v.bounced.bindImage(2, 1, GL_WRITE_ONLY);
    }
    const gl::Program& program = frame.shaders.program({ name, { "bounce/ReinjectBounce.comp" }, defines });
    program.use();
    if (filterDirectional)
        program.set("uTileStride", DirectionalStackLayout::of(res).stride(0));
    program.set("uGridOrigin", v.frame.origin);
    program.set("uVoxelSize", v.frame.voxelSize());
    program.set("uCellVoxels", m_cells.cellSize);
    program.set("uCells", cells);
    program.set("uCellSize", v.frame.extent / float(cells));
    if (split) {
        const int higherCells = res / m_higherCells.cellSize;
        program.set("uHigherCellVoxels", m_higherCells.cellSize);
        program.set("uHigherCells", higherCells);
        program.set("uHigherCellSize", v.frame.extent / float(higherCells));
        (increment ? v.higherBounceChange : v.higherBounceIrradiance).bindUnit(3);
        (increment ? v.higherBounceChangeBack : v.higherBounceIrradianceBack).bindUnit(4);
        v.higherBounceCellNormal.bindUnit(5);
        v.higherBounceBase.bindUnit(6);
        v.higherBounceBaseBack.bindUnit(7);
    }
    program.set("uCompare", compare ? 1 : 0);
    program.set("uIteration", iteration);
    v.albedo.bindUnit(0);
    v.normal.bindUnit(1);
    v.radiance.bindUnit(2);
    v.bounceIrradiance.bindUnit(kIrradianceUnit);
    v.bounceCellNormal.bindUnit(kCellNormalUnit);
    v.bounceIrradianceBack.bindUnit(kIrradianceBackUnit);
    v.bounced.bindImage(0, 0, GL_READ_WRITE);
    m_sums.bindImage(1, 0, GL_READ_WRITE);
    // By blocks of 2^3 voxels: the first level's cells (listCells() lists them above every occupied voxel).
    m_builder.cellsOfSize(2).dispatchOverCells();
    glMemoryBarrier(
        GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
    timed.reset();
    // The levels above the one the reinjection wrote.
    const PhaseTimes::Scope filtered = m_phases.time(kFilterPhase);
    if (filterDirectional)
        m_builder.buildDirectional(frame.shaders, v.bounced,
            frame.settings.dropBackFaces ? &v.normal : nullptr, res, v.bouncedDirectional, 1);
    else if (filterBox)
        m_builder.buildBox(frame.shaders, v.bounced, 2);
}

std::vector<VoxelBouncePass::Change> VoxelBouncePass::readChanges(int first, int count)
{
    std::vector<float> sums(std::size_t(BOUNCE_SUMS_PER_ITERATION * BOUNCE_SUMS_ITERATIONS));
    glGetTextureImage(m_sums.id(), 0, GL_RED, GL_FLOAT, GLsizei(sums.size() * sizeof(float)), sums.data());
    std::vector<Change> changes;
    for (int k = first; k < first + count; ++k) {
        const auto at
            = [&](int which) { return double(sums[std::size_t(BOUNCE_SUMS_PER_ITERATION * k + which)]); };
        // The tail is per channel; any of them added means the solve extrapolated.
        const double tail
            = std::max({ at(BOUNCE_SUM_TAIL), at(BOUNCE_SUM_TAIL + 1), at(BOUNCE_SUM_TAIL + 2) });
        changes.push_back(
            { at(BOUNCE_SUM_VOXEL_CHANGE), at(BOUNCE_SUM_VOXEL_TOTAL), tail, at(BOUNCE_SUM_TAIL_ERROR) });
    }
    return changes;
}

void VoxelBouncePass::judge(const Change& change, double tolerance)
{
    m_residual = change.total > 0.0 ? change.change / change.total : 0.0;
    if (change.tail > 0.0) {
        // bounce/DecideTail.comp added the tail, having estimated its error under the tolerance.
        m_extrapolated = true;
        m_done = true;
        m_residual = change.tailError;
        m_lastChange = 0.0;
        return;
    }
    // Otherwise converged when this change is under the tolerance and those still to come, the last one times
    // the tail q / (1 - q) (q: the ratio of two consecutive changes, none taken across an extrapolation),
    // under half of it: like the tail's own estimate (bounce/DecideTail.comp), q taken from two changes runs
    // short while it still settles.
    const double q = m_lastChange > 0.0 ? change.change / m_lastChange : -1.0;
    // Also for ratios too close to one to extrapolate with (a closed room of albedo 0.95, whose gathers
    // capture all around them): there the changes still to come are many times the last one, and a tail from
    // an earlier, smaller ratio stopped such a room 9% short of its limit while calling it converged. Light
    // that does not shrink (albedo 1 in a closed room) never stops on its change.
    if (q > 0.0 && q < 1.0)
        m_tail = q / (1.0 - q);
    else if (q >= 1.0)
        m_tail = std::numeric_limits<double>::infinity();
    m_lastChange = change.change;
    const double toCome = m_residual > 0.0 ? m_residual * (m_tail > 0.0 ? m_tail : 1.0) : 0.0;
    m_done = m_iterations >= 2 && m_residual < tolerance && toCome < 0.5 * tolerance;
}

bool VoxelBouncePass::cellsOutdated(const VoxelVolume& v) const
{
    // New textures (the pipeline makes them as textures() says) need their cells found again too.
    return v.materialsVersion != m_listedMaterials || v.bounced.serial() != m_bouncedSerial
        || v.bounceIrradiance.serial() != m_cellsSerial;
}

bool VoxelBouncePass::redoesWholeGrid(const FrameContext& frame) const
{
    // New voxels: every occupied cell is found again and the solve starts over from the first bounce. A light
    // edit over the same voxels starts from the last solve instead, and is not a rebuild.
    return cellsOutdated(frame.voxels);
}

void VoxelBouncePass::execute(FrameContext& frame)
{
    m_phases.start(frame.phaseTimes);
    VoxelVolume& v = frame.voxels;
    const int res = v.frame.resolution;
    const bool converging = frame.settings.bounces == RenderSettings::kConvergedBounces;
    const bool split = splitsBounces(frame);
    const bool progressive = frame.bounceIterationsPerFrame > 0 && converging;
    const bool sameSolve = v.bounced && v.radianceVersion == m_radianceVersion && keyOf(frame) == m_key;
    const bool voxelsChanged = cellsOutdated(v);
    // A sparse grid whose bricks were all allocated again keeps its light's texels in other places.
    const bool sameBouncedTexture
        = v.bounced.serial() == m_bouncedSerial && (!v.sparse || v.brickLayout == m_brickLayout);
    if (voxelsChanged) {
        m_bouncedSerial = v.bounced.serial();
        m_brickLayout = v.brickLayout;
        m_cellsSerial = v.bounceIrradiance.serial();
        // The mip filter lists the cells of every level above the occupied voxels: those of the bounce cells'
        // sizes are the cells to gather, where lists of their own searched the whole grid's voxels again.
        m_builder.listCells(
            frame.shaders, res, v.frame.levelCount(), v.occupiedVoxels(frame.scene.hasDynamicMeshes()));
        m_cells.cellSize = frame.settings.bounceCellVoxels(res);
        m_cells.list = &m_builder.cellsOfSize(m_cells.cellSize);
        m_listedMaterials = v.materialsVersion;
        m_cells.geometryKnown = false;
        m_higherCells.cellSize = 0;
        m_cellSumsReady = false;
    }
    if (split
        && (m_higherCells.cellSize != frame.settings.higherBounceCellVoxels(res)
            || v.higherBounceIrradiance.serial() != m_higherCellsSerial)) {
        if (v.higherBounceIrradiance.serial() != m_higherCellsSerial) {
            // New textures hold no earlier base: a solve going on from an iterate of a solve that did not
            // split (or of other cells) takes that iterate's gather against the new base's, not against
            // whatever the texture's memory held.
            const float none[4] = { 0.0f, 0.0f, 0.0f, -1.0f };
            glClearTexImage(v.higherBounceBase.id(), 0, GL_RGBA, GL_FLOAT, none);
            glClearTexImage(v.higherBounceBaseBack.id(), 0, GL_RGBA, GL_FLOAT, none);
        }
        m_higherCellsSerial = v.higherBounceIrradiance.serial();
        m_higherCells.cellSize = frame.settings.higherBounceCellVoxels(res);
        m_higherCells.list = &m_builder.cellsOfSize(m_higherCells.cellSize);
        m_higherCells.geometryKnown = false;
        // Summed for other cells, or not yet: the higher cells read their voxels until the bounce cells' next
        // first gather.
        m_cellSumsReady = false;
    }
    // An interactive view starts a new solve from the last one, so that a light edit brightens or dims the
    // bounces smoothly instead of starting again from one bounce; and so does a change of voxels in the same
    // grid (a dragged object, an edited material), where most of the light is where it was: the iteration
    // converges from any start, and from the last solve it needs a frame or two, where starting over showed
    // the moving object's surroundings darker, with one or two bounces, for as long as it moved. The voxels
    // it left are cleared before the first reinjection; until then the first gather still sees them.
    // Across a grid that stepped by whole voxels (a clip level following the camera) the last solve moves
    // with it first, and the slabs it did not cover start from the first-bounce light: a level that started
    // over at each step showed fewer bounces near the camera for the frames its solve took, and the solve ran
    // in most frames of a flight.
    // A brick pool is no grid to shift (a sparse grid that moved has new bricks anyway).
    const std::optional<glm::ivec3> shift
        = voxelsChanged && sameBouncedTexture && m_grid != v.frame && !v.sparse
        ? VolumeShift::between(m_grid, v.frame)
        : std::nullopt;
    const bool carryOver = progressive && m_iterations > 0
        && (!voxelsChanged || (sameBouncedTexture && (m_grid == v.frame || shift)));
    bool warm = sameSolve || carryOver;
    // A grid that stepped moved its light (below) but not its higher-bounce cells' gathers, in cells coarser
    // than the step: those no longer match it.
    m_baseInPlace = m_grid == v.frame;
    m_staleVoxels = warm && voxelsChanged;
    if (!warm)
        startFromFirstBounce(frame);
    else if (carryOver && shift) {
        VolumeShift::apply(v.bounced, &v.radiance, *shift);
        buildMips(frame);
    }
    if (!sameSolve) {
        m_iterations = 0;
        m_residual = 0.0;
        m_lastChange = 0.0;
        m_tail = -1.0;
        m_done = false;
        m_extrapolated = false;
        m_stoppedAtLimit = false;
        const float zero[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
        glClearTexImage(m_sums.id(), 0, GL_RED, GL_FLOAT, zero);
    }
    const int limit = iterationLimit(frame);
    // A split solve's first iteration gathers the new first-bounce light on both sizes of cells and costs
    // about three later ones: a frame that starts a solve (each frame of a dragged light) runs that one only,
    // and the frames that go on with the same solve run the whole budget.
    const int budget = progressive ? (split && !sameSolve ? 1 : frame.bounceIterationsPerFrame) : limit;
    // Iterations run in batches with one readback of their residuals after each: a frame of the interactive
    // view runs its whole budget and then waits once, instead of stalling after every iteration; a frame that
    // converges fully decides after each one, so that it stops where the change is small enough.
    for (int ran = 0; ran < budget && !m_done;) {
        const int batch = std::min(
            { converging && progressive ? kBatchIterations : 1, budget - ran, limit - m_iterations });
        for (int k = 0; k < batch; ++k) {
            // The first iteration of a cold start gathers from the first-bounce light; its reinjection then
            // overwrites every occupied voxel, and the clear before it every other.
            if (split)
                iterateSplit(frame, warm, m_iterations + k == 0, m_iterations + k);
            else
                iterate(frame, warm, m_iterations + k);
            warm = true;
        }
        ran += batch;
        if (!converging) {
            m_iterations += batch;
            m_done = m_iterations >= limit;
            continue;
        }
        for (const Change& change : readChanges(m_iterations, batch)) {
            ++m_iterations;
            if (!m_done)
                judge(change, double(frame.settings.bounceTolerance));
        }
        m_stoppedAtLimit = !m_done && m_iterations >= limit;
        m_done = m_done || m_iterations >= limit;
    }
    v.bounceProgress = { m_iterations, m_residual, m_done, m_extrapolated, m_stoppedAtLimit };
    m_radianceVersion = v.radianceVersion;
    m_grid = v.frame;
    m_key = keyOf(frame);
    ++v.bouncedVersion;
}

} // namespace vct::render
