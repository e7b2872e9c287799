#include "core/EnclosureMap.h"

namespace vct::render {

void EnclosureMap::finish()
{
    if (!pending.valid())
        return;
    const Build build = pending.get();
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTextureSubImage3D(texture.id(), 0, 0, 0, 0, grid.resolution, grid.resolution, grid.resolution, GL_RED,
        GL_UNSIGNED_BYTE, build.texels.data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    enclosedCells = build.enclosedCells;
}

void EnclosureMap::abandon()
{
    if (pending.valid())
        pending.wait();
    pending = {};
}

} // namespace vct::render
