// Turns the sums into averages. With uMergeStatic, voxels the dynamic meshes touched take their values and
// the rest keep the static layer's, so a moving object never erases the static scene.
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

float acc(ivec3 voxel, int slot)
{
    return imageLoad(uAccumulators, accumulatorCoord(voxel, slot, uResolution)).r;
}

void main()
{
    if (any(greaterThanEqual(ivec3(gl_GlobalInvocationID), uRegionSize)))
        return;
    ivec3 voxel = uRegionOrigin + ivec3(gl_GlobalInvocationID);
    float count = acc(voxel, ACC_COUNT);
    vec4 albedo = vec4(0.0), normal = vec4(0.0), emission = vec4(0.0);
    if (count > 0.0) {
        albedo = vec4(acc(voxel, ACC_ALBEDO_R), acc(voxel, ACC_ALBEDO_G), acc(voxel, ACC_ALBEDO_B), count) / count;
        albedo.a = 1.0;
        vec3 n = vec3(acc(voxel, ACC_NORMAL_X), acc(voxel, ACC_NORMAL_Y), acc(voxel, ACC_NORMAL_Z)) / count;
        // Opposite faces in one voxel cancel: keep the length (< 1) so lighting can tell the voxel is two-sided.
        normal = vec4(n, 0.0);
        emission = vec4(acc(voxel, ACC_EMISSION_R), acc(voxel, ACC_EMISSION_G), acc(voxel, ACC_EMISSION_B), 0.0) / count;
    } else if (uMergeStatic) {
        albedo = texelFetch(uStaticAlbedo, voxel, 0);
        normal = texelFetch(uStaticNormal, voxel, 0);
        emission = texelFetch(uStaticEmission, voxel, 0);
    }
    imageStore(uAlbedoOut, voxel, albedo);
    imageStore(uNormalOut, voxel, normal);
    imageStore(uEmissionOut, voxel, emission);
}
