// The irradiance cache (passes/VoxelIrradiancePass): one gather of the diffuse cones per requested cell of
// uCellSize^3 voxels (irradiance/RequestCells.frag lists the cells this frame's lookups read). The cones start
// where a pixel's would, from the mean position of the cell's surface voxels, and what they gather,
// sum_i w_i L_i, is stored with the ambient visibility in alpha. Irradiance varies slowly over a surface, so
// a 2^3 cell costs far less than a gather per pixel and pixels interpolate between cells.
// A wall thinner than a voxel has both faces in the same voxels, whose normals then cancel: such a cell
// gathers both sides of the axis along which its neighbours are emptiest (the wall's normal for walls
// along the grid axes, within 45 degrees otherwise), so that pixels on either face find their light.
// The back sides are gathered apart: this shader lists the two-sided cells (storage buffers 2 and 3), and a
// second dispatch of it with BACK_SIDES (and CACHED_GEOMETRY) runs over that list alone. Gathered in the same
// invocation, a back side cost every cell of a group where one cell had one: llvmpipe runs a loop's body for
// all lanes while any lane needs it (docs/BENCHMARKS.md, "Back sides gathered apart").
#ifdef CHANGE_SUMS
#extension GL_NV_shader_atomic_float : require
#endif
#include "common/ConeMath.glsl"

#define MAX_CONES 32
#include "common/ConeTracing.glsl"

// Runs over the requested cells (core/OccupiedCellList); a requested cell without voxels is marked empty.
#include "common/OccupiedCells.glsl"
#ifndef BACK_SIDES
#define APPEND_BINDING 2
#include "common/AppendCell.glsl"
uniform uint uBackSideCapacity; // room in the list of back sides; a cell past it gathers its back side here
#endif

layout(local_size_x = 64) in;

layout(binding = 0) uniform sampler3D uAlbedo;
layout(binding = 1) uniform sampler3D uNormal;
#ifdef CHANGE_SUMS
// The bounce iteration (passes/VoxelBouncePass) also sums how much each gather changed from the one before, and
// the gathers themselves, into its row of sums (bounce/BounceSums.glsl): the ratio between two iterations'
// changes is how fast the iteration converges (bounce/DecideTail.comp).
#include "bounce/BounceSums.glsl"
#define SUMS_BINDING 3
#include "common/GroupSums.glsl"
uniform int uIteration; // this iteration's index in the solve
uniform bool uFirstGather; // what the cells hold is not an earlier gather of this solve: count it as nothing
#define GATHER_ACCESS
#elif defined(SHIFT_ITERATE) || defined(WRITE_CHANGE)
#define GATHER_ACCESS
#else
#define GATHER_ACCESS writeonly
#endif
#ifdef SHIFT_ITERATE
// A solve of the bounce iteration that goes on from an earlier one (passes/VoxelBouncePass) under new
// first-bounce light: this gather of the new light replaces the higher-bounce cells' gather of the old one, and
// the gather of the iterate moves by as much, so that the two still differ by the earlier solve's higher bounces.
layout(rgba16f, binding = 4) uniform image3D uIterate;
layout(rgba16f, binding = 5) uniform image3D uIterateBack;
#endif
#ifdef WRITE_CHANGE
// The bounce iteration's later gathers also store how much each cell's gather changed from the one it replaces,
// the change of this iteration's higher bounces that the reinjection adds to each voxel
// (bounce/ReinjectBounce.comp): one lookup a voxel, where the whole sum took three.
layout(rgba16f, binding = 6) writeonly uniform image3D uChange;
layout(rgba16f, binding = 7) writeonly uniform image3D uChangeBack;
#endif
layout(rgba16f, binding = 0) GATHER_ACCESS uniform image3D uIrradiance;     // along the cell normal
layout(rgba16f, binding = 1) GATHER_ACCESS uniform image3D uIrradianceBack; // against it, two-sided cells only
// xyz: the mean of the cell's voxel normals (a two-sided cell's: the axis it gathers along); w: 0 = no surface,
// 1 = one-sided, 2 = two-sided (uIrradianceBack is valid)
layout(rgba8_snorm, binding = 2) writeonly uniform image3D uCellNormal; // w = sides / 2 (common/IrradianceLookup.glsl)
#ifdef CACHED_GEOMETRY
// The bounce iteration gathers the same cells again and again from the same voxels: after the first gather the
// normals and sides it wrote are read back instead of found again (for a two-sided cell that search reads six
// neighbouring cells, and llvmpipe runs it in every lane of a group where one cell needs it).
layout(binding = 2) uniform sampler3D uCellGeometry; // what the first gather wrote to uCellNormal
#endif

