#include "core/FrameResources.h"

#include "core/VoxelTextureMemory.h"

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
    for (const VoxelTextureMemory& texture : describeVoxelMemory(*this))
        total += texture.totalBytes();
    return total;
}

} // namespace vct::render
