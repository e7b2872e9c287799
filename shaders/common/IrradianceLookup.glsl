// The irradiance cache's lookup (passes/VoxelIrradiancePass): the diffuse cones gathered once per surface cell
// along its own normal, interpolated for a pixel.
// Needs uGridOrigin (metres) declared before it.
#include "common/Bindings.glsl"
layout(binding = IRRADIANCE_UNIT) uniform sampler3D uIrradiance;
// rgba8 snorm: xyz the cell normal (a one-sided cell's is the mean of its voxels', shorter than one where they
// disagree), w = 0 no surface, 0.5 one-sided, 1 two-sided (half the sides, to fit snorm).
layout(binding = CELL_NORMAL_UNIT) uniform sampler3D uCellNormal;
layout(binding = IRRADIANCE_BACK_UNIT) uniform sampler3D uIrradianceBack;
uniform int uCells;         // cache cells per side
uniform float uCellSize;    // metres
#include "common/IrradianceCells.glsl"

// Trilinear over the eight cells around p, keeping only cells whose surface faces the way this pixel does (a
// mean cosine of at least one half, weighted by its fourth power), so light from the far side of a wall or a
// corner's other face does not bleed in; a two-sided cell offers whichever of its sides faces the pixel. The
// small floor on the trilinear weight lets a lone matching cell count. False when no cell nearby carries this
// surface (thin two-sided walls, sub-voxel details): the caller traces instead.
// Over any cells laid out as the cache's (`cells` per side, cellSize metres each); with `subtract`, of what
// front and back hold less what minusFront and minusBack do, with the same weights (the bounce iteration's
// higher bounces, bounce/ReinjectBounce.comp).
bool lookUpCells(sampler3D front, sampler3D back, sampler3D normals, sampler3D minusFront, sampler3D minusBack,
    bool subtract, int cells, float cellSize, vec3 p, vec3 n, out vec4 result)
{
    ivec3 base;
    vec3 f;
    irradianceCellBlock(p, uGridOrigin, cellSize, base, f);
    vec4 sum = vec4(0.0);
    float weightSum = 0.0;
    for (int i = 0; i < 8; ++i) {
        ivec3 corner = ivec3(i & 1, (i >> 1) & 1, i >> 2);
        ivec3 c = base + corner;
        if (any(lessThan(c, ivec3(0))) || any(greaterThanEqual(c, ivec3(cells))))
            continue;
        vec4 cellNormal = texelFetch(normals, c, 0);
        if (cellNormal.w <= 0.0)
            continue;
        float agreement = dot(cellNormal.xyz, n);
        bool backSide = cellNormal.w > 0.75 && agreement < 0.0;
        if (backSide)
            agreement = -agreement;
        if (agreement < 0.5)
            continue;
        vec4 cached = backSide ? texelFetch(back, c, 0) : texelFetch(front, c, 0);
        if (cached.a < 0.0)
            continue;
        if (subtract)
            cached -= backSide ? texelFetch(minusBack, c, 0) : texelFetch(minusFront, c, 0);
        vec3 t = mix(vec3(1.0) - f, f, vec3(corner));
        float a2 = agreement * agreement;
        float w = (t.x * t.y * t.z + 1e-3) * a2 * a2;
        sum += w * cached;
        weightSum += w;
    }
    if (weightSum <= 0.0)
        return false;
    result = sum / weightSum;
    return true;
}

bool lookUpIrradiance(vec3 p, vec3 n, out vec4 result)
{
    return lookUpCells(uIrradiance, uIrradianceBack, uCellNormal, uIrradiance, uIrradianceBack, false, uCells,
        uCellSize, p, n, result);
}
