// Marks the voxels the voxelizer reached as done (common/VoxelWords.glsl): albedo's count becomes 255, read as
// opacity 1, and normal's becomes 0, which samplers read as w = 0. The emission word needs nothing. The
// voxelizer listed these voxels as it reached them.
#include "common/OccupiedCells.glsl"
#include "common/VoxelBricks.glsl"

layout(local_size_x = 64) in;

layout(r32ui, binding = 0) uniform uimage3D uAlbedoWords;
layout(r32ui, binding = 1) uniform uimage3D uNormalWords;

void main()
{
    ivec3 voxel;
    if (!occupiedCell(voxel))
        return;
    ivec3 texel = voxelStoreTexel(voxel);
    imageAtomicOr(uAlbedoWords, texel, 0xFF000000u);
    imageAtomicAnd(uNormalWords, texel, 0x00FFFFFFu);
}