uniform int uResolution; // voxels per side
uniform int uCellSize;   // voxels per cell side
uniform int uOne;          // 1

const vec4 kNone = vec4(0.0, 0.0, 0.0, -1.0);

// A cell's sums of its surface voxels (passes/VoxelBouncePass), as integers so that the order of the atomic adds
// does not matter: its voxels' normals (times kNormalScale), their positions (times 2: a voxel's centre is
// voxel + 0.5), and how many there are. Seven texels of one r32ui volume of twice the cells a side, one octant
// each; negative sums wrap around as two's complement and read back as ints.
#if defined(PARENT_SUMS) || defined(CHILD_SUMS)
const float kNormalScale = 1024.0;
ivec3 sumsTexel(ivec3 cell, int which, int cellsPerSide)
{
    return cell + cellsPerSide * ivec3(which & 1, (which >> 1) & 1, which >> 2);
}
#endif
#ifdef PARENT_SUMS
// The bounce cells' first gather over these voxels adds each cell's sums to its cell of the higher bounces'
// grid, uParentRatio of its cells a side, so that the higher cells' gathers find their normal, sides and
// centre from eight sums instead of reading each of their voxels (CHILD_SUMS).
layout(r32ui, binding = 4) uniform uimage3D uParentSums;
uniform int uParentRatio;
#endif
#ifdef CHILD_SUMS
layout(binding = 4) uniform usampler3D uCellSums; // written by the bounce cells' gather (PARENT_SUMS)
int cellSum(ivec3 cell, int which)
{
    return int(texelFetch(uCellSums, sumsTexel(cell, which, uResolution / uCellSize), 0).r);
}

// What the loops over a cell's voxels below would sum, from the bounce cells' sums.
void readCellSums(ivec3 cell, out vec3 normalSum, out vec3 positionSum, out float occupied)
{
    normalSum = vec3(cellSum(cell, 0), cellSum(cell, 1), cellSum(cell, 2)) / kNormalScale;
    positionSum = 0.5 * vec3(cellSum(cell, 3), cellSum(cell, 4), cellSum(cell, 5));
    occupied = float(cellSum(cell, 6));
}
#endif

// The share of occupied voxels in the cell `offset` cells away; 1 outside the grid (nothing to gather there).
float cellOccupancy(ivec3 cell, ivec3 offset)
{
    ivec3 first = (cell + offset) * uCellSize;
    if (any(lessThan(first, ivec3(0))) || any(greaterThanEqual(first, ivec3(uResolution))))
        return 1.0;
#ifdef CHILD_SUMS
    return float(cellSum(cell + offset, 6)) / float(uCellSize * uCellSize * uCellSize);
#endif
    float occupied = 0.0;
    for (int z = 0; z < uCellSize; ++z)
        for (int y = 0; y < uCellSize; ++y)
            for (int x = 0; x < uCellSize; ++x)
                occupied += texelFetch(uAlbedo, voxelLoadTexel(first + ivec3(x, y, z)), 0).a > 0.0 ? 1.0 : 0.0;
    return occupied / float(uCellSize * uCellSize * uCellSize);
}

vec3 gChange = vec3(0.0); // this invocation's part of the change sums (CHANGE_SUMS), per channel
float gTotal = 0.0;

