// Two sums over a work group of 64 invocations, added to two neighbouring texels of uSums with one atomic add
// each per group instead of one per invocation. Every invocation of the group must call addGroupSums (it has a
// barrier). Needs GL_NV_shader_atomic_float, and SUMS_BINDING defined before the include.
layout(r32f, binding = SUMS_BINDING) uniform image2D uSums;

shared float sGroupFirst[64];
shared float sGroupSecond[64];

void addGroupSums(float first, float second, int texel)
{
    sGroupFirst[gl_LocalInvocationIndex] = first;
    sGroupSecond[gl_LocalInvocationIndex] = second;
    barrier();
    // One invocation adds the 64 up: a tree of halving strides took a barrier per level, and llvmpipe pays
    // for each barrier in every invocation of the group (docs/BENCHMARKS.md, "The bounce solve's cheaper steps").
    if (gl_LocalInvocationIndex == 0u) {
        float firstSum = 0.0, secondSum = 0.0;
        for (int i = 0; i < 64; ++i) {
            firstSum += sGroupFirst[i];
            secondSum += sGroupSecond[i];
        }
        imageAtomicAdd(uSums, ivec2(texel, 0), firstSum);
        imageAtomicAdd(uSums, ivec2(texel + 1, 0), secondSum);
    }
}
