// The listing side of core/OccupiedCellList: appendCell() adds a cell for the heavy pass and keeps the
// indirect dispatch's workgroup count (x; y = z = 1, then the count) large enough to cover it. The list is
// bound at storage buffers APPEND_BINDING and the next (0 and 1 unless defined), so a shader can read one list
// (common/OccupiedCells.glsl) while it appends to another.
#ifndef APPEND_BINDING
#define APPEND_BINDING 0
#endif
layout(std430, binding = APPEND_BINDING) buffer OccupiedDispatch { uint uGroupsX; uint uGroupsY; uint uGroupsZ; uint uCount; };
layout(std430, binding = APPEND_BINDING + 1) writeonly buffer OccupiedCells { uint uCells[]; };

uniform uint uGroupSize; // the heavy shader's local_size_x

// Writes the cell at the index an append took.
void storeCell(uint index, ivec3 cell)
{
    uCells[index] = uint(cell.x) | (uint(cell.y) << 10) | (uint(cell.z) << 20);
    // The invocation that starts a new heavy workgroup raises the number of workgroups to include it.
    if (index % uGroupSize == 0u)
        atomicMax(uGroupsX, index / uGroupSize + 1u);
}

void appendCell(ivec3 cell)
{
    storeCell(atomicAdd(uCount, 1u), cell);
}

// appendCell() for a list with room for `capacity` cells: false, and the list as it was, where it is full.
bool appendCellWithin(ivec3 cell, uint capacity)
{
    uint index = atomicAdd(uCount, 1u);
    if (index >= capacity) {
        // Each append past the end takes back its own count, so the count ends at the cells listed.
        atomicAdd(uCount, 0xFFFFFFFFu);
        return false;
    }
    storeCell(index, cell);
    return true;
}