// A cell side with no surface: a lookup passes over it.
void storeNone(ivec3 cell, bool front)
{
#ifdef WRITE_CHANGE
    if (front)
        imageStore(uChange, cell, kNone);
    else
        imageStore(uChangeBack, cell, kNone);
#endif
    if (front)
        imageStore(uIrradiance, cell, kNone);
    else
        imageStore(uIrradianceBack, cell, kNone);
}

void storeGathered(ivec3 cell, bool front, vec4 gathered)
{
#if defined(WRITE_CHANGE) || defined(CHANGE_SUMS) || defined(SHIFT_ITERATE)
    // What the cell held before this gather, read once for all that compare with it.
    vec4 replaced = front ? imageLoad(uIrradiance, cell) : imageLoad(uIrradianceBack, cell);
#endif
#ifdef WRITE_CHANGE
    vec4 change = vec4(gathered.rgb - (replaced.a >= 0.0 ? replaced.rgb : vec3(0.0)), gathered.a);
    if (front)
        imageStore(uChange, cell, change);
    else
        imageStore(uChangeBack, cell, change);
#endif
#ifdef CHANGE_SUMS
    vec3 before = uFirstGather ? vec3(0.0) : max(replaced.rgb, vec3(0.0));
    gChange += abs(gathered.rgb - before);
    gTotal += dot(gathered.rgb, vec3(1.0));
#endif
#ifdef SHIFT_ITERATE
    vec4 iterate = front ? imageLoad(uIterate, cell) : imageLoad(uIterateBack, cell);
    // A cell the earlier voxels did not hold has no earlier first-bounce gather: the iterate's is taken against
    // this one (moved by all of it, the new gather would count twice).
    if (replaced.a >= 0.0)
        iterate.rgb += gathered.rgb - replaced.rgb;
    if (front)
        imageStore(uIterate, cell, iterate);
    else
        imageStore(uIterateBack, cell, iterate);
#endif
    if (front)
        imageStore(uIrradiance, cell, gathered);
    else
        imageStore(uIrradianceBack, cell, gathered);
}

