// Lists the cells requested this frame (irradiance/RequestCells.frag) that hold voxels, for the gather to run
// over (core/OccupiedCellList), and marks every requested cell gathered. Listing in grid order over 8^3 work
// groups, rather than appending from the pixels that request them, keeps cells without voxels out of the
// gather: there they would still take a lane of the gather's SIMD groups (atrium: 9,265 requested cells,
// 5,508 with voxels; gather 150 -> 89 ms).
#include "common/AppendCell.glsl"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 8) in;

layout(binding = 0) uniform sampler3D uAlbedo; // a = opacity: a voxel holds a surface when it is above zero
layout(r32ui, binding = 3) uniform coherent uimage3D uRequested;

uniform ivec3 uRegionOrigin; // in cells
uniform ivec3 uRegionSize;
uniform int uCellSize;       // voxels per cell side

#include "common/IrradianceCells.glsl"

void main()
{
    if (any(greaterThanEqual(ivec3(gl_GlobalInvocationID), uRegionSize)))
        return;
    ivec3 cell = uRegionOrigin + ivec3(gl_GlobalInvocationID);
    if (imageLoad(uRequested, cell).r != CELL_REQUESTED)
        return;
    imageStore(uRequested, cell, uvec4(CELL_GATHERED));
    bool occupied = false;
    for (int z = 0; z < uCellSize && !occupied; ++z)
        for (int y = 0; y < uCellSize && !occupied; ++y)
            for (int x = 0; x < uCellSize && !occupied; ++x)
                occupied = texelFetch(uAlbedo, cell * uCellSize + ivec3(x, y, z), 0).a > 0.0;
    if (occupied)
        appendCell(cell);
}
