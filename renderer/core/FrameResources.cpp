#include "core/FrameResources.h"

namespace vct::render {

std::size_t VoxelVolume::byteSize() const
{
    std::size_t total = 0;
    for (const gl::Texture* t : { &accumulators, &staticAlbedo, &staticNormal, &staticEmission, &albedo,
             &normal, &emission, &radiance, &opacity, &directional, &bounced, &bouncedDirectional,
             &bounceIrradiance, &bounceIrradianceBack, &bounceCellNormal, &irradiance, &irradianceBack,
             &irradianceNormal, &irradianceRequested })
        total += *t ? t->byteSize() : 0;
    return total;
}

} // namespace vct::render
