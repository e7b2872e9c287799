// Two sums over a work group of 64 invocations, added to two neighbouring texels of uSums with one atomic add
// each per group instead of one per invocation. Every invocation of the group must call addGroupSums (it has
// barriers). Needs GL_NV_shader_atomic_float, and SUMS_BINDING defined before the include.
layout(r32f, binding = SUMS_BINDING) uniform image2D uSums;

shared float sGroupFirst[64];
shared float sGroupSecond[64];

void addGroupSums(float first, float second, int texel)
{
    sGroupFirst[gl_LocalInvocationIndex] = first;
    sGroupSecond[gl_LocalInvocationIndex] = second;
    barrier();
    for (uint stride = 32u; stride > 0u; stride >>= 1u) {
        if (gl_LocalInvocationIndex < stride) {
            sGroupFirst[gl_LocalInvocationIndex] += sGroupFirst[gl_LocalInvocationIndex + stride];
            sGroupSecond[gl_LocalInvocationIndex] += sGroupSecond[gl_LocalInvocationIndex + stride];
        }
        barrier();
    }
    if (gl_LocalInvocationIndex == 0u) {
        imageAtomicAdd(uSums, ivec2(texel, 0), sGroupFirst[0]);
        imageAtomicAdd(uSums, ivec2(texel + 1, 0), sGroupSecond[0]);
    }
}
