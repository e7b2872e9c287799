// The layout of the bounce iteration's sums (passes/VoxelBouncePass), one r32f row shared by the gather, the
// tail decision and the reinjection, and read back by the renderer; defined once for GLSL and C++.
#ifndef BOUNCE_SUMS_GLSL
#define BOUNCE_SUMS_GLSL

#define BOUNCE_SUMS_PER_ITERATION 10 // the texels of one iteration, at BOUNCE_SUMS_PER_ITERATION * iteration:
#define BOUNCE_SUM_VOXEL_CHANGE 0 // sum over occupied voxels of |L - previous L| (rgb summed)
#define BOUNCE_SUM_VOXEL_TOTAL 1 // sum of L
// Per colour channel (three texels, r g b): light of each colour shrinks at its own ratio where the surfaces'
// colours differ (a red wall keeps more red), and one ratio for all left the red of a room 1.25% short.
#define BOUNCE_SUM_CELL_CHANGE 2 // sum over the bounce cells of |gathered - gathered before|, r g b
#define BOUNCE_SUM_CELL_TOTAL 5 // sum of gathered (rgb summed)
#define BOUNCE_SUM_TAIL 6 // the tail q / (1 - q) this iteration's reinjection added per channel, r g b; 0 for none
#define BOUNCE_SUM_TAIL_ERROR 9 // its estimated error (largest channel), -1 before one can be estimated
#define BOUNCE_SUMS_ITERATIONS 64 // iterations one solve can record (RenderSettings::kMaxBounces)

#endif
