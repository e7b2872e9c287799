in vec3 vWorld;
in vec3 vNormal;
in vec2 vUv;

// TEXTURED: the variant for materials with an albedo texture (passes/GBufferPass); the others skip the fetch,
// which cost an untextured g-buffer a fifth of its time (docs/DESIGN.md, "Measured choices").
#define GBUFFER_WRITER
#include "common/GBufferSurface.glsl"

uniform vec3 uAlbedo;
uniform int uMaterialIndex; // into the material table (common/MaterialTable.glsl): specular, emission
uniform vec3 uCameraPosition;
uniform vec3 uCameraForward; // unit
#ifdef TEXTURED
layout(binding = 0) uniform sampler2D uAlbedoTexture;
#endif

layout(location = 0) out uvec4 oSurface; // common/GBufferSurface.glsl

void main()
{
    // Vertex normals are unit length (core/GpuScene); between opposite ones the interpolated normal can vanish,
    // and then the pixel faces the camera rather than carrying a NaN the packed target could not show.
    vec3 n = vNormal * inversesqrt(dot(vNormal, vNormal));
    if (!(abs(n.x) + abs(n.y) + abs(n.z) > 0.5))
        n = normalize(uCameraPosition - vWorld);
    // Surfaces are shaded from the side the camera sees; emission is one-sided (front faces only).
    if (!gl_FrontFacing)
        n = -n;
#ifdef TEXTURED
    vec3 albedo = uAlbedo * texture(uAlbedoTexture, vUv).rgb;
#else
    vec3 albedo = uAlbedo;
#endif
    oSurface = packSurface(n, albedo, gl_FrontFacing, uMaterialIndex, dot(vWorld - uCameraPosition, uCameraForward));
}
