// Between the gather and the reinjection of one bounce iteration (passes/VoxelBouncePass), on the GPU so that
// no readback stalls the iteration: whether this reinjection should add the geometric tail.
// From one iteration to the next the change shrinks by about the same ratio q (the scene's mean albedo times
// what a gather captures; per colour channel, since coloured surfaces keep more of their own colour), so the
// changes still to come sum to the last one times q / (1 - q), the tail. The ratio is this gather's change over
// the last one's; its drift since the ratio before bounds how wrong the tail is, so the earliest iteration that
// can add it is the third. (A first ratio taken from the first bounce over
// the first-bounce light itself would allow the second, but there the change still holds light that shrinks at
// other rates in different places: the reference Cornell box with a point light then read 2% off its limit in
// a tenth of its pixels, and both it and the atrium moved further from their path-traced references.)
#include "bounce/BounceSums.glsl"

layout(local_size_x = 1) in;

layout(r32f, binding = 1) uniform image2D uSums;
uniform int uIteration; // this iteration's index in the solve, from 0
uniform float uTolerance;
uniform float uLargestRatio; // above this the solve is too slow for its tail to be trusted

float sum(int iteration, int which)
{
    return imageLoad(uSums, ivec2(BOUNCE_SUMS_PER_ITERATION * iteration + which, 0)).r;
}

vec3 cellChange(int iteration)
{
    return vec3(sum(iteration, BOUNCE_SUM_CELL_CHANGE), sum(iteration, BOUNCE_SUM_CELL_CHANGE + 1),
        sum(iteration, BOUNCE_SUM_CELL_CHANGE + 2));
}

float tailOf(float change, float before)
{
    if (before <= 0.0)
        return -1.0;
    float q = change / before;
    return q > 0.0 && q < uLargestRatio ? q / (1.0 - q) : -1.0;
}

void main()
{
    int k = uIteration;
    // Once per solve: iterating on from an extrapolated iterate corrects what the extrapolation got wrong.
    bool allowed = k >= 2 && sum(k - 1, BOUNCE_SUM_VOXEL_TOTAL) > 0.0;
    for (int i = 0; i < k; ++i)
        for (int c = 0; c < 3; ++c)
            allowed = allowed && sum(i, BOUNCE_SUM_TAIL + c) <= 0.0;
    vec3 tail = vec3(0.0);
    float error = -1.0;
    bool extrapolate = false;
    if (allowed) {
        vec3 now = cellChange(k), last = cellChange(k - 1), before = cellChange(k - 2);
        // A channel that carries next to nothing (a scene without blue light) needs no tail, and its ratio of
        // rounding noise would hold the others back.
        float largest = max(last.r, max(last.g, last.b));
        extrapolate = largest > 0.0;
        error = 0.0;
        for (int c = 0; c < 3; ++c) {
            if (last[c] <= 1e-3 * largest)
                continue;
            float t = tailOf(now[c], last[c]);
            float previousTail = tailOf(last[c], before[c]);
            if (t <= 0.0 || previousTail <= 0.0) {
                extrapolate = false;
                continue;
            }
            // This iteration's relative change of the voxels, from the last one's and the channel's ratio.
            float change = sum(k - 1, BOUNCE_SUM_VOXEL_CHANGE) / sum(k - 1, BOUNCE_SUM_VOXEL_TOTAL) * now[c] / last[c];
            error = max(error, change * abs(t - previousTail));
            tail[c] = t;
        }
        // Half the tolerance: the drift of two ratios underestimates the error while the ratio still settles
        // (a room at 32^3 ended 1.04% short of its limit at an estimate of 0.63%; tst_HardCases).
        extrapolate = extrapolate && error < 0.5 * uTolerance;
    }
    for (int c = 0; c < 3; ++c)
        imageStore(uSums, ivec2(BOUNCE_SUMS_PER_ITERATION * k + BOUNCE_SUM_TAIL + c, 0),
            vec4(extrapolate ? tail[c] : 0.0));
    imageStore(uSums, ivec2(BOUNCE_SUMS_PER_ITERATION * k + BOUNCE_SUM_TAIL_ERROR, 0), vec4(error));
}
