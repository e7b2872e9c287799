// COUNT_SAMPLES: the benchmark-only variant of the cone shaders (vct-bench perf, debug/ConeSampleCounter.h)
// counts their 3D texture fetches. Each fragment sums its own and adds them once to a 64-bit count kept as
// two words, so atomics stay few. Include before common/ConeTracing.glsl; call countSamples() at the end.
#ifdef COUNT_SAMPLES
layout(std430, binding = 0) buffer ConeSampleCount { uint uSamplesLow; uint uSamplesHigh; };
uint gSamples = 0u;
#define COUNT_FETCHES(n) gSamples += uint(n)
#endif

void countSamples()
{
#ifdef COUNT_SAMPLES
    uint before = atomicAdd(uSamplesLow, gSamples);
    if (before + gSamples < before) // the low word wrapped
        atomicAdd(uSamplesHigh, 1u);
#endif
}
