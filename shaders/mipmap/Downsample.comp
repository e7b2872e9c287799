// One mip level from the one below: the mean of the 2x2x2 children (a box filter of premultiplied radiance
// and opacity, which is what a wider cone sees), over the listed cells (common/OccupiedCells.glsl,
// VoxelMipBuilder); the level is cleared first.
#include "common/OccupiedCells.glsl"

layout(local_size_x = 64) in;

layout(binding = 0) uniform sampler3D uSource;
layout(rgba16f, binding = 0) writeonly uniform image3D uTarget;
uniform int uSourceLevel;

void main()
{
    ivec3 voxel;
    if (!occupiedCell(voxel))
        return;
    ivec3 base = voxel * 2;
    vec4 sum = vec4(0.0);
    for (int i = 0; i < 8; ++i)
        sum += texelFetch(uSource, base + ivec3(i & 1, (i >> 1) & 1, i >> 2), uSourceLevel);
    imageStore(uTarget, voxel, sum * 0.125);
}
