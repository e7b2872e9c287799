// One step of the bounce iteration (passes/VoxelBouncePass). Each occupied voxel's outgoing radiance becomes
//   L = L_direct + albedo * sum_i w_i L_i,
// the cone weights splitting the cosine lobe (sum_i w_i L_i = E / pi, and a Lambertian surface sends
// albedo / pi * E), where sum_i w_i L_i is what the bounce cells gathered from the previous iterate
// (irradiance/GatherCells.comp over every occupied cell), looked up as a pixel looks up the irradiance cache.
// With the higher bounces on coarser cells, the bounce cells hold the gather of L_direct, and the coarser cells
// add the gather of the previous iterate less theirs of L_direct: the same sum, as the gather is linear in
// the light, with what the later bounces add gathered at their coarser scale.
// The step also sums how much the voxels changed and how bright they are: the residual that decides when the
// iteration has converged.
#extension GL_NV_shader_atomic_float : require
#include "bounce/BounceSums.glsl"
#include "common/OccupiedCells.glsl"
#include "common/VoxelBricks.glsl"
#define SUMS_BINDING 1
#include "common/GroupSums.glsl"

layout(local_size_x = 64) in;

layout(binding = 0) uniform sampler3D uAlbedo;
layout(binding = 1) uniform sampler3D uNormal;
layout(binding = 2) uniform sampler3D uDirect; // first-bounce radiance (direct light and emission), premultiplied
layout(rgba16f, binding = 0) uniform image3D uBounced; // the previous iterate in, the new one out
uniform int uIteration; // this iteration's index in the solve (bounce/BounceSums.glsl)

uniform vec3 uGridOrigin;
uniform float uVoxelSize;
uniform int uCellVoxels; // voxels per bounce cell side
uniform bool uCompare;   // the previous iterate is in uBounced (else it was just cleared)
// Each way of finding the new radiance is a program of its own (passes/VoxelBouncePass::reinject): with the
// others' lookups in the same program, left out by uniforms, each reinjection took about a third longer on
// llvmpipe (docs/BENCHMARKS.md).
// INCREMENT: the iterations after a split solve's first add to the previous iterate what its higher bounces
// changed by: uHigher and uHigherBack then hold the last gather's change (irradiance/GatherCells.comp,
// WRITE_CHANGE), and the sum above is unchanged but for rounding, as the lookups are linear in what the cells
// hold: one lookup a voxel, where the whole sum takes three (the bounce cells' gather and both higher-bounce
// gathers).
// HIGHER_BOUNCES: the whole sum adds the higher bounces' cells (passes/VoxelBouncePass), when the solve splits
// them off: their gather of the previous iterate, its cells' normals, and their gather of L_direct.
uniform int uHigherCellVoxels;
uniform int uHigherCells;
uniform float uHigherCellSize; // metres
layout(binding = 3) uniform sampler3D uHigher;
layout(binding = 4) uniform sampler3D uHigherBack;
layout(binding = 5) uniform sampler3D uHigherNormal;
layout(binding = 6) uniform sampler3D uHigherBase;
layout(binding = 7) uniform sampler3D uHigherBaseBack;

#include "common/IrradianceLookup.glsl"

// The voxel's own cell, when no cell around it faces its way. A voxel whose faces cancel (a wall thinner than a
// voxel, or two surfaces pressed together) sends the same radiance both ways, so it takes the mean of what
// reaches its two sides: that keeps the power it reflects, where the sum would send each side's light out of
// both sides and, two faces lighting each other, grow without bound from one iteration to the next.
// What the cells hold is light, never below zero, unless `change` (INCREMENT).
vec3 ownCell(sampler3D front, sampler3D back, sampler3D normals, sampler3D minusFront, sampler3D minusBack,
    bool subtract, int cellVoxels, ivec3 voxel, vec3 n, bool faced, bool change)
{
    ivec3 cell = voxel / cellVoxels;
    vec4 cellNormal = texelFetch(normals, cell, 0);
    if (cellNormal.w <= 0.0)
        return vec3(0.0);
    vec3 lowest = change ? vec3(-65504.0) : vec3(0.0);
    vec3 frontLight = texelFetch(front, cell, 0).rgb - (subtract ? texelFetch(minusFront, cell, 0).rgb : vec3(0.0));
    if (cellNormal.w < 0.75) // one-sided (common/IrradianceLookup.glsl)
        return max(frontLight, lowest);
    vec3 backLight = texelFetch(back, cell, 0).rgb - (subtract ? texelFetch(minusBack, cell, 0).rgb : vec3(0.0));
    if (!faced)
        return 0.5 * (max(frontLight, lowest) + max(backLight, lowest));
    return max(dot(n, cellNormal.xyz) >= 0.0 ? frontLight : backLight, lowest);
}

