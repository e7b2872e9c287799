// Turns the sums of the voxels fragments reached into averages, and zeroes those sums for the next
// voxelization: the atlas is all zeros between passes, so no pass has to clear it (a clear of the whole atlas
// costs a noticeable share of a voxelization: docs/DESIGN.md, "Measured choices"). The voxelizer listed these voxels as it reached them; the pass has already written every
// other voxel of the region (the static layer's values when merging, so a moving object never erases the
// static scene).
#include "common/OccupiedCells.glsl"
#include "common/VoxelAccumulators.glsl"

layout(local_size_x = 64) in;

layout(r32f, binding = 0) uniform image3D uAccumulators;
layout(rgba8, binding = 1) writeonly uniform image3D uAlbedoOut;
layout(rgba16f, binding = 2) writeonly uniform image3D uNormalOut;
layout(rgba16f, binding = 3) writeonly uniform image3D uEmissionOut;

uniform int uResolution;

float acc(ivec3 voxel, int slot)
{
    return imageLoad(uAccumulators, accumulatorCoord(voxel, slot, uResolution)).r;
}

void main()
{
    ivec3 voxel;
    if (!occupiedCell(voxel))
        return;
    float count = acc(voxel, ACC_COUNT);
    vec4 albedo = vec4(acc(voxel, ACC_ALBEDO_R), acc(voxel, ACC_ALBEDO_G), acc(voxel, ACC_ALBEDO_B), count) / count;
    albedo.a = 1.0;
    vec3 n = vec3(acc(voxel, ACC_NORMAL_X), acc(voxel, ACC_NORMAL_Y), acc(voxel, ACC_NORMAL_Z)) / count;
    // Opposite faces in one voxel cancel: keep the length (< 1) so lighting can tell the voxel is two-sided.
    vec4 emission = vec4(acc(voxel, ACC_EMISSION_R), acc(voxel, ACC_EMISSION_G), acc(voxel, ACC_EMISSION_B), 0.0) / count;
    for (int slot = 0; slot < ACC_SLOTS; ++slot)
        imageStore(uAccumulators, accumulatorCoord(voxel, slot, uResolution), vec4(0.0));
    imageStore(uAlbedoOut, voxel, albedo);
    imageStore(uNormalOut, voxel, vec4(n, 0.0));
    imageStore(uEmissionOut, voxel, emission);
}
