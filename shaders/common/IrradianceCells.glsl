// The eight irradiance-cache cells a lookup at world position p interpolates between
// (common/IrradianceLookup.glsl), computed in one place so the cells requested for this frame
// (irradiance/RequestCells.frag) are exactly the cells its lookups read. Corner i of the block is
// base + (i & 1, (i >> 1) & 1, i >> 2); f is the trilinear position inside the block. gridOrigin in metres, cellSize in metres per cell.
void irradianceCellBlock(vec3 p, vec3 gridOrigin, float cellSize, out ivec3 base, out vec3 f)
{
    vec3 g = (p - gridOrigin) / cellSize - 0.5;
    base = ivec3(floor(g));
    f = g - vec3(base);
}

// States of a cell in VoxelVolume::irradianceRequested.
#define CELL_NOT_REQUESTED 0u
#define CELL_GATHERED 1u  // for the current voxel light, or found empty
#define CELL_REQUESTED 2u // by this frame's pixels, not gathered yet
