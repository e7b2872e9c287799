// Lists the cells (uCellSize^3 voxels; 1 = single voxels) of a region that hold any surface, for a heavy pass
// to run over with glDispatchComputeIndirect (core/OccupiedCellList). Heavy passes are split this way because llvmpipe runs a compute shader that
// holds lighting or cone-tracing code about four times slower per invocation even where that code is skipped
// (docs/DESIGN.md, "Measured choices"), and most of a grid is empty.
#include "common/AppendCell.glsl"
#include "common/VoxelBricks.glsl"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 8) in;

layout(binding = 0) uniform sampler3D uAlbedo; // a = opacity: a voxel holds a surface when it is above zero

uniform ivec3 uRegionOrigin; // in cells
uniform ivec3 uRegionSize;
uniform int uCellSize;

void main()
{
    if (any(greaterThanEqual(ivec3(gl_GlobalInvocationID), uRegionSize)))
        return;
    ivec3 cell = uRegionOrigin + ivec3(gl_GlobalInvocationID);
    bool occupied = false;
    for (int z = 0; z < uCellSize && !occupied; ++z)
        for (int y = 0; y < uCellSize && !occupied; ++y)
            for (int x = 0; x < uCellSize && !occupied; ++x)
                occupied = texelFetch(uAlbedo, voxelLoadTexel(cell * uCellSize + ivec3(x, y, z)), 0).a > 0.0;
    if (occupied)
        appendCell(cell);
}
