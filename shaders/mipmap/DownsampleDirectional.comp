// One level of the six direction-dependent mip chains (Crassin et al.'s anisotropic voxels), all tiles of the
// stack (common/DirectionalStack.glsl) in one dispatch: for a cone travelling
// along +-axis, each pair of children along that axis is composited front to back before the four pairs are
// averaged, so a thin wall facing the cone stays opaque at coarse levels instead of fading to 1/2^k.
// One invocation per listed cell (common/OccupiedCells.glsl, VoxelMipBuilder) for all six tiles; the level is
// cleared first.
#include "common/DirectionalStack.glsl"
#include "common/OccupiedCells.glsl"

layout(local_size_x = 64) in;

layout(binding = 0) uniform sampler3D uSource; // the stack itself, read one level finer than written
layout(rgba16f, binding = 0) writeonly uniform image3D uTarget;
uniform int uSourceLevel;
uniform int uTileStride; // texels from one tile's start to the next at the level written


// Texel `voxel` of chain `tile` at the level written, tiles tileSize wide.
vec4 towards(int tile, ivec3 voxel, int tileSize)
{
    int axis = tile / 2;
    bool positive = (tile & 1) == 0; // the cone travels towards +axis, so the lower child is in front
    ivec3 along = ivec3(axis == 0, axis == 1, axis == 2);
    ivec3 u = ivec3(axis == 1, axis == 2, axis == 0);
    ivec3 v = ivec3(axis == 2, axis == 0, axis == 1);
    ivec3 base = voxel * 2 + ivec3(0, 0, 2 * uTileStride * tile); // the tile one level finer
    ivec3 frontOffset = positive ? ivec3(0) : along;
    ivec3 backOffset = positive ? along : ivec3(0);
    vec4 sum = vec4(0.0);
    for (int i = 0; i < 4; ++i) {
        ivec3 lateral = u * (i & 1) + v * (i >> 1);
        vec4 front = texelFetch(uSource, base + lateral + frontOffset, uSourceLevel);
        vec4 back = texelFetch(uSource, base + lateral + backOffset, uSourceLevel);
        sum += front + (1.0 - front.a) * back;
    }
    return sum * 0.25;
}

void main()
{
    int tileSize = imageSize(uTarget).x;
    ivec3 voxel;
    if (!occupiedCell(voxel))
        return;
    for (int tile = 0; tile < STACK_TILES; ++tile)
        imageStore(uTarget, voxel + ivec3(0, 0, uTileStride * tile), towards(tile, voxel, tileSize));
}
