// Requests the irradiance-cache cells this frame's lookups will read: one fragment per traced pixel (the
// cone pass's pixel grid) marks the eight cells around its surface point, unless they were gathered already
// for the current voxel light. irradiance/ListRequested.comp then lists the marked cells that hold voxels for
// the gather (passes/VoxelIrradiancePass), so cells no traced pixel looks at are never gathered and a camera
// move gathers only the cells that came into view.
// LIST_NEW: after a camera move, when few cells are new: the one fragment that marks a cell first also lists
// it, so the lister runs over those instead of the whole cell grid. After a light change nearly every cell
// in view is new, and listing them in grid order makes the gather faster (DESIGN.md): then they are marked only.
#include "common/GBufferSurface.glsl"
#ifdef LIST_NEW
#include "common/AppendCell.glsl"
#endif

layout(binding = 1) uniform usampler2D gSurface;
layout(r32ui, binding = 3) uniform coherent uimage3D uRequested;

uniform vec3 uGridOrigin;
uniform vec3 uCameraPosition;
uniform float uCellSize; // metres
uniform int uCellsPerSide;
uniform int uDivisor;    // one traced pixel stands for uDivisor x uDivisor screen pixels
uniform ivec3 uFullSize; // full-resolution width, height

#include "common/IrradianceCells.glsl"
#include "common/CacheBand.glsl"

void main()
{
    ivec2 pixel = min(ivec2(gl_FragCoord.xy) * uDivisor + uDivisor / 2, uFullSize.xy - 1);
    uvec4 surface = texelFetch(gSurface, pixel, 0);
    if (!surfaceExists(surface))
        return;
    vec3 position = uCameraPosition + surfaceFromCamera(surface, pixel);
    if (inCacheBand(position))
        return; // it traces its own cones
    ivec3 base;
    vec3 f;
    irradianceCellBlock(position, uGridOrigin, uCellSize, base, f);
    for (int i = 0; i < 8; ++i) {
        ivec3 c = base + ivec3(i & 1, (i >> 1) & 1, i >> 2);
        if (any(lessThan(c, ivec3(0))) || any(greaterThanEqual(c, ivec3(uCellsPerSide))))
            continue;
#ifdef LIST_NEW
        // The plain load first: after a camera move nearly every cell is known already, and atomics cost.
        if (imageLoad(uRequested, c).r == CELL_NOT_REQUESTED
            && imageAtomicCompSwap(uRequested, c, CELL_NOT_REQUESTED, CELL_GATHERED) == CELL_NOT_REQUESTED)
            appendCell(c);
#else
        // Pixels racing for one cell all store the same value.
        if (imageLoad(uRequested, c).r == CELL_NOT_REQUESTED)
            imageStore(uRequested, c, uvec4(CELL_REQUESTED));
#endif
    }
}
