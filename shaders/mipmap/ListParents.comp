// Lists the cells one mip level up from a listed level (common/OccupiedCells.glsl, at storage buffers 0 and 1):
// each parent once, however many of its eight children are listed, marked by uLevelBit in uListed. The
// directional mips then filter only the cells that hold anything (VoxelMipBuilder), and clear the rest.
#define APPEND_BINDING 2
#include "common/AppendCell.glsl"
#include "common/OccupiedCells.glsl"

layout(local_size_x = 64) in;

layout(r32ui, binding = 0) uniform coherent uimage3D uListed; // cells of level 1 and coarser, one bit per level
uniform uint uLevelBit;

void main()
{
    ivec3 child;
    if (!occupiedCell(child))
        return;
    ivec3 parent = child >> 1;
    // A plain load first: most parents were listed already by a sibling, and atomics cost.
    if ((imageLoad(uListed, parent).r & uLevelBit) == 0u && (imageAtomicOr(uListed, parent, uLevelBit) & uLevelBit) == 0u)
        appendCell(parent);
}
