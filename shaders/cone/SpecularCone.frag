// Indirect specular light of a glossy pixel of the specular grid (stencil PIXEL_GLOSSY, set by
// cone/ClassifyPixels.frag): one cone along the mirrored view direction, as wide as the material's Phong lobe.
#include "common/ConeMath.glsl"
#include "cone/ConeSampleCount.glsl"
#include "common/ConeTracing.glsl"
#include "cone/TracedPixel.glsl"
#include "common/GBufferSurface.glsl"
#include "common/Bindings.glsl"
#include "common/MaterialTable.glsl"

// The stencil test must reject pixels before the shader runs even in the COUNT_SAMPLES variant, whose
// atomics would otherwise make it run, and count, everywhere.
layout(early_fragment_tests) in;

layout(binding = 1) uniform usampler2D gSurface;

uniform float uSpecularMinTanHalf;
uniform vec3 uCameraPosition;

layout(location = 0) out vec4 oSpecular;

void main()
{
    ivec2 pixel = tracedPixel();
    uvec4 surface = texelFetch(gSurface, pixel, 0);
    vec3 fromCamera = surfaceFromCamera(surface, pixel);
    vec3 n = surfaceNormal(surface);
    float shininess = materialAt(surfaceMaterial(surface)).specularShininess.w;
    vec3 mirror = reflect(normalize(fromCamera), n);
    // Half-angle where the Phong lobe cos^n falls to one half, never narrower than the set minimum.
    float lobeHalf = acos(pow(0.5, 1.0 / max(shininess, 1e-3)));
    float tanHalf = max(tan(min(lobeHalf, 1.5)), uSpecularMinTanHalf);
    float unused;
    oSpecular = vec4(traceSurfaceCone(uCameraPosition + fromCamera, n, mirror, tanHalf, max(dot(mirror, n), 0.05), unused).rgb, 1.0);
    countSamples();
}
