// The layout of the bounce iteration's sums (passes/VoxelBouncePass), one r32f row shared by the gather, the
// tail decision and the reinjection, and read back by the renderer; defined once for GLSL and C++.
#ifndef BOUNCE_SUMS_GLSL
#define BOUNCE_SUMS_GLSL

#define BOUNCE_SUMS_PER_ITERATION 6 // the texels of one iteration, at BOUNCE_SUMS_PER_ITERATION * iteration:
#define BOUNCE_SUM_VOXEL_CHANGE 0 // sum over occupied voxels of |L - previous L| (rgb summed)
#define BOUNCE_SUM_VOXEL_TOTAL 1 // sum of L
#define BOUNCE_SUM_CELL_CHANGE 2 // sum over the bounce cells of |gathered - gathered before|
#define BOUNCE_SUM_CELL_TOTAL 3 // sum of gathered
#define BOUNCE_SUM_TAIL 4 // the tail q / (1 - q) this iteration's reinjection added, 0 for none
#define BOUNCE_SUM_TAIL_ERROR 5 // its estimated relative error, -1 where none was decided
#define BOUNCE_SUMS_ITERATIONS 64 // iterations one solve can record (RenderSettings::kMaxBounces)

#endif
