// Adds this fragment's material to every voxel its pixel column crosses; the resolve pass divides by count,
// so overlapping fragments average instead of the last one winning. The first fragment to reach a voxel lists
// it (core/OccupiedCellList) for the resolve and, after a full rebuild, for light injection: no pass has to
// search the grid for the voxels drawn.
// EMISSIVE: the variant for emissive materials (passes/VoxelizePass). The atomics are most of this pass's
// cost on llvmpipe, and other materials add nothing to the emission sums, so they skip those three.
#extension GL_NV_shader_atomic_float : require
#include "common/VoxelAccumulators.glsl"
#include "common/AppendCell.glsl"

in vec3 gNormal;
in vec2 gUv;
flat in int gAxis;
flat in vec4 gPixelBounds;
flat in float gDepthSlope;

uniform int uResolution;
uniform bool uConservative;
uniform vec3 uAlbedo;
#ifdef EMISSIVE
uniform vec3 uEmission;
#endif
layout(binding = 0) uniform sampler2D uAlbedoTexture;
layout(r32f, binding = 0) uniform coherent image3D uAccumulators;
uniform ivec3 uRegionLo; // voxels outside [lo, hi) are being kept: their sums were not cleared
uniform ivec3 uRegionHi;

ivec3 unswizzle(ivec3 c, int axis)
{
    return axis == 0 ? c.zxy : (axis == 1 ? c.yzx : c.xyz);
}

void add(ivec3 voxel, int slot, float value)
{
    imageAtomicAdd(uAccumulators, accumulatorCoord(voxel, slot, uResolution), value);
}

void main()
{
    if (uConservative
        && (gl_FragCoord.x < gPixelBounds.x || gl_FragCoord.y < gPixelBounds.y || gl_FragCoord.x > gPixelBounds.z
            || gl_FragCoord.y > gPixelBounds.w))
        discard;
    vec3 albedo = uAlbedo * texture(uAlbedoTexture, gUv).rgb;
    vec3 normal = gNormal;
    float len = length(normal);
    normal = len > 1e-20 ? normal / len : vec3(0.0);

    float depth = gl_FragCoord.z * float(uResolution);
    float spread = uConservative ? gDepthSlope : 0.0;
    int first = max(int(floor(depth - spread)), 0);
    int last = min(int(floor(depth + spread)), uResolution - 1);
    for (int z = first; z <= last; ++z) {
        ivec3 voxel = unswizzle(ivec3(ivec2(gl_FragCoord.xy), z), gAxis);
        if (any(lessThan(voxel, uRegionLo)) || any(greaterThanEqual(voxel, uRegionHi)))
            continue;
        if (imageAtomicAdd(uAccumulators, accumulatorCoord(voxel, ACC_COUNT, uResolution), 1.0) == 0.0)
            appendCell(voxel);
        add(voxel, ACC_ALBEDO_R, albedo.r);
        add(voxel, ACC_ALBEDO_G, albedo.g);
        add(voxel, ACC_ALBEDO_B, albedo.b);
        add(voxel, ACC_NORMAL_X, normal.x);
        add(voxel, ACC_NORMAL_Y, normal.y);
        add(voxel, ACC_NORMAL_Z, normal.z);
#ifdef EMISSIVE
        add(voxel, ACC_EMISSION_R, uEmission.r);
        add(voxel, ACC_EMISSION_G, uEmission.g);
        add(voxel, ACC_EMISSION_B, uEmission.b);
#endif
    }
}
