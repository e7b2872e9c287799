// The first of the cone passes over a grid of traced pixels (passes/ConeTracePass): sorts them into stencil
// classes (common/PixelClass.glsl) so that the cone shaders run only where they are needed and writes the
// composite's upsampling guide (the traced surface's tangent plane). On the diffuse grid it takes indirect
// diffuse light from the irradiance cache (IRRADIANCE_CACHE) and marks the pixels the cache cannot serve, or
// every pixel without a cache, PIXEL_NEEDS_CONES for cone/DiffuseCones.frag; on the specular grid
// (SPECULAR_GRID) it marks the glossy pixels PIXEL_GLOSSY for cone/SpecularCone.frag.
#extension GL_ARB_shader_stencil_export : require
#include "common/PixelClass.glsl"
#include "common/GBufferSurface.glsl"
#include "common/Bindings.glsl"
#include "common/MaterialTable.glsl"
#include "cone/TracedPixel.glsl"

layout(binding = 1) uniform usampler2D gSurface;

uniform vec3 uGridOrigin;
uniform vec3 uCameraPosition;
#ifndef SPECULAR_GRID
uniform bool uDiffuseEnabled;
#endif

#if defined(IRRADIANCE_CACHE) && !defined(SPECULAR_GRID)
#include "common/IrradianceLookup.glsl"
#include "common/CacheBand.glsl"
#endif

#ifndef SPECULAR_GRID
layout(location = 0) out vec4 oDiffuse; // rgb: sum_i w_i L_i, a: ambient visibility
#endif
layout(location = 1) out vec4 oGuide;   // the traced pixel's tangent plane: normal, offset from the camera; 0 = none

void main()
{
    ivec2 pixel = tracedPixel();
    uvec4 surface = texelFetch(gSurface, pixel, 0);
    vec3 n = surfaceNormal(surface);
    vec3 fromCamera = surfaceFromCamera(surface, pixel);
    bool geometry = surfaceExists(surface);
    uint pixelClass = geometry ? PIXEL_GEOMETRY : 0u;
#ifdef SPECULAR_GRID
    MaterialEntry material = materialAt(max(surfaceMaterial(surface), 1.0));
    float shininess = material.specularShininess.w;
    vec3 specular = material.specularShininess.rgb;
    if (geometry && shininess > 0.0 && max(specular.r, max(specular.g, specular.b)) > 0.0)
        pixelClass |= PIXEL_GLOSSY;
#else
    oDiffuse = vec4(0.0, 0.0, 0.0, 1.0);
    bool needsCones = geometry && uDiffuseEnabled;
#ifdef IRRADIANCE_CACHE
    vec4 cached;
    vec3 p = uCameraPosition + fromCamera;
    if (needsCones && !inCacheBand(p) && lookUpIrradiance(p, n, cached)) {
        oDiffuse = cached;
        needsCones = false;
    }
#endif
    if (needsCones)
        pixelClass |= PIXEL_NEEDS_CONES;
#endif
    // Relative to the camera, so the offset keeps its precision in a scene far from the origin.
    oGuide = geometry ? vec4(n, dot(fromCamera, n)) : vec4(0.0);
    gl_FragStencilRefARB = int(pixelClass);
}
