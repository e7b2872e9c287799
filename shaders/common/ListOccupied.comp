// Lists the cells (uCellSize^3 voxels; 1 = single voxels) of a region that hold any surface, for a heavy pass
// to run over with glDispatchComputeIndirect (core/OccupiedCellList), and optionally writes uClearValue into
// uClearTarget at the empty ones. Heavy passes are split this way because llvmpipe runs a compute shader that
// holds lighting or cone-tracing code about four times slower per invocation even where that code is skipped
// (light injection on the atrium: 183 ms for the grid in one shader, 54 ms without the lighting code), and
// most of a grid is empty.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(binding = 0) uniform sampler3D uAlbedo; // a = opacity: a voxel holds a surface when it is above zero
layout(rgba16f, binding = 0) writeonly uniform image3D uClearTarget;
// x = workgroups of the heavy dispatch, then y and z = 1 (DispatchIndirectCommand), then the count.
layout(std430, binding = 0) buffer Dispatch { uint uGroupsX; uint uGroupsY; uint uGroupsZ; uint uCount; };
layout(std430, binding = 1) writeonly buffer Occupied { uint uCells[]; };

uniform ivec3 uRegionOrigin; // in cells
uniform ivec3 uRegionSize;
uniform int uCellSize;
uniform bool uClear;
uniform vec4 uClearValue;
uniform uint uGroupSize; // the heavy shader's local_size_x

void main()
{
    if (any(greaterThanEqual(ivec3(gl_GlobalInvocationID), uRegionSize)))
        return;
    ivec3 cell = uRegionOrigin + ivec3(gl_GlobalInvocationID);
    bool occupied = false;
    for (int z = 0; z < uCellSize && !occupied; ++z)
        for (int y = 0; y < uCellSize && !occupied; ++y)
            for (int x = 0; x < uCellSize && !occupied; ++x)
                occupied = texelFetch(uAlbedo, cell * uCellSize + ivec3(x, y, z), 0).a > 0.0;
    if (!occupied) {
        if (uClear)
            imageStore(uClearTarget, cell, uClearValue);
        return;
    }
    uint index = atomicAdd(uCount, 1u);
    uCells[index] = uint(cell.x) | (uint(cell.y) << 10) | (uint(cell.z) << 20);
    // The invocation that starts a new heavy workgroup raises the number of workgroups to include it.
    if (index % uGroupSize == 0u)
        atomicMax(uGroupsX, index / uGroupSize + 1u);
}