void gatherCell(ivec3 cell)
{
    vec3 normalSum = vec3(0.0);
    vec3 positionSum = vec3(0.0);
    float occupied = 0.0;
#ifdef CACHED_GEOMETRY
    vec4 geometry = texelFetch(uCellGeometry, cell, 0);
    if (geometry.w <= 0.0) {
        storeNone(cell, true);
        storeNone(cell, false);
        return;
    }
#ifdef CHILD_SUMS
    readCellSums(cell, normalSum, positionSum, occupied);
#else
    for (int z = 0; z < uCellSize; ++z)
        for (int y = 0; y < uCellSize; ++y)
            for (int x = 0; x < uCellSize; ++x) {
                ivec3 voxel = cell * uCellSize + ivec3(x, y, z);
                float occupancy = texelFetch(uAlbedo, voxelLoadTexel(voxel), 0).a > 0.0 ? 1.0 : 0.0;
                positionSum += occupancy * (vec3(voxel) + 0.5);
                occupied += occupancy;
            }
#endif
    vec3 centre = uGridOrigin + positionSum / occupied * uVoxelSize;
    bool twoSided = geometry.w > 0.75;
    vec3 n = normalize(geometry.xyz);
#else
#ifdef CHILD_SUMS
    readCellSums(cell, normalSum, positionSum, occupied);
#else
    for (int z = 0; z < uCellSize; ++z)
        for (int y = 0; y < uCellSize; ++y)
            for (int x = 0; x < uCellSize; ++x) {
                ivec3 voxel = cell * uCellSize + ivec3(x, y, z);
                ivec3 texel = voxelLoadTexel(voxel);
                if (texelFetch(uAlbedo, texel, 0).a <= 0.0)
                    continue;
                vec3 n = texelFetch(uNormal, texel, 0).xyz;
                // A voxel whose faces cancel adds (almost) nothing to the direction, but still counts.
                normalSum += dot(n, n) > 1e-8 ? normalize(n) * min(length(n), 1.0) : vec3(0.0);
                positionSum += vec3(voxel) + 0.5;
                occupied += 1.0;
            }
#endif
#ifdef PARENT_SUMS
    if (occupied > 0.0) {
        ivec3 parent = cell / uParentRatio;
        int parents = uResolution / (uCellSize * uParentRatio);
        ivec3 normalFixed = ivec3(round(normalSum * kNormalScale));
        ivec3 positionTwice = ivec3(round(positionSum * 2.0));
        for (int i = 0; i < 3; ++i) {
            imageAtomicAdd(uParentSums, sumsTexel(parent, i, parents), uint(normalFixed[i]));
            imageAtomicAdd(uParentSums, sumsTexel(parent, 3 + i, parents), uint(positionTwice[i]));
        }
        imageAtomicAdd(uParentSums, sumsTexel(parent, 6, parents), uint(occupied));
    }
#endif
    if (occupied == 0.0) {
        storeNone(cell, true);
        storeNone(cell, false);
        imageStore(uCellNormal, cell, vec4(0.0));
        return;
    }
    vec3 centre = uGridOrigin + positionSum / occupied * uVoxelSize;
    float normalLength = length(normalSum);
    bool twoSided = normalLength < 0.5 * occupied;
    vec3 n = twoSided ? vec3(0.0, 0.0, 1.0) : normalSum / normalLength;
    if (twoSided) {
        // Faces cancel: take the axis whose two neighbouring cells are emptiest, and gather both ways along it.
        float best = 3.0;
        for (int axis = 0; axis < 3; ++axis) {
            ivec3 step = ivec3(axis == 0, axis == 1, axis == 2);
            float opacity = cellOccupancy(cell, step) + cellOccupancy(cell, -step);
            if (opacity < best) {
                best = opacity;
                n = vec3(step);
            }
        }
    }
    // A one-sided cell stores the mean of its voxels' normals, not its direction alone: a lookup's cosine with it
    // is then the mean cosine of the cell's surface with the pixel's, and a cell on an edge, holding two faces,
    // counts as the half of it that faces the pixel's way. With unit normals such a cell, its normal between
    // the faces, passed for either face and lit a row of blobs along a box's edge with the light it gathered
    // along that in-between direction (docs/ACCURACY.md, "Lookups keep to their side").
    vec3 stored = twoSided ? n : n * min(normalLength / occupied, 1.0);
    imageStore(uCellNormal, cell, vec4(stored, twoSided ? 1.0 : 0.5));
    // Gather along the normal as stored (8-bit snorm), as later gathers that read it back will: a solve must
    // not depend on which of its gathers came first.
    n = normalize(round(clamp(stored, -1.0, 1.0) * 127.0) / 127.0);
#endif
    if (!twoSided) // (a two-sided cell's back face is read first for its change: CHANGE_SUMS)
        storeNone(cell, false);
    // The gather appears once, in a loop over the sides: llvmpipe runs all code of a shader in every lane, so
    // three gathers written out (one side, or two) cost every cell the first steps of fifteen cones, and the
    // second pass of this loop runs only where a lane has a second side: a two-sided cell whose back side did
    // not fit the list. uOne keeps the compiler from unrolling it back into two copies.
#ifdef BACK_SIDES
    int first = 1;
    int sides = 2 * uOne;
#else
    int first = 0;
    bool backLater = twoSided && appendCellWithin(cell, uBackSideCapacity);
    int sides = (twoSided && !backLater ? 2 : 1) * uOne;
#endif
    for (int side = first; side < sides; ++side) {
        vec3 direction = side == 0 ? n : -n;
        storeGathered(cell, side == 0, gatherDiffuse(centre, direction));
    }
}

void main()
{
    ivec3 cell;
    if (occupiedCell(cell))
        gatherCell(cell);
#ifdef CHANGE_SUMS
    int sums = BOUNCE_SUMS_PER_ITERATION * uIteration + BOUNCE_SUM_CELL_CHANGE;
    addGroupSums(gChange.r, gChange.g, sums);
    barrier(); // the first call's last reads of the shared sums before the second writes them
    addGroupSums(gChange.b, gTotal, sums + 2);
#endif
}
