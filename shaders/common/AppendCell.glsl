// The listing side of core/OccupiedCellList: appendCell() adds a cell for the heavy pass and keeps the
// indirect dispatch's workgroup count (x; y = z = 1, then the count) large enough to cover it.
layout(std430, binding = 0) buffer OccupiedDispatch { uint uGroupsX; uint uGroupsY; uint uGroupsZ; uint uCount; };
layout(std430, binding = 1) writeonly buffer OccupiedCells { uint uCells[]; };

uniform uint uGroupSize; // the heavy shader's local_size_x

void appendCell(ivec3 cell)
{
    uint index = atomicAdd(uCount, 1u);
    uCells[index] = uint(cell.x) | (uint(cell.y) << 10) | (uint(cell.z) << 20);
    // The invocation that starts a new heavy workgroup raises the number of workgroups to include it.
    if (index % uGroupSize == 0u)
        atomicMax(uGroupsX, index / uGroupSize + 1u);
}
