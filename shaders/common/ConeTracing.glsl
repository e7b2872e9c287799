// How far, in footprints, a cone's samples keep from the tangent plane of the surface it leaves (traceCone).
// 1.5 measured best of 1 (no effect on 30-degree cones), 1.5, 3 and rays (docs/DESIGN.md).
#define CLEARANCE 1.5
// Tracing one cone through the radiance volume, shared by the per-pixel cone passes (cone/DiffuseCones.frag,
// cone/SpecularCone.frag), the irradiance cache's gather and the per-voxel bounce gather
// (bounce/GatherBounce.comp), so all see the volume the same way.
// A shader that counts texture fetches defines COUNT_FETCHES(n) before including this file.
#ifndef COUNT_FETCHES
#define COUNT_FETCHES(n)
#endif

layout(binding = 5) uniform sampler3D uRadiance;
#ifdef ANISOTROPIC
// Direction-dependent mips (RenderSettings::anisotropicMips): level k here is grid level k + 1.
// A compile-time variant, not a uniform branch: llvmpipe ran both sides of the branch and the plain
// path cost six times as much.
// The six chains are tiles of one texture stacked along z (+x, -x, +y, -y, +z, -z; VoxelVolume::directional),
// empty gaps between (common/DirectionalStack.glsl): a cone picks its side of each axis by coordinate. With six
// samplers, picking per pixel fetched from both sides of every axis: the cone pass took 1.7 times as long
// (docs/DESIGN.md, "Measured choices").
#include "common/DirectionalStack.glsl"
layout(binding = 6) uniform sampler3D uTowards;
uniform vec2 uStack; // in tiles: from one tile's start to the next, and the stack's depth

// Chain `tile` at uvw (in the grid's [0, 1]^3) and level l; the gaps read as the border a texture of its own has.
vec4 sampleTowards(int tile, vec3 uvw, float l)
{
    uvw.z = (uvw.z + uStack.x * float(tile)) / uStack.y;
    return textureLod(uTowards, uvw, l);
}
#endif

uniform vec3 uGridOrigin;
uniform float uGridExtent;
uniform float uVoxelSize;
uniform float uMaxLevel;
uniform float uStepFactor;
uniform float uMaxDistance;
uniform bool uAoEnabled;          // accumulate occlusion only when the AO view shows it
uniform float uAoDistance;        // occluders beyond this count half
uniform float uConeOffset;        // metres: where cones start along the surface normal

const int kMaxSteps = 256;

// The volume as a cone travelling along dir sees it at a (fractional) mip level.
vec4 sampleVolume(vec3 uvw, float level, vec3 dir)
{
#ifndef ANISOTROPIC
    COUNT_FETCHES(1);
    return textureLod(uRadiance, uvw, level);
#else
    // Level 0 and the three directional chains are fetched at every step, and blended by the level: llvmpipe
    // runs both sides of a branch on the level anyway, and written as a branch it fetched level 0 twice
    // (five fetches a step where four do; the cone loop ~20% faster).
    COUNT_FETCHES(4);
    vec4 finest = textureLod(uRadiance, uvw, 0.0);
    vec3 w = dir * dir; // sums to one for a unit direction
    float l = max(level - 1.0, 0.0);
    vec4 directional = w.x * sampleTowards(dir.x > 0.0 ? 0 : 1, uvw, l)
        + w.y * sampleTowards(dir.y > 0.0 ? 2 : 3, uvw, l)
        + w.z * sampleTowards(dir.z > 0.0 ? 4 : 5, uvw, l);
    return mix(finest, directional, clamp(level, 0.0, 1.0));
#endif
}

// Front-to-back compositing along one cone; returns premultiplied radiance and opacity. The cone starts
// `clearOffset` metres off a surface it leaves at cosine `clearCos` to its normal; its footprint stays within
// 1 / CLEARANCE of its height above that surface's tangent plane, so that coarse lookups gather less of the
// surface the cone starts from. A cone leaving at a low angle thus narrows.
vec4 traceCone(vec3 origin, vec3 dir, float tanHalf, float clearCos, float clearOffset, out float occlusion)
{
    vec3 color = vec3(0.0);
    float alpha = 0.0;
    occlusion = 0.0;
    float t = uVoxelSize;
    for (int step = 0; step < kMaxSteps && t < uMaxDistance && alpha < 0.99; ++step) {
        float d = min(coneDiameter(t, tanHalf), max((clearOffset + t * clearCos) / CLEARANCE, uVoxelSize));
        float level = coneMipLevel(d, uVoxelSize, uMaxLevel);
        vec3 uvw = (origin + t * dir - uGridOrigin) / uGridExtent;
        if (any(lessThan(uvw, vec3(0.0))) || any(greaterThan(uvw, vec3(1.0))))
            break;
        float stepLength = coneStepLength(d, uVoxelSize, uStepFactor);
        vec4 s = sampleVolume(uvw, level, dir);
        if (s.a > 1e-4) {
            float a = correctOpacity(s.a, stepLength, uVoxelSize * exp2(level));
            color += (1.0 - alpha) * s.rgb * (a / s.a);
            if (uAoEnabled)
                occlusion += (1.0 - alpha) * a / (1.0 + t / uAoDistance);
            alpha += (1.0 - alpha) * a;
        }
        t += stepLength;
    }
    return vec4(color, alpha);
}

// Orthonormal basis around n without a branch on a reference axis (Duff et al. 2017).
void tangentBasis(vec3 n, out vec3 t, out vec3 b)
{
    float s = n.z >= 0.0 ? 1.0 : -1.0;
    float a = -1.0 / (s + n.z);
    float c = n.x * n.y * a;
    t = vec3(1.0 + s * n.x * n.x * a, s * c, -s * n.x);
    b = vec3(c, s + n.y * n.y * a, -n.y);
}

#ifdef MAX_CONES
// The diffuse cone set (core/ConeSet): tangent-space axes whose weights split the cosine lobe, summing to one.
uniform int uConeCount;
uniform vec4 uCones[MAX_CONES]; // tangent-space axis, w = weight
uniform float uDiffuseTanHalf;

// The diffuse cones around n from origin: rgb = sum_i w_i L_i (irradiance / pi), a = ambient visibility.
vec4 gatherDiffuse(vec3 origin, vec3 n)
{
    vec3 t, b;
    tangentBasis(n, t, b);
    vec3 sum = vec3(0.0);
    float occlusion = 0.0;
    for (int i = 0; i < uConeCount; ++i) {
        vec3 axis = uCones[i].xyz;
        vec3 dir = normalize(t * axis.x + b * axis.y + n * axis.z);
        float coneOcclusion;
        sum += uCones[i].w * traceCone(origin, dir, uDiffuseTanHalf, max(axis.z, 0.05), uConeOffset, coneOcclusion).rgb;
        occlusion += uCones[i].w * coneOcclusion;
    }
    return vec4(sum, clamp(1.0 - occlusion, 0.0, 1.0));
}
#endif
