#include "core/FrameResources.h"

namespace vct::render {

std::vector<VoxelVolume::NamedTexture> VoxelVolume::textures() const
{
    return { { "albedo", &albedo }, { "normal", &normal }, { "emission", &emission },
        { "radiance", &radiance }, { "opacity", &opacity },
        { "radiance, directional (+x -x +y -y +z -z)", &directional }, { "bounced", &bounced },
        { "bounced, directional (+x -x +y -y +z -z)", &bouncedDirectional },
        { "bounce cells", &bounceIrradiance }, { "bounce cells, back faces", &bounceIrradianceBack },
        { "bounce cell normals", &bounceCellNormal }, { "irradiance cache", &irradiance },
        { "irradiance cache, back faces", &irradianceBack }, { "irradiance cell normals", &irradianceNormal },
        { "irradiance cells gathered", &irradianceRequested },
        { "box levels for inspection", &inspectionMips } };
}

std::size_t VoxelVolume::byteSize() const
{
    std::size_t total = 0;
    // From the textures' own sizes: asked every frame for the stats, so no GL queries (describeVoxelMemory
    // adds GL's description of each level, for the benchmarks and tests).
    for (const NamedTexture& named : textures())
        total += *named.texture ? named.texture->byteSize() : 0;
    return total;
}

} // namespace vct::render
