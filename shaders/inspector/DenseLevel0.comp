// A sparse grid's level 0 (common/VoxelBricks.glsl) written out as a dense volume, for the inspector's box
// levels, readVoxels and the NaN check's view of the cone volume (Renderer's ensureInspectionMips): a dense
// grid copies its level 0 instead.
#include "common/VoxelBricks.glsl"

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(binding = 0) uniform sampler3D uPool;
layout(rgba16f, binding = 0) writeonly uniform image3D uDense;

void main()
{
    ivec3 voxel = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(voxel, imageSize(uDense))))
        return;
    imageStore(uDense, voxel, texelFetch(uPool, voxelLoadTexel(voxel), 0));
}
