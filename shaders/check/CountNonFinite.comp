// Counts texels of one level holding NaN or Inf in any channel: the stability checks run it over every
// render target and every voxel level. VOLUME selects a 3D texture, otherwise a 2D one.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

#ifdef VOLUME
layout(binding = 0) uniform sampler3D uSource;
#else
layout(binding = 0) uniform sampler2D uSource;
#endif
layout(std430, binding = 0) buffer Counter { uint count; };
uniform int uLevel;

void main()
{
#ifdef VOLUME
    ivec3 size = textureSize(uSource, uLevel);
    ivec3 texel = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(texel, size)))
        return;
    vec4 v = texelFetch(uSource, texel, uLevel);
#else
    ivec2 size = textureSize(uSource, uLevel);
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (gl_GlobalInvocationID.z > 0u || any(greaterThanEqual(texel, size)))
        return;
    vec4 v = texelFetch(uSource, texel, uLevel);
#endif
    if (any(isnan(v)) || any(isinf(v)))
        atomicAdd(count, 1u);
}
