// The first level of all six direction-dependent chains at once (see DownsampleDirectional.comp for one
// chain): all six start from the same eight children of the isotropic level 0, so fetching them once instead
// of once per direction takes the 3D fetches of the largest directional level from 48 to 8 per texel.
// Over the listed cells only (common/OccupiedCells.glsl, VoxelMipBuilder); the level is cleared first.
#include "common/DirectionalStack.glsl"
#include "common/OccupiedCells.glsl"

layout(local_size_x = 64) in;
uniform int uTileStride; // texels from one tile's start to the next at the level written

layout(binding = 0) uniform sampler3D uSource; // premultiplied radiance, a = opacity
// The six chains' first level as tiles stacked along z: +x, -x, +y, -y, +z, -z (common/DirectionalStack.glsl).
layout(rgba16f, binding = 0) writeonly uniform image3D uTowards;

vec4 children[8]; // index x + 2y + 4z

// For a cone travelling towards +axis (positive) the lower child of each pair along the axis is in front.
vec4 composite(int axis, bool positive)
{
    vec4 sum = vec4(0.0);
    for (int i = 0; i < 8; ++i) {
        if (((i >> axis) & 1) != 0)
            continue;
        vec4 lower = children[i];
        vec4 upper = children[i | (1 << axis)];
        vec4 front = positive ? lower : upper;
        vec4 back = positive ? upper : lower;
        sum += front + (1.0 - front.a) * back;
    }
    return sum * 0.25;
}

void main()
{
    int tileSize = imageSize(uTowards).x;
    ivec3 voxel;
    if (!occupiedCell(voxel))
        return;
    for (int i = 0; i < 8; ++i)
        children[i] = texelFetch(uSource, voxel * 2 + ivec3(i & 1, (i >> 1) & 1, i >> 2), 0);
    // Spelled out, not looped: with constant arguments composite() indexes children[] statically, which
    // llvmpipe turns into registers; a loop variable made it index memory and doubled the mip pass.
    ivec3 tile = ivec3(0, 0, uTileStride); // a tile and the gap after it
    imageStore(uTowards, voxel, composite(0, true));
    imageStore(uTowards, voxel + tile, composite(0, false));
    imageStore(uTowards, voxel + 2 * tile, composite(1, true));
    imageStore(uTowards, voxel + 3 * tile, composite(1, false));
    imageStore(uTowards, voxel + 4 * tile, composite(2, true));
    imageStore(uTowards, voxel + 5 * tile, composite(2, false));
}
