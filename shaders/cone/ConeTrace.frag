// Indirect light per visible pixel: diffuse cones over the hemisphere (their weights split the cosine lobe,
// summing to one) and one specular cone along the mirror direction for glossy surfaces.
#include "common/ConeMath.glsl"

#define MAX_CONES 32

layout(binding = 0) uniform sampler2D gPosition;
layout(binding = 1) uniform sampler2D gNormal;
layout(binding = 3) uniform sampler2D gSpecular;
layout(binding = 5) uniform sampler3D uRadiance;
#ifdef ANISOTROPIC
// Direction-dependent mips (RenderSettings::anisotropicMips): level k here is grid level k + 1.
// A compile-time variant, not a uniform branch: llvmpipe ran both sides of the branch and the plain
// path cost six times as much.
layout(binding = 6) uniform sampler3D uTowardsPosX;
layout(binding = 7) uniform sampler3D uTowardsNegX;
layout(binding = 8) uniform sampler3D uTowardsPosY;
layout(binding = 9) uniform sampler3D uTowardsNegY;
layout(binding = 10) uniform sampler3D uTowardsPosZ;
layout(binding = 11) uniform sampler3D uTowardsNegZ;
#endif

uniform vec3 uGridOrigin;
uniform float uGridExtent;
uniform float uVoxelSize;
uniform float uMaxLevel;
uniform float uStepFactor;
uniform float uMaxDistance;
uniform float uConeOffset;        // metres along the normal
uniform int uConeCount;
uniform vec4 uCones[MAX_CONES];   // tangent-space axis, w = weight
uniform float uDiffuseTanHalf;
uniform float uSpecularMinTanHalf;
uniform bool uDiffuseEnabled;
uniform bool uSpecularEnabled;
uniform bool uAoEnabled;          // accumulate occlusion only when the AO view shows it
uniform float uAoDistance;        // occluders beyond this count half
uniform vec3 uCameraPosition;
uniform int uDivisor;     // one traced pixel stands for uDivisor x uDivisor screen pixels
uniform ivec3 uFullSize;  // full-resolution width, height

layout(location = 0) out vec4 oDiffuse;  // rgb: sum_i w_i L_i, a: ambient visibility
layout(location = 1) out vec4 oSpecular;

const int kMaxSteps = 256;

// The volume as a cone travelling along dir sees it at a (fractional) mip level.
vec4 sampleVolume(vec3 uvw, float level, vec3 dir)
{
#ifndef ANISOTROPIC
    return textureLod(uRadiance, uvw, level);
#else
    if (level <= 0.0)
        return textureLod(uRadiance, uvw, level);
    vec3 w = dir * dir; // sums to one for a unit direction
    float l = max(level - 1.0, 0.0);
    vec4 directional = w.x * (dir.x > 0.0 ? textureLod(uTowardsPosX, uvw, l) : textureLod(uTowardsNegX, uvw, l))
        + w.y * (dir.y > 0.0 ? textureLod(uTowardsPosY, uvw, l) : textureLod(uTowardsNegY, uvw, l))
        + w.z * (dir.z > 0.0 ? textureLod(uTowardsPosZ, uvw, l) : textureLod(uTowardsNegZ, uvw, l));
    return level < 1.0 ? mix(textureLod(uRadiance, uvw, 0.0), directional, level) : directional;
#endif
}

// Front-to-back compositing along one cone; returns premultiplied radiance and opacity.
vec4 traceCone(vec3 origin, vec3 dir, float tanHalf, out float occlusion)
{
    vec3 color = vec3(0.0);
    float alpha = 0.0;
    occlusion = 0.0;
    float t = uVoxelSize;
    for (int step = 0; step < kMaxSteps && t < uMaxDistance && alpha < 0.99; ++step) {
        float d = coneDiameter(t, tanHalf);
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

void main()
{
    // Trace from the centre pixel of the block this low-resolution pixel covers; composite upsamples.
    ivec2 pixel = min(ivec2(gl_FragCoord.xy) * uDivisor + uDivisor / 2, uFullSize.xy - 1);
    vec4 position = texelFetch(gPosition, pixel, 0);
    oDiffuse = vec4(0.0, 0.0, 0.0, 1.0);
    oSpecular = vec4(0.0);
    if (position.a <= 0.0)
        return;
    vec4 normalShininess = texelFetch(gNormal, pixel, 0);
    vec3 n = normalShininess.xyz;
    vec3 origin = position.xyz + n * uConeOffset;

    if (uDiffuseEnabled) {
        vec3 t, b;
        tangentBasis(n, t, b);
        vec3 sum = vec3(0.0);
        float occlusion = 0.0;
        for (int i = 0; i < uConeCount; ++i) {
            vec3 axis = uCones[i].xyz;
            vec3 dir = normalize(t * axis.x + b * axis.y + n * axis.z);
            float coneOcclusion;
            sum += uCones[i].w * traceCone(origin, dir, uDiffuseTanHalf, coneOcclusion).rgb;
            occlusion += uCones[i].w * coneOcclusion;
        }
        oDiffuse = vec4(sum, clamp(1.0 - occlusion, 0.0, 1.0));
    }
    float shininess = normalShininess.w;
    vec3 specular = texelFetch(gSpecular, pixel, 0).rgb;
    if (uSpecularEnabled && shininess > 0.0 && max(specular.r, max(specular.g, specular.b)) > 0.0) {
        vec3 view = normalize(position.xyz - uCameraPosition);
        vec3 mirror = reflect(view, n);
        // Half-angle where the Phong lobe cos^n falls to one half, never narrower than the set minimum.
        float lobeHalf = acos(pow(0.5, 1.0 / max(shininess, 1e-3)));
        float tanHalf = max(tan(min(lobeHalf, 1.5)), uSpecularMinTanHalf);
        float unused;
        oSpecular = vec4(traceCone(origin, mirror, tanHalf, unused).rgb, 1.0);
    }
}
