// First half of the resolve: lists the voxels fragments reached for Resolve.comp to average (the pass has
// already cleared the region, or copied the static layer into it when merging a dynamic layer over it).
// core/OccupiedCellList: a heavy shader over the whole grid costs several times more per voxel on llvmpipe.
#include "common/AppendCell.glsl"
#include "common/VoxelAccumulators.glsl"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 8) in;

layout(r32f, binding = 0) readonly uniform image3D uAccumulators;

uniform int uResolution;
uniform ivec3 uRegionOrigin; // only the region a moving object touched is resolved
uniform ivec3 uRegionSize;

void main()
{
    if (any(greaterThanEqual(ivec3(gl_GlobalInvocationID), uRegionSize)))
        return;
    ivec3 voxel = uRegionOrigin + ivec3(gl_GlobalInvocationID);
    if (imageLoad(uAccumulators, accumulatorCoord(voxel, ACC_COUNT, uResolution)).r > 0.0)
        appendCell(voxel);
}
