// The g-buffer (passes/GBufferPass): one RGBA32UI texel per pixel. Each colour target of the g-buffer costs
// llvmpipe the same whatever its format (docs/DESIGN.md), so everything a pixel's shading needs shares one:
//   x  shading normal facing the camera, octahedral, two 16-bit snorms
//   y  linear albedo, 10 bits per channel, and the front-face bit
//   z  material index + 1 (the material table, common/MaterialTable.glsl); 0 = no surface, the sky
//   w  view depth (float bits): the surface's distance along the camera's forward axis, in metres
// The world position is rebuilt from the pixel and the view depth (surfacePosition), exactly enough: the
// depth is stored as the float the rasteriser interpolated, and the ray runs through the pixel centre the
// g-buffer sampled. Needs uCameraPosition, and uPixelToRay for surfacePosition (FrameContext::pixelToRay).
const uint kFrontFaceBit = 1u << 30;

uint packNormal(vec3 n)
{
    n /= abs(n.x) + abs(n.y) + abs(n.z);
    vec2 e = n.z >= 0.0 ? n.xy : (1.0 - abs(n.yx)) * vec2(n.x >= 0.0 ? 1.0 : -1.0, n.y >= 0.0 ? 1.0 : -1.0);
    return packSnorm2x16(e);
}

vec3 unpackNormal(uint bits)
{
    vec2 e = unpackSnorm2x16(bits);
    vec3 n = vec3(e, 1.0 - abs(e.x) - abs(e.y));
    float t = max(-n.z, 0.0);
    n.xy += vec2(n.x >= 0.0 ? -t : t, n.y >= 0.0 ? -t : t);
    return normalize(n);
}

uvec4 packSurface(vec3 normal, vec3 albedo, bool frontFace, int materialIndex, float viewDepth)
{
    uvec3 a = uvec3(clamp(albedo, 0.0, 1.0) * 1023.0 + 0.5);
    return uvec4(packNormal(normal), a.r | (a.g << 10) | (a.b << 20) | (frontFace ? kFrontFaceBit : 0u),
        uint(materialIndex + 1), floatBitsToUint(viewDepth));
}

bool surfaceExists(uvec4 surface)
{
    return surface.z != 0u;
}

vec3 surfaceNormal(uvec4 surface)
{
    return unpackNormal(surface.x);
}

vec3 surfaceAlbedo(uvec4 surface)
{
    return vec3(uvec3(surface.y, surface.y >> 10, surface.y >> 20) & 1023u) * (1.0 / 1023.0);
}

bool surfaceFrontFace(uvec4 surface)
{
    return (surface.y & kFrontFaceBit) != 0u;
}

// The material index + 1, as materialAt() (common/MaterialTable.glsl) takes it.
float surfaceMaterial(uvec4 surface)
{
    return float(surface.z);
}

#ifndef GBUFFER_WRITER
uniform mat3 uPixelToRay; // full-resolution pixel (x, y, 1) to the world-space ray with unit forward component

// The surface point seen through full-resolution pixel `pixel`, relative to the camera.
vec3 surfaceFromCamera(uvec4 surface, ivec2 pixel)
{
    return uPixelToRay * vec3(vec2(pixel) + 0.5, 1.0) * uintBitsToFloat(surface.w);
}
#endif
