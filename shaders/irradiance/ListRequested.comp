// Lists the cells requested this frame (irradiance/RequestCells.frag) that hold voxels, for the gather to run
// over (core/OccupiedCellList). Cells without voxels stay out of the gather: there they would still take a
// lane of its SIMD groups (docs/DESIGN.md, "Measured choices").
// Over the whole cell grid in 8^3 work groups, marking every requested cell gathered, which lists the cells
// in grid order; with FROM_LIST over the cells the request pass listed itself (its LIST_NEW variant, common/
// OccupiedCells.glsl), which costs nothing when a camera move brings few new cells into view.
#ifdef FROM_LIST
#define APPEND_BINDING 2
#include "common/OccupiedCells.glsl"
layout(local_size_x = 64) in;
#else
layout(local_size_x = 8, local_size_y = 8, local_size_z = 8) in;
#endif
#include "common/AppendCell.glsl"
#include "common/VoxelBricks.glsl"

layout(binding = 0) uniform sampler3D uAlbedo; // a = opacity: a voxel holds a surface when it is above zero
layout(r32ui, binding = 3) uniform coherent uimage3D uRequested;

uniform ivec3 uRegionOrigin; // in cells
uniform ivec3 uRegionSize;
uniform int uCellSize;       // voxels per cell side

#include "common/IrradianceCells.glsl"

void main()
{
#ifdef FROM_LIST
    ivec3 cell;
    if (!occupiedCell(cell))
        return;
#else
    if (any(greaterThanEqual(ivec3(gl_GlobalInvocationID), uRegionSize)))
        return;
    ivec3 cell = uRegionOrigin + ivec3(gl_GlobalInvocationID);
    if (imageLoad(uRequested, cell).r != CELL_REQUESTED)
        return;
    imageStore(uRequested, cell, uvec4(CELL_GATHERED));
#endif
    bool occupied = false;
    for (int z = 0; z < uCellSize && !occupied; ++z)
        for (int y = 0; y < uCellSize && !occupied; ++y)
            for (int x = 0; x < uCellSize && !occupied; ++x)
                occupied = texelFetch(uAlbedo, voxelLoadTexel(cell * uCellSize + ivec3(x, y, z)), 0).a > 0.0;
    if (occupied)
        appendCell(cell);
}
