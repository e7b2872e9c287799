// The heavy side of core/OccupiedCellList: one invocation per listed cell (local_size_x = 64, launched with
// glDispatchComputeIndirect). occupiedCell() returns false for the invocations past the end of the list.
layout(std430, binding = 0) readonly buffer ListedDispatch { uint uListGroupsX; uint uListGroupsY; uint uListGroupsZ; uint uListCount; };
layout(std430, binding = 1) readonly buffer ListedCells { uint uListCells[]; };

bool occupiedCell(out ivec3 cell)
{
    if (gl_GlobalInvocationID.x >= uListCount)
        return false;
    uint code = uListCells[gl_GlobalInvocationID.x];
    cell = ivec3(code & 1023u, (code >> 10) & 1023u, code >> 20);
    return true;
}
