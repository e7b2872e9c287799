// Level 0 of the opacity volume the area lights' visibility cones trace (common/AreaLights.glsl): 1 in every
// occupied voxel. Runs over the voxelizer's lists of occupied voxels; the rest of the level was cleared to 0,
// and the levels above are built from it (inject/DownsampleOpacity.comp).
#include "common/OccupiedCells.glsl"

layout(local_size_x = 64) in;

layout(rgba8, binding = 0) writeonly uniform image3D uOpacity;

void main()
{
    ivec3 voxel;
    if (!occupiedCell(voxel))
        return;
    imageStore(uOpacity, voxel, vec4(1.0));
}
