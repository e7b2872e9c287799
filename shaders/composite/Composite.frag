// The frame's linear radiance: emission + shadowed direct light + albedo * indirect diffuse
// + specular * indirect specular. Tone mapping happens later, only for 8-bit output.
//
// A compile-time variant per frame shape and pixel class (passes/CompositePass): light counts, which terms are
// on, the debug view, whether the indirect light needs upsampling and what the pixel's material has are
// defines, not uniforms, so each shader carries only the code its pixels use (llvmpipe pays for code behind
// any branch; see common/PixelClass.glsl). Each variant is drawn with a stencil test for its pixel class;
// pixels with no surface keep the cleared black.
//   POINT_LIGHT_COUNT, DIRECTIONAL_LIGHT_COUNT  analytic lights (common/Lights.glsl)
//   AREA_LIGHT_COUNT  emitters lit as area lights (common/AreaLights.glsl)
//   DIRECT, INDIRECT_DIFFUSE, INDIRECT_SPECULAR  the terms present this frame
//   GLOSSY    the material has a specular lobe (PIXEL_GLOSSY)
//   EMISSION  the material emits (PIXEL_EMISSIVE) and emission is on
//   UPSAMPLE  the diffuse grid is 1/uDivisor of the screen per axis
//   SPECULAR_UPSAMPLE  the specular grid is 1/uSpecularDivisor of the screen per axis
//   AREA_UPSAMPLE  the area lights' shadow grid is 1/uAreaDivisor of the screen per axis
//   VIEW      RenderSettings::view (0 = the final image)
//   AO_AVAILABLE  the cone pass computed ambient occlusion
#include "common/Lights.glsl"
#include "common/AreaLights.glsl"
#include "common/Bindings.glsl"
#include "common/MaterialTable.glsl"
#include "common/GBufferSurface.glsl"

layout(early_fragment_tests) in;

layout(binding = 1) uniform usampler2D gSurface;
layout(binding = 5) uniform sampler2D uIndirectDiffuse;
layout(binding = 6) uniform sampler2D uIndirectSpecular; // at the specular grid
layout(binding = 7) uniform sampler2D uIndirectGuide;    // ScreenTargets::indirectGuide
layout(binding = 10) uniform sampler2D uSpecularGuide;   // ScreenTargets::specularGuide
layout(binding = 2) uniform sampler2D uAreaShadow;       // ScreenTargets::areaShadow, at the indirect grid
layout(binding = 4) uniform sampler2D uAreaShadowGuide;  // ScreenTargets::areaShadowGuide

uniform vec3 uCameraPosition;
uniform float uVoxelSize; // metres: the upsampler weighs distances from a surface in voxels
uniform float uAreaShadowOffset; // metres along the normal where area-light shadow cones start
uniform int uDivisor;         // the diffuse grid's
uniform int uSpecularDivisor; // the specular grid's
uniform int uAreaDivisor;     // the area lights' shadow grid's

#include "composite/Upsampling.glsl"

layout(location = 0) out vec4 oRadiance;

const float kPi = 3.14159265358979;

