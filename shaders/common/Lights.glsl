// Analytic lights with shadow maps, shared by voxel injection and the per-pixel composite.
// Units: point intensity W/sr, directional irradiance W/m^2; results are irradiance (W/m^2) or radiance.
#define MAX_POINT_LIGHTS 8
#define MAX_DIRECTIONAL_LIGHTS 4
#define POINT_SHADOW_UNIT 8
#define DIRECTIONAL_SHADOW_UNIT 9

// Compile-time light counts (POINT_LIGHT_COUNT, DIRECTIONAL_LIGHT_COUNT: the composite and injection variants):
// with a loop per kind and a count known to the compiler, llvmpipe unrolls each loop and drops the code of a
// kind the scene does not have. A loop over both kinds that branches on the index ran every kind's code in
// every lane instead (the atrium's composite 89 -> 58 ms).
#define kPointLightCount POINT_LIGHT_COUNT
#define kDirectionalLightCount DIRECTIONAL_LIGHT_COUNT
uniform vec4 uPointLightPosition[MAX_POINT_LIGHTS];  // w = 1 when it casts shadows
uniform vec4 uPointLightIntensity[MAX_POINT_LIGHTS]; // w: the cosine of a spot's inner angle (-1: not a spot)
uniform vec4 uPointLightSpot[MAX_POINT_LIGHTS];      // a spot's axis, w: the cosine of its outer angle (-2: none)
uniform float uPointShadowNear;
uniform float uPointShadowFar;
uniform vec4 uDirectionalLightDirection[MAX_DIRECTIONAL_LIGHTS]; // travel direction, w = shadows
uniform vec4 uDirectionalLightIrradiance[MAX_DIRECTIONAL_LIGHTS];
uniform mat4 uDirectionalLightMatrix[MAX_DIRECTIONAL_LIGHTS];
// Comparison samplers (gl::Texture::setDepthComparison): each lookup is the bilinear average of the four nearest
// texels' depth tests, so shadow edges are texel-area averages, as a reference image's are, not steps.
layout(binding = POINT_SHADOW_UNIT) uniform samplerCubeArrayShadow uPointShadow;
layout(binding = DIRECTIONAL_SHADOW_UNIT) uniform sampler2DArrayShadow uDirectionalShadow;

// The share of point light i's intensity sent toward p: 1 for an isotropic light; for a spot, a smoothstep in
// the cosine from its outer to its inner angle (scene/PointLight.h::spotFactor, the same function).
float spotFactor(int i, vec3 p)
{
    float outer = uPointLightSpot[i].w, inner = uPointLightIntensity[i].w;
    float c = dot(normalize(p - uPointLightPosition[i].xyz), uPointLightSpot[i].xyz);
    if (inner - outer <= 1e-6)
        return c >= outer ? 1.0 : 0.0;
    float t = clamp((c - outer) / (inner - outer), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

// p is already pushed off the surface by the caller; the bias absorbs depth quantisation only.
float pointLightVisibility(int i, vec3 p)
{
    if (uPointLightPosition[i].w < 0.5)
        return 1.0;
    vec3 fromLight = p - uPointLightPosition[i].xyz;
    // The face that holds this direction is the one of its largest component; its view depth is that
    // component, and the stored window depth inverts to it through the face's perspective projection.
    vec3 a = abs(fromLight);
    float viewDepth = max(a.x, max(a.y, a.z));
    float n = uPointShadowNear;
    float f = uPointShadowFar;
    // The bias is in view depth (it absorbs depth quantisation only); the face's perspective projection then
    // turns the biased depth into the window depth the map stores.
    float biased = max(viewDepth - 1e-3 * f, n);
    float reference = f * (biased - n) / (biased * (f - n));
    return texture(uPointShadow, vec4(fromLight, float(i)), reference);
}

float directionalLightVisibility(int i, vec3 p)
{
    if (uDirectionalLightDirection[i].w < 0.5)
        return 1.0;
    vec4 clip = uDirectionalLightMatrix[i] * vec4(p, 1.0);
    vec3 coord = clip.xyz / clip.w * 0.5 + 0.5;
    if (any(lessThan(coord.xy, vec2(0.0))) || any(greaterThan(coord.xy, vec2(1.0))))
        return 1.0;
    return texture(uDirectionalShadow, vec4(coord.xy, float(i), coord.z - 2e-3));
}
