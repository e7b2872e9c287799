// The g-buffer's second target (passes/GBufferPass): a pixel's shading normal and albedo in one RGBA32UI texel.
// Each extra colour target of the g-buffer cost llvmpipe ~12 ms at 1280x720, whatever its format, so the
// normal (its float bits, exact and free to pack) and the albedo (10 bits per channel, linear, with the
// front-face bit) share one.
const uint kFrontFaceBit = 1u << 30;

uvec4 packSurface(vec3 normal, vec3 albedo, bool frontFace)
{
    uvec3 a = uvec3(clamp(albedo, 0.0, 1.0) * 1023.0 + 0.5);
    return uvec4(floatBitsToUint(normal), a.r | (a.g << 10) | (a.b << 20) | (frontFace ? kFrontFaceBit : 0u));
}

vec3 surfaceNormal(uvec4 surface)
{
    return uintBitsToFloat(surface.xyz);
}

vec3 surfaceAlbedo(uvec4 surface)
{
    return vec3(uvec3(surface.w, surface.w >> 10, surface.w >> 20) & 1023u) * (1.0 / 1023.0);
}

bool surfaceFrontFace(uvec4 surface)
{
    return (surface.w & kFrontFaceBit) != 0u;
}
