// The area lights' shadows on the indirect grid (passes/AreaLightPass): for the full-resolution pixel each
// traced pixel stands for, the share of its unshadowed area-light irradiance that the shadow cones let
// through (common/AreaLights.glsl), and its tangent plane for the composite's upsampling.
#include "common/GBufferSurface.glsl"
#include "common/AreaLights.glsl"
#include "cone/TracedPixel.glsl"

layout(binding = 1) uniform usampler2D gSurface;
uniform vec3 uCameraPosition;
uniform float uAreaShadowOffset; // metres along the normal where the shadow cones start

// rgb: the share of the unshadowed irradiance let through, per channel (the lights differ in colour and in
// shadow); a: the same over all channels, for the glossy lobe. 1 where nothing is lit.
layout(location = 0) out vec4 oShadow;
layout(location = 1) out vec4 oGuide;  // the traced pixel's tangent plane: normal, offset from the camera; 0 = none

void main()
{
    ivec2 pixel = tracedPixel();
    uvec4 surface = texelFetch(gSurface, pixel, 0);
    if (!surfaceExists(surface)) {
        oShadow = vec4(1.0);
        oGuide = vec4(0.0);
        return;
    }
    vec3 n = surfaceNormal(surface);
    vec3 fromCamera = surfaceFromCamera(surface, pixel);
    vec3 p = uCameraPosition + fromCamera;
    vec3 unshadowed, shadowed;
    areaLightIrradiance(p, n, uAreaShadowOffset, unshadowed, shadowed);
    float total = dot(unshadowed, vec3(1.0));
    vec3 share = vec3(1.0);
    for (int c = 0; c < 3; ++c)
        share[c] = unshadowed[c] > 0.0 ? clamp(shadowed[c] / unshadowed[c], 0.0, 1.0) : 1.0;
    oShadow = vec4(share, total > 0.0 ? clamp(dot(shadowed, vec3(1.0)) / total, 0.0, 1.0) : 1.0);
    oGuide = vec4(n, dot(fromCamera, n));
}
