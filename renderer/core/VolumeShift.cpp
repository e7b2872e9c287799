#include "core/VolumeShift.h"

#include <stdexcept>

#include "gl/Texture.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace vct::render {

std::optional<glm::ivec3> VolumeShift::between(const VoxelGridFrame& from, const VoxelGridFrame& to)
{
    if (from.resolution != to.resolution || from.extent != to.extent || !(to.extent > 0.0f))
        return std::nullopt;
    const glm::vec3 voxels = (to.origin - from.origin) / to.voxelSize();
    glm::ivec3 shift;
    for (int axis = 0; axis < 3; ++axis) {
        if (!std::isfinite(voxels[axis]))
            return std::nullopt;
        const float whole = std::round(voxels[axis]);
        // A clip level's corner is its scene grid's corner plus whole steps: off by rounding only.
        if (std::abs(voxels[axis] - whole) > 1e-3f || std::abs(whole) >= float(to.resolution))
            return std::nullopt;
        shift[axis] = int(whole);
    }
    return shift;
}

void VolumeShift::apply(const gl::Texture& volume, const gl::Texture* fill, const glm::ivec3& shift)
{
    const int size = volume.width();
    if (volume.height() != size || volume.depth() != size)
        throw std::logic_error("VolumeShift moves the texels of a cubic grid, not of a brick pool");
    glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    // One axis at a time: new[i] = old[i + d]. Slabs |d| thick, from the side the content moves towards, so
    // each copy reads slabs not yet overwritten (a copy within one image must not overlap itself).
    for (int axis = 0; axis < 3; ++axis) {
        const int d = shift[axis];
        if (d == 0)
            continue;
        const int thickness = std::abs(d);
        const auto copySlab = [&](GLuint source, int from, int to, int width) {
            glm::ivec3 src(0), dst(0), extent(size);
            src[axis] = from;
            dst[axis] = to;
            extent[axis] = width;
            glCopyImageSubData(source, GL_TEXTURE_3D, 0, src.x, src.y, src.z, volume.id(), GL_TEXTURE_3D, 0,
                dst.x, dst.y, dst.z, extent.x, extent.y, extent.z);
        };
        if (d > 0) {
            for (int i = 0; i < size - d; i += thickness)
                copySlab(volume.id(), i + d, i, std::min(thickness, size - d - i));
            if (fill)
                copySlab(fill->id(), size - d, size - d, d);
        } else {
            for (int end = size; end > thickness; end -= thickness) {
                const int width = std::min(thickness, end - thickness);
                copySlab(volume.id(), end - thickness - width, end - width, width);
            }
            if (fill)
                copySlab(fill->id(), 0, 0, thickness);
        }
    }
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

VoxelRegion VolumeShift::kept(const glm::ivec3& shift, int resolution)
{
    VoxelRegion shared = VoxelRegion::whole(resolution);
    for (int axis = 0; axis < 3; ++axis) {
        if (shift[axis] > 0)
            shared.hi[axis] = std::max(resolution - shift[axis], 0);
        else if (shift[axis] < 0)
            shared.lo[axis] = std::min(-shift[axis], resolution);
    }
    return shared;
}

std::vector<VoxelRegion> VolumeShift::newSlabs(const glm::ivec3& shift, int resolution)
{
    const VoxelRegion shared = kept(shift, resolution);
    std::vector<VoxelRegion> slabs;
    // What no slab took yet: each slab spans it on the axes not yet done, so the slabs do not overlap.
    VoxelRegion rest = VoxelRegion::whole(resolution);
    for (int axis = 0; axis < 3; ++axis) {
        if (shift[axis] == 0)
            continue;
        VoxelRegion slab = rest;
        if (shift[axis] > 0) {
            slab.lo[axis] = shared.hi[axis];
            rest.hi[axis] = shared.hi[axis];
        } else {
            slab.hi[axis] = shared.lo[axis];
            rest.lo[axis] = shared.lo[axis];
        }
        if (!slab.isEmpty())
            slabs.push_back(slab);
    }
    return slabs;
}

} // namespace vct::render
