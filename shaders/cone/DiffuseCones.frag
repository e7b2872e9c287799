// Indirect diffuse light of a traced pixel the irradiance cache does not serve (stencil PIXEL_NEEDS_CONES, set
// by cone/ClassifyPixels.frag): the diffuse cones over its hemisphere, whose weights split the cosine lobe and
// sum to one, with ambient occlusion in alpha.
#include "common/ConeMath.glsl"
#include "cone/ConeSampleCount.glsl"
#define MAX_CONES 32
#include "common/ConeTracing.glsl"
#include "cone/TracedPixel.glsl"
#include "common/GBufferSurface.glsl"

// The stencil test must reject pixels before the shader runs even in the COUNT_SAMPLES variant, whose
// atomics would otherwise make it run, and count, everywhere.
layout(early_fragment_tests) in;

layout(binding = 1) uniform usampler2D gSurface;

uniform vec3 uCameraPosition;

layout(location = 0) out vec4 oDiffuse; // rgb: sum_i w_i L_i, a: ambient visibility

void main()
{
    ivec2 pixel = tracedPixel();
    uvec4 surface = texelFetch(gSurface, pixel, 0);
    vec3 p = uCameraPosition + surfaceFromCamera(surface, pixel);
    vec3 n = surfaceNormal(surface);
    oDiffuse = gatherDiffuse(p, n);
    countSamples();
}
