#pragma once

#include "scene/Material.h"

#include <cstdint>

// The GLSL file is the single definition of the stencil bits.
#include "common/PixelClass.glsl"

namespace vct::render {

/** The stencil bits the g-buffer writes for a surface of this material (common/PixelClass.glsl). */
inline std::uint32_t pixelClassOf(const Material& material)
{
    return PIXEL_GEOMETRY | (material.isGlossy() ? PIXEL_GLOSSY : 0u)
        | (material.isEmissive() ? PIXEL_EMISSIVE : 0u);
}

} // namespace vct::render
