// core/OccupiedCellList::assignShifted: the cells of one list (bindings 0 and 1) moved with their grid into
// another (bindings 2 and 3), so that a grid that stepped by whole voxels (core/VolumeShift) keeps naming
// every voxel it still holds without searching the grid for them again.
#include "common/OccupiedCells.glsl"
#define APPEND_BINDING 2
#include "common/AppendCell.glsl"

layout(local_size_x = 64) in;

uniform ivec3 uShift; // new index = old index - uShift
uniform ivec3 uKeptLo; // the cells to keep, after the move: [lo, hi)
uniform ivec3 uKeptHi;

void main()
{
    ivec3 cell;
    if (!occupiedCell(cell))
        return;
    ivec3 moved = cell - uShift;
    if (any(lessThan(moved, uKeptLo)) || any(greaterThanEqual(moved, uKeptHi)))
        return;
    appendCell(moved);
}
