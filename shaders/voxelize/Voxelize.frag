// Voxelizes one fragment of a projected triangle (Voxelize.geom): its material goes into the voxels of its
// pixel's column (voxelize/VoxelColumn.glsl).
// Variants (passes/VoxelizePass::voxelizer): EMISSIVE for emissive materials (other materials leave the emission
// word alone unless it holds light, so most fragments skip its compare-and-swap); EMISSION_VOLUME when the scene
// has emissive materials (passes/VoxelizePass::ensureEmission), so that the grid has an emission word at all;
// CONSERVATIVE when the geometry shader enlarged the triangle (clipped here to its pixel bounds); TEXTURED for
// materials with an albedo texture (the others skip the fetch, as the g-buffer's do).
in vec3 gNormal;
in vec2 gUv;
flat in int gAxis;
flat in vec4 gPixelBounds;
flat in float gDepthSlope;
noperspective in float gDepth;

uniform int uResolution;
uniform vec3 uAlbedo;
#ifdef EMISSIVE
uniform vec3 uEmission;
#endif
#ifdef TEXTURED
layout(binding = 0) uniform sampler2D uAlbedoTexture;
#endif
uniform ivec3 uRegionLo; // voxels outside [lo, hi) are being kept
uniform ivec3 uRegionHi;

#include "voxelize/ProjectTriangle.glsl"
#include "voxelize/VoxelColumn.glsl"

void main()
{
#ifdef CONSERVATIVE
    if (gl_FragCoord.x < gPixelBounds.x || gl_FragCoord.y < gPixelBounds.y || gl_FragCoord.x > gPixelBounds.z
        || gl_FragCoord.y > gPixelBounds.w)
        discard;
    float spread = gDepthSlope;
#else
    float spread = 0.0;
#endif
#ifdef TEXTURED
    vec3 albedo = uAlbedo * texture(uAlbedoTexture, gUv).rgb;
#else
    vec3 albedo = uAlbedo;
#endif
    vec3 normal = gNormal;
    float len = length(normal);
    normal = len > 1e-20 ? normal / len : vec3(0.0);
#ifdef EMISSIVE
    vec3 emission = uEmission;
#else
    vec3 emission = vec3(0.0);
#endif
    addToColumn(ivec2(gl_FragCoord.xy), gDepth, spread, gAxis, albedo, normal, emission);
}