void main()
{
    // The stencil test let only pixels of this variant's class through: there is a surface here.
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    uvec4 surface = texelFetch(gSurface, pixel, 0);
    vec3 fromCamera = surfaceFromCamera(surface, pixel);
    vec3 p = uCameraPosition + fromCamera;
    vec3 n = surfaceNormal(surface);
    vec3 albedo = surfaceAlbedo(surface);
#if defined(GLOSSY) || defined(EMISSION)
    MaterialEntry material = materialAt(surfaceMaterial(surface));
#endif
#ifdef GLOSSY
    float shininess = material.specularShininess.w;
    vec3 specular = material.specularShininess.rgb;
#endif

    vec4 indirectDiffuse = vec4(0.0, 0.0, 0.0, 1.0);
#if defined(INDIRECT_DIFFUSE) || VIEW == 4
#ifdef UPSAMPLE
    indirectDiffuse = upsampled(uIndirectDiffuse, upsamplingTaps(uIndirectGuide, uDivisor, pixel, fromCamera, n));
#else
    indirectDiffuse = texelFetch(uIndirectDiffuse, pixel, 0);
#endif
#endif
    vec3 indirectSpecular = vec3(0.0);
#if defined(INDIRECT_SPECULAR) && defined(GLOSSY)
#ifdef SPECULAR_UPSAMPLE
    indirectSpecular = upsampled(uIndirectSpecular, upsamplingTaps(uSpecularGuide, uSpecularDivisor, pixel, fromCamera, n)).rgb;
#else
    indirectSpecular = texelFetch(uIndirectSpecular, pixel, 0).rgb;
#endif
#endif

    vec3 direct = vec3(0.0);
#if defined(DIRECT) && (VIEW == 0 || VIEW == 1)
#ifdef GLOSSY
    vec3 mirror = reflect(normalize(fromCamera), n);
#endif
    // One loop per light kind, each with its compile-time count: a loop over both kinds branched on the index,
    // and llvmpipe ran the directional light's code for every pixel of a scene that has none.
    for (int i = 0; i < kPointLightCount; ++i) {
        vec3 d = uPointLightPosition[i].xyz - p;
        // A floor only at the light itself, relative to the scene as every bias is: an absolute one would bend
        // the light of a scene measured in 1e-4 units (tests/hardcases, scale invariance).
        float distance2 = max(dot(d, d), uPointShadowNear * uPointShadowNear);
        vec3 toLight = normalize(d);
        float cosTheta = max(dot(n, toLight), 0.0);
        vec3 irradiance = uPointLightIntensity[i].rgb * spotFactor(i, p) / distance2
            * pointLightVisibility(i, pointShadowOrigin(i, p, n), n) * cosTheta;
        vec3 brdf = albedo / kPi;
#ifdef GLOSSY // normalised modified Phong
        brdf += specular * (shininess + 2.0) / (2.0 * kPi) * pow(max(dot(mirror, toLight), 0.0), shininess);
#endif
        direct += brdf * irradiance;
    }
    for (int i = 0; i < kDirectionalLightCount; ++i) {
        vec3 toLight = -normalize(uDirectionalLightDirection[i].xyz);
        float cosTheta = max(dot(n, toLight), 0.0);
        vec3 irradiance = uDirectionalLightIrradiance[i].rgb * directionalLightVisibility(i, directionalShadowOrigin(i, p, n), n) * cosTheta;
        vec3 brdf = albedo / kPi;
#ifdef GLOSSY
        brdf += specular * (shininess + 2.0) / (2.0 * kPi) * pow(max(dot(mirror, toLight), 0.0), shininess);
#endif
        direct += brdf * irradiance;
    }
    // Area lights: the Lambertian lobe exactly, the glossy lobe by its fitted cosines (common/AreaLights.glsl). The
    // shadow cone starts where the cones of indirect light do, clear of the surface's own voxels.
    if (kAreaLightCount > 0) {
        // Exact unshadowed light per pixel, times the share of it the shadow cones let through, traced on a
        // grid of their own (passes/AreaLightPass) and upsampled like indirect light: cone-traced shadows vary
        // slowly, the irradiance's own gradient near a light need not.
#ifdef AREA_UPSAMPLE
        vec4 areaShadow = upsampled(uAreaShadow, upsamplingTaps(uAreaShadowGuide, uAreaDivisor, pixel, fromCamera, n));
#else
        vec4 areaShadow = texelFetch(uAreaShadow, pixel, 0);
#endif
        direct += albedo / kPi * areaLightUnshadowed(p, n) * areaShadow.rgb;
#ifdef GLOSSY
        direct += specular * areaLightSpecular(p, n, -normalize(fromCamera), shininess) * areaShadow.a;
#endif
    }
#endif
    vec3 diffuseIndirect = vec3(0.0);
#ifdef INDIRECT_DIFFUSE
    diffuseIndirect = albedo * indirectDiffuse.rgb;
#endif
    vec3 specularIndirect = vec3(0.0);
#if defined(INDIRECT_SPECULAR) && defined(GLOSSY)
    specularIndirect = specular * indirectSpecular;
#endif
    vec3 emitted = vec3(0.0);
#ifdef EMISSION
    emitted = surfaceFrontFace(surface) ? material.emission.rgb : vec3(0.0);
#endif

#if VIEW == 0
    vec3 result = emitted + direct + diffuseIndirect + specularIndirect;
#elif VIEW == 1
    vec3 result = direct;
#elif VIEW == 2
    vec3 result = diffuseIndirect;
#elif VIEW == 3
    vec3 result = specularIndirect;
#elif VIEW == 4
#ifdef AO_AVAILABLE
    vec3 result = vec3(indirectDiffuse.a);
#else
    vec3 result = vec3(1.0);
#endif
#elif VIEW == 5
    vec3 result = albedo;
#elif VIEW == 6
    vec3 result = n * 0.5 + 0.5;
#else
    vec3 result = emitted;
#endif
    oRadiance = vec4(result, 1.0);
}
