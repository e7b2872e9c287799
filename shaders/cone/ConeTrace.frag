// Indirect light per visible pixel: diffuse cones over the hemisphere (their weights split the cosine lobe,
// summing to one) and one specular cone along the mirror direction for glossy surfaces.
#include "common/ConeMath.glsl"

#define MAX_CONES 32

layout(binding = 0) uniform sampler2D gPosition;
layout(binding = 1) uniform sampler2D gNormal;
layout(binding = 3) uniform sampler2D gSpecular;
#ifdef COUNT_SAMPLES
// Benchmark-only variant (vct-bench perf, core/ConeSampleCounter.h): counts the 3D texture fetches. Each
// fragment sums its own and adds them once to a 64-bit count kept as two words, so atomics stay few.
layout(std430, binding = 0) buffer ConeSampleCount { uint uSamplesLow; uint uSamplesHigh; };
uint gSamples = 0u;
#define COUNT_FETCHES(n) gSamples += uint(n)
#endif
#include "common/ConeTracing.glsl"

uniform float uConeOffset;        // metres along the normal
uniform int uConeCount;
uniform vec4 uCones[MAX_CONES];   // tangent-space axis, w = weight
uniform float uDiffuseTanHalf;
uniform float uSpecularMinTanHalf;
uniform bool uDiffuseEnabled;
uniform bool uSpecularEnabled;
uniform vec3 uCameraPosition;
uniform int uDivisor;     // one traced pixel stands for uDivisor x uDivisor screen pixels
uniform ivec3 uFullSize;  // full-resolution width, height

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
#ifdef COUNT_SAMPLES
    uint before = atomicAdd(uSamplesLow, gSamples);
    if (before + gSamples < before) // the low word wrapped
        atomicAdd(uSamplesHigh, 1u);
#endif
}
