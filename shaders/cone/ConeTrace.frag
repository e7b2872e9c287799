// Indirect light per visible pixel: diffuse cones over the hemisphere (their weights split the cosine lobe,
// summing to one) and one specular cone along the mirror direction for glossy surfaces.
#include "common/ConeMath.glsl"
#define MATERIAL_TABLE_UNIT 3
#include "common/MaterialTable.glsl"

#define MAX_CONES 32

layout(binding = 0) uniform sampler2D gPosition;
layout(binding = 1) uniform sampler2D gNormal;
#ifdef COUNT_SAMPLES
// Benchmark-only variant (vct-bench perf, core/ConeSampleCounter.h): counts the 3D texture fetches. Each
// fragment sums its own and adds them once to a 64-bit count kept as two words, so atomics stay few.
layout(std430, binding = 0) buffer ConeSampleCount { uint uSamplesLow; uint uSamplesHigh; };
uint gSamples = 0u;
#define COUNT_FETCHES(n) gSamples += uint(n)
#endif
#include "common/ConeTracing.glsl"

uniform float uConeOffset;        // metres along the normal
uniform float uSpecularMinTanHalf;
uniform bool uDiffuseEnabled;
uniform bool uSpecularEnabled;
uniform vec3 uCameraPosition;
uniform int uDivisor;     // one traced pixel stands for uDivisor x uDivisor screen pixels
uniform ivec3 uFullSize;  // full-resolution width, height

#ifdef IRRADIANCE_CACHE
// passes/VoxelIrradiancePass: the diffuse cones gathered once per surface voxel along its own normal.
layout(binding = 12) uniform sampler3D uIrradiance;
layout(binding = 13) uniform sampler3D uCellNormal; // w: 0 none, 1 one-sided, 2 two-sided
layout(binding = 14) uniform sampler3D uIrradianceBack;
uniform int uCells;         // cache cells per side
uniform float uCellSize;    // metres
#include "common/IrradianceCells.glsl"

// Trilinear over the eight cells around p, keeping only cells whose surface faces the way this pixel does
// (within 60 degrees, weighted by cos^4), so light from the far side of a wall or a corner's other face does
// not bleed in; a two-sided cell offers whichever of its sides faces the pixel. The small floor on the trilinear weight lets a lone matching cell count. False when no
// cell nearby carries this surface (thin two-sided walls, sub-voxel details): the caller traces instead.
bool lookUpIrradiance(vec3 p, vec3 n, out vec4 result)
{
    ivec3 base;
    vec3 f;
    irradianceCellBlock(p, uGridOrigin, uCellSize, base, f);
    vec4 sum = vec4(0.0);
    float weightSum = 0.0;
    for (int i = 0; i < 8; ++i) {
        ivec3 corner = ivec3(i & 1, (i >> 1) & 1, i >> 2);
        ivec3 c = base + corner;
        if (any(lessThan(c, ivec3(0))) || any(greaterThanEqual(c, ivec3(uCells))))
            continue;
        vec4 cellNormal = texelFetch(uCellNormal, c, 0);
        if (cellNormal.w <= 0.0)
            continue;
        float agreement = dot(cellNormal.xyz, n);
        bool back = cellNormal.w > 1.5 && agreement < 0.0;
        agreement = abs(agreement);
        if (agreement < 0.5)
            continue;
        vec4 cached = back ? texelFetch(uIrradianceBack, c, 0) : texelFetch(uIrradiance, c, 0);
        if (cached.a < 0.0)
            continue;
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
#endif

layout(location = 0) out vec4 oDiffuse;  // rgb: sum_i w_i L_i, a: ambient visibility
layout(location = 1) out vec4 oSpecular;

void main()
{
    // Trace from the centre pixel of the block this low-resolution pixel covers; composite upsamples.
    ivec2 pixel = min(ivec2(gl_FragCoord.xy) * uDivisor + uDivisor / 2, uFullSize.xy - 1);
    vec4 position = texelFetch(gPosition, pixel, 0);
    oDiffuse = vec4(0.0, 0.0, 0.0, 1.0);
    oSpecular = vec4(0.0);
    if (position.a <= 0.0)
        return;
    vec3 n = texelFetch(gNormal, pixel, 0).xyz;
    vec3 origin = position.xyz + n * uConeOffset;

    if (uDiffuseEnabled) {
#ifdef IRRADIANCE_CACHE
        if (!lookUpIrradiance(position.xyz, n, oDiffuse))
            oDiffuse = gatherDiffuse(origin, n);
#else
        oDiffuse = gatherDiffuse(origin, n);
#endif
    }
    MaterialEntry material = materialAt(position.a);
    float shininess = material.specularShininess.w;
    vec3 specular = material.specularShininess.rgb;
    if (uSpecularEnabled && shininess > 0.0 && max(specular.r, max(specular.g, specular.b)) > 0.0) {
        vec3 view = normalize(position.xyz - uCameraPosition);
        vec3 mirror = reflect(view, n);
        // Half-angle where the Phong lobe cos^n falls to one half, never narrower than the set minimum.
        float lobeHalf = acos(pow(0.5, 1.0 / max(shininess, 1e-3)));
        float tanHalf = max(tan(min(lobeHalf, 1.5)), uSpecularMinTanHalf);
        float unused;
        oSpecular = vec4(traceCone(origin, mirror, tanHalf, unused).rgb, 1.0);
    }
#ifdef COUNT_SAMPLES
    uint before = atomicAdd(uSamplesLow, gSamples);
    if (before + gSamples < before) // the low word wrapped
        atomicAdd(uSamplesHigh, 1u);
#endif
}
