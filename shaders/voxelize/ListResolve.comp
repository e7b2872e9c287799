// First half of the resolve: voxels no fragment reached this time take the static layer's values (when
// merging a dynamic layer over it) or nothing, and the touched ones are listed for Resolve.comp to average
// (core/OccupiedCellList: a heavy shader over the whole grid costs several times more per voxel on llvmpipe).
#include "common/AppendCell.glsl"
#include "common/VoxelAccumulators.glsl"

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(r32f, binding = 0) readonly uniform image3D uAccumulators;
layout(rgba8, binding = 1) writeonly uniform image3D uAlbedoOut;
layout(rgba16f, binding = 2) writeonly uniform image3D uNormalOut;
layout(rgba16f, binding = 3) writeonly uniform image3D uEmissionOut;
layout(binding = 0) uniform sampler3D uStaticAlbedo;
layout(binding = 1) uniform sampler3D uStaticNormal;
layout(binding = 2) uniform sampler3D uStaticEmission;

uniform int uResolution;
uniform bool uMergeStatic;
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