void main()
{
    ivec3 voxel;
    bool listed = occupiedCell(voxel);
    float change = 0.0, total = 0.0;
    if (listed) {
        ivec3 texel = voxelLoadTexel(voxel);
        vec4 albedo = texelFetch(uAlbedo, texel, 0);
        vec4 direct = texelFetch(uDirect, texel, 0);
        // A cold start's previous iterate is the first-bounce light (the volume was cleared before this step).
        vec3 previous = uCompare ? imageLoad(uBounced, texel).rgb : direct.rgb;
#ifdef INCREMENT
        vec4 result = vec4(previous, direct.a);
#else
        vec4 result = direct;
#endif
        if (albedo.a > 0.0 && max(albedo.r, max(albedo.g, albedo.b)) > 0.0) {
            vec3 normalSum = texelFetch(uNormal, texel, 0).xyz;
            float normalLength = length(normalSum);
            bool faced = normalLength >= 0.5;
            vec3 n = normalLength > 1e-4 ? normalSum / normalLength : vec3(0.0);
            vec3 p = uGridOrigin + (vec3(voxel) + 0.5) * uVoxelSize;
            vec4 looked;
            vec3 gathered;
#ifdef INCREMENT
            gathered = faced && lookUpCells(uHigher, uHigherBack, uHigherNormal, uHigher, uHigherBack, false,
                                    uHigherCells, uHigherCellSize, p, n, looked)
                ? looked.rgb
                : ownCell(uHigher, uHigherBack, uHigherNormal, uHigher, uHigherBack, false, uHigherCellVoxels, voxel,
                    n, faced, true);
#else
            gathered = faced && lookUpIrradiance(p, n, looked)
                ? looked.rgb
                : ownCell(uIrradiance, uIrradianceBack, uCellNormal, uIrradiance, uIrradianceBack, false,
                    uCellVoxels, voxel, n, faced, false);
#ifdef HIGHER_BOUNCES
            // Rounding can take a difference of two gathers of nearly the same light below zero.
            gathered += faced && lookUpCells(uHigher, uHigherBack, uHigherNormal, uHigherBase, uHigherBaseBack, true,
                                     uHigherCells, uHigherCellSize, p, n, looked)
                ? max(looked.rgb, vec3(0.0))
                : ownCell(uHigher, uHigherBack, uHigherNormal, uHigherBase, uHigherBaseBack, true, uHigherCellVoxels,
                    voxel, n, faced, false);
#endif
#endif
            // A change may be negative (a light dimmed); rounding must not take the sum below zero.
            result.rgb = max(result.rgb + albedo.rgb * gathered * albedo.a, vec3(0.0));
        }
        change = dot(abs(result.rgb - previous), vec3(1.0));
        total = dot(result.rgb, vec3(1.0));
        // Where bounce/DecideTail.comp found the tail q / (1 - q) trustworthy, store L + tail * change: the limit
        // of the iteration when its change shrinks by q per step. The sums above still measure the plain change.
        int at = BOUNCE_SUMS_PER_ITERATION * uIteration + BOUNCE_SUM_TAIL;
        vec3 tail = vec3(imageLoad(uSums, ivec2(at, 0)).r, imageLoad(uSums, ivec2(at + 1, 0)).r,
            imageLoad(uSums, ivec2(at + 2, 0)).r);
        if (any(greaterThan(tail, vec3(0.0))))
            result.rgb = max(result.rgb + tail * (result.rgb - previous), vec3(0.0));
        STORE_VOXEL(uBounced, voxel, result);
    }
    addGroupSums(change, total, BOUNCE_SUMS_PER_ITERATION * uIteration + BOUNCE_SUM_VOXEL_CHANGE);
}
