#pragma once

#include "gl/Program.h"
#include "gl/Texture.h"

namespace vct::render {

class ShaderLibrary;

/**
 * Filters a radiance volume into its mip levels: the box chain (each level the 2x2x2 average of the one
 * below) and, for anisotropic mips, six directional chains. Shared by the mipmap pass (first-bounce
 * radiance) and the bounce pass (the volume after a second bounce), so both filter identically.
 */
class VoxelMipBuilder {
public:
    /** Levels 1..N of @p volume from its level 0. */
    void buildBox(const ShaderLibrary& shaders, gl::Texture& volume, int resolution);
    /**
     * Six chains (+x, -x, +y, -y, +z, -z; texture level k = grid level k + 1) composited front to back from
     * level 0 of @p source into the tiles of @p directional (a gl::Texture::create3DStack, (re)allocated as
     * needed).
     */
    void buildDirectional(const ShaderLibrary& shaders, const gl::Texture& source, int resolution,
        gl::Texture& directional);

private:
    gl::Program m_boxProgram;
    gl::Program m_directionalProgram;
    gl::Program m_allDirectionsProgram;
};

} // namespace vct::render
