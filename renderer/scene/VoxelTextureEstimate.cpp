#include "scene/VoxelTextureEstimate.h"

#include "scene/DirectionalStackLayout.h"
#include "scene/RenderSettings.h"

#include <algorithm>

namespace vct::render {

std::string clipLevelName(int level, const std::string& name)
{
    return level == 0 ? name : "clip level " + std::to_string(level) + ": " + name;
}

namespace {

/** Bytes of a cube of @p side texels of @p bytesPerTexel, with its whole mip chain when @p mips. */
std::uint64_t chain(std::uint64_t side, std::uint64_t bytesPerTexel, bool mips)
{
    std::uint64_t total = 0;
    for (std::uint64_t s = side; s >= 1; s /= 2) {
        total += s * s * s * bytesPerTexel;
        if (!mips)
            break;
    }
    return total;
}

} // namespace

std::vector<VoxelTextureEstimate> VoxelTextureEstimate::of(
    const RenderSettings& settings, VoxelSceneNeeds scene)
{
    std::vector<VoxelTextureEstimate> textures;
    const std::uint64_t n = std::uint64_t(settings.voxelResolution);
    // A sparse grid keeps level 0 in a pool of bricks of 9^3 texels per 8^3 voxels (core/BrickPool).
    const bool sparse = settings.voxelMode == VoxelMode::Sparse;
    const auto level0 = [&](std::uint64_t bytes) {
        return sparse ? std::uint64_t(double(bytes) * scene.brickShare * (729.0 / 512.0)) : bytes;
    };
    // The voxelizer's averages (VoxelizePass): albedo rgba8, normal rgba8 snorm, and emission
    // (r11f_g11f_b10f) for a scene with emissive materials.
    textures.push_back({ "albedo", level0(chain(n, 4, false)) });
    textures.push_back({ "normal", level0(chain(n, 4, false)) });
    if (scene.emission)
        textures.push_back({ "emission", level0(chain(n, 4, false)) });
    // The volume cones trace, rgba16f: with anisotropic mips level 0 and six directional chains from level 1
    // (one stack of six tiles with five gaps between them), else its box mip chain. It is the bounced volume
    // when bounces are carried by the voxels (the first-bounce radiance then keeps level 0 only, as the
    // iteration's source), else the first-bounce radiance itself.
    const bool bounced = settings.bounces != 1 && scene.lightSources;
    textures.push_back({ "radiance", level0(chain(n, 8, !bounced && !settings.anisotropicMips)) });
    if (scene.areaLights)
        textures.push_back({ "opacity", chain(n, 4, true) }); // rgba8 per axis, the area lights' shadow cones
    // Which cells above the occupied voxels the mip filter has listed, a bit per level (r32ui over level 1),
    // for the volume cones trace: the bounce iteration's filter, or the first-bounce light's.
    textures.push_back({ bounced ? "cell marks, bounced levels" : "cell marks, first-bounce levels",
        chain(std::max<std::uint64_t>(n / 2, 1), 4, false) });
    if (const DirectionalStackLayout stack = DirectionalStackLayout::of(settings.voxelResolution);
        settings.anisotropicMips && stack.levels > 0)
        textures.push_back({ bounced ? "bounced, directional (+x -x +y -y +z -z)"
                                     : "radiance, directional (+x -x +y -y +z -z)",
            stack.bytes(8) });
    if (bounced) {
        textures.push_back({ "bounced", level0(chain(n, 8, !settings.anisotropicMips)) });
        // The bounce gather's cells: front and back rgba16f, the normal rgba8 snorm.
        const std::uint64_t cells = n / std::uint64_t(settings.bounceCellVoxels(int(n)));
        textures.push_back({ "bounce cells", chain(cells, 8, false) });
        textures.push_back({ "bounce cells, back faces", chain(cells, 8, false) });
        textures.push_back({ "bounce cell normals", chain(cells, 4, false) });
        // The higher bounces' coarser cells (VoxelBouncePass::splitsBounces): six rgba16f, the normal rgba8
        // snorm, and their surfaces' sums.
        const std::uint64_t higherCells = n / std::uint64_t(settings.higherBounceCellVoxels(int(n)));
        if (settings.splitsHigherBounces(int(n))) {
            textures.push_back({ "higher-bounce cells", chain(higherCells, 8, false) });
            textures.push_back({ "higher-bounce cells, back faces", chain(higherCells, 8, false) });
            textures.push_back({ "higher-bounce cell normals", chain(higherCells, 4, false) });
            textures.push_back({ "higher-bounce cells, first-bounce light", chain(higherCells, 8, false) });
            textures.push_back(
                { "higher-bounce cells, first-bounce light, back faces", chain(higherCells, 8, false) });
            textures.push_back({ "higher-bounce cells, last change", chain(higherCells, 8, false) });
            textures.push_back(
                { "higher-bounce cells, last change, back faces", chain(higherCells, 8, false) });
            // Seven r32ui sums per cell, in a volume of twice the cells a side.
            textures.push_back({ "higher-bounce cells, surface sums", chain(2 * higherCells, 4, false) });
        }
    }
    // Each coarser level of a clipmap is a grid like the finest, named as Renderer::describeVoxelMemory
    // names them.
    const std::size_t oneLevel = textures.size();
    for (int level = 1; level < settings.gridLevels(); ++level)
        for (std::size_t i = 0; i < oneLevel; ++i)
            textures.push_back({ clipLevelName(level, textures[i].name), textures[i].bytes });
    // Where the grid around the scene is closed in (passes/EnclosurePass): r8.
    if (settings.enclosedSpace)
        textures.push_back({ "enclosed space",
            chain(std::min<std::uint64_t>(n, RenderSettings::kMaxEnclosureResolution), 1, false) });
    // The irradiance cache's cells, and which of them were gathered (r32ui): over the finest grid only (in a
    // clipmap, pixels beyond its finest level trace their own cones).
    if (settings.irradianceCache) {
        const std::uint64_t cells
            = std::max<std::uint64_t>(n / std::uint64_t(settings.irradianceCellSize), 1);
        textures.push_back({ "irradiance cache", chain(cells, 8, false) });
        textures.push_back({ "irradiance cache, back faces", chain(cells, 8, false) });
        textures.push_back({ "irradiance cell normals", chain(cells, 4, false) });
        textures.push_back({ "irradiance cells gathered", chain(cells, 4, false) });
    }
    return textures;
}

} // namespace vct::render
