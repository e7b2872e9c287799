// One step of the bounce iteration (passes/VoxelBouncePass). Each occupied voxel's outgoing radiance becomes
//   L = L_direct + albedo * sum_i w_i L_i,
// the cone weights splitting the cosine lobe (sum_i w_i L_i = E / pi, and a Lambertian surface sends
// albedo / pi * E), where sum_i w_i L_i is what the bounce cells gathered from the previous iterate
// (irradiance/GatherCells.comp over every occupied cell), looked up as a pixel looks up the irradiance cache.
// With the higher bounces on coarser cells, the bounce cells hold the gather of L_direct, and the coarser cells
// add the gather of the previous iterate less theirs of L_direct: the same sum, as the gather is linear in
// the light, with what the later bounces add gathered at their coarser scale.
// The step also sums how much the voxels changed and how bright they are: the residual that decides when the
// iteration has converged.
// One invocation per listed cell of 2^3 voxels (VoxelMipBuilder's first level), not per voxel: a lookup
// interpolates between the eight cells around a voxel, and the eight voxels of an aligned 2^3 block have the same
// eight around them for any cells of 4^3 voxels or more, so the block fetches those cells once for all of its
// voxels (the bounce cells with BLOCK_CELLS: cells of 2^3 voxels, `bounce_cell=2`, are looked up voxel by voxel;
// the higher bounces' cells, coarser than the bounce cells, are 4^3 voxels at least). Having its voxels' new light
// at hand, it also writes the cell's texels of the first mip level above them (FILTER_DIRECTIONAL: the six chains,
// common/DirectionalComposite.glsl; FILTER_BOX: the box level), which the filter would otherwise fetch again
// (docs/DESIGN.md, "The reinjection by blocks").
#extension GL_NV_shader_atomic_float : require
#include "bounce/BounceSums.glsl"
#include "common/OccupiedCells.glsl"
#include "common/VoxelBricks.glsl"
#define SUMS_BINDING 1
#include "common/GroupSums.glsl"

layout(local_size_x = 64) in;

layout(binding = 0) uniform sampler3D uAlbedo;
layout(binding = 1) uniform sampler3D uNormal;
layout(binding = 2) uniform sampler3D uDirect; // first-bounce radiance (direct light and emission), premultiplied
layout(rgba16f, binding = 0) uniform image3D uBounced; // the previous iterate in, the new one out
uniform int uIteration; // this iteration's index in the solve (bounce/BounceSums.glsl)
#ifdef FILTER_DIRECTIONAL
layout(rgba16f, binding = 2) writeonly uniform image3D uTowards;
#include "common/DirectionalComposite.glsl"
#else
vec4 children[8];
#endif
#ifdef FILTER_BOX
layout(rgba16f, binding = 2) writeonly uniform image3D uBoxLevel; // the bounced volume's level 1
#endif

uniform vec3 uGridOrigin;
uniform float uVoxelSize;
uniform int uCellVoxels; // voxels per bounce cell side
uniform bool uCompare;   // the previous iterate is in uBounced (else it was just cleared)
// Each way of finding the new radiance is a program of its own (passes/VoxelBouncePass::reinject): with the
// others' lookups in the same program, left out by uniforms, each reinjection took about a third longer on
// llvmpipe (docs/BENCHMARKS.md).
// INCREMENT: the iterations after a split solve's first add to the previous iterate what its higher bounces
// changed by: uHigher and uHigherBack then hold the last gather's change (irradiance/GatherCells.comp,
// WRITE_CHANGE), and the sum above is unchanged but for rounding, as the lookups are linear in what the cells
// hold: one lookup a voxel, where the whole sum takes three (the bounce cells' gather and both higher-bounce
// gathers).
// HIGHER_BOUNCES: the whole sum adds the higher bounces' cells (passes/VoxelBouncePass), when the solve splits
// them off: their gather of the previous iterate, its cells' normals, and their gather of L_direct.
uniform int uHigherCellVoxels;
uniform int uHigherCells;
uniform float uHigherCellSize; // metres
layout(binding = 3) uniform sampler3D uHigher;
layout(binding = 4) uniform sampler3D uHigherBack;
layout(binding = 5) uniform sampler3D uHigherNormal;
layout(binding = 6) uniform sampler3D uHigherBase;
layout(binding = 7) uniform sampler3D uHigherBaseBack;

#include "common/IrradianceLookup.glsl"

// The eight cells around a block (corner i at base + (i & 1, (i >> 1) & 1, i >> 2), as
// common/IrradianceLookup.glsl numbers them): each one's normal and sides (w = 0 outside the grid or without a
// surface), and what its front and back hold, less what minusFront and minusBack hold with `subtract`; a = -1
// where the cell holds no gather (common/IrradianceLookup.glsl skips those), else 0.
struct BlockCells {
    vec4 normal[8];
    vec4 front[8];
    vec4 back[8];
};

// One corner of fetchBlockCells(), i a constant: the loops over corners are spelled out, so that llvmpipe keeps
// the block's cells in registers (indexed by a loop variable they went to memory, and the reinjection took half
// as long again).
void fetchBlockCell(int i, sampler3D front, sampler3D back, sampler3D normals, sampler3D minusFront,
    sampler3D minusBack, bool subtract, int cells, ivec3 base, out vec4 normal, out vec4 frontLight,
    out vec4 backLight)
{
    ivec3 c = base + ivec3(i & 1, (i >> 1) & 1, i >> 2);
    bool inside = all(greaterThanEqual(c, ivec3(0))) && all(lessThan(c, ivec3(cells)));
    ivec3 at = clamp(c, ivec3(0), ivec3(cells - 1));
    vec4 cellNormal = inside ? texelFetch(normals, at, 0) : vec4(0.0);
    frontLight = vec4(0.0, 0.0, 0.0, -1.0);
    backLight = vec4(0.0, 0.0, 0.0, -1.0);
    if (cellNormal.w > 0.0) {
        vec4 held = texelFetch(front, at, 0);
        vec3 less = subtract ? texelFetch(minusFront, at, 0).rgb : vec3(0.0);
        frontLight = vec4(held.rgb - less, held.a < 0.0 ? -1.0 : 0.0);
    }
    if (cellNormal.w > 0.75) {
        vec4 held = texelFetch(back, at, 0);
        vec3 less = subtract ? texelFetch(minusBack, at, 0).rgb : vec3(0.0);
        backLight = vec4(held.rgb - less, held.a < 0.0 ? -1.0 : 0.0);
    }
    normal = cellNormal;
}

#define FOR_EACH_CORNER(CALL) CALL(0) CALL(1) CALL(2) CALL(3) CALL(4) CALL(5) CALL(6) CALL(7)

BlockCells fetchBlockCells(sampler3D front, sampler3D back, sampler3D normals, sampler3D minusFront,
    sampler3D minusBack, bool subtract, int cells, ivec3 base)
{
    BlockCells block;
#define FETCH_CELL(i)                                                                                              \
    fetchBlockCell(i, front, back, normals, minusFront, minusBack, subtract, cells, base, block.normal[i],         \
        block.front[i], block.back[i]);
    FOR_EACH_CORNER(FETCH_CELL)
#undef FETCH_CELL
    return block;
}

// One corner's share of lookUpBlock(), i a constant.
void addCorner(BlockCells block, int i, vec3 f, vec3 n, inout vec3 sum, inout float weightSum)
{
    ivec3 corner = ivec3(i & 1, (i >> 1) & 1, i >> 2);
    vec4 cellNormal = block.normal[i];
    float agreement = dot(cellNormal.xyz, n);
    bool backSide = cellNormal.w > 0.75 && agreement < 0.0;
    if (backSide)
        agreement = -agreement;
    vec4 cached = backSide ? block.back[i] : block.front[i];
    if (cellNormal.w <= 0.0 || agreement < 0.5 || cached.a < 0.0)
        return;
    vec3 t = mix(vec3(1.0) - f, f, vec3(corner));
    float a2 = agreement * agreement;
    float w = (t.x * t.y * t.z + 1e-3) * a2 * a2;
    sum += w * cached.rgb;
    weightSum += w;
}

// common/IrradianceLookup.glsl's lookUpCells over a block's cells, for a voxel at trilinear position f among
// them with normal n: the same weights, summed in the same order.
bool lookUpBlock(BlockCells block, vec3 f, vec3 n, out vec3 result)
{
    vec3 sum = vec3(0.0);
    float weightSum = 0.0;
#define ADD_CORNER(i) addCorner(block, i, f, n, sum, weightSum);
    FOR_EACH_CORNER(ADD_CORNER)
#undef ADD_CORNER
    if (weightSum <= 0.0)
        return false;
    result = sum / weightSum;
    return true;
}

// The block's own cell (one of its eight: a block lies inside one cell), for its voxels that no cell around
// them faces. A voxel whose faces cancel (a wall thinner than a voxel, or two surfaces pressed together) sends
// the same radiance both ways, so it takes the mean of what reaches its two sides: that keeps the power it
// reflects, where the sum would send each side's light out of both sides and, two faces lighting each other,
// grow without bound from one iteration to the next.
struct OwnCell {
    vec4 normal;
    vec3 front;
    vec3 back;
};

OwnCell ownCellOf(BlockCells block, int corner)
{
    OwnCell own = OwnCell(vec4(0.0), vec3(0.0), vec3(0.0));
#define PICK_OWN(i)                                                                                                \
    if (corner == i)                                                                                               \
        own = OwnCell(block.normal[i], block.front[i].rgb, block.back[i].rgb);
    FOR_EACH_CORNER(PICK_OWN)
#undef PICK_OWN
    return own;
}

// What the own cell holds is light, never below zero, unless `change` (INCREMENT).
vec3 ownCellLight(OwnCell own, vec3 n, bool faced, bool change)
{
    if (own.normal.w <= 0.0)
        return vec3(0.0);
    vec3 lowest = change ? vec3(-65504.0) : vec3(0.0);
    if (own.normal.w < 0.75) // one-sided (common/IrradianceLookup.glsl)
        return max(own.front, lowest);
    if (!faced)
        return 0.5 * (max(own.front, lowest) + max(own.back, lowest));
    return max(dot(n, own.normal.xyz) >= 0.0 ? own.front : own.back, lowest);
}

// A voxel's own cell read directly, for cells too small to be shared by a block.
OwnCell ownCellAt(ivec3 cell)
{
    vec4 cellNormal = texelFetch(uCellNormal, cell, 0);
    vec3 backLight = cellNormal.w > 0.75 ? texelFetch(uIrradianceBack, cell, 0).rgb : vec3(0.0);
    return OwnCell(cellNormal, texelFetch(uIrradiance, cell, 0).rgb, backLight);
}

// The corner of a block's cells (base, cellVoxels voxels a side) that holds voxel `first`.
int ownCorner(ivec3 first, ivec3 base, int cellVoxels)
{
    ivec3 corner = first / cellVoxels - base;
    return corner.x + 2 * corner.y + 4 * corner.z;
}

void main()
{
    ivec3 cell;
    bool listed = occupiedCell(cell);
    float change = 0.0, total = 0.0;
    if (listed) {
        ivec3 firstVoxel = cell * 2;
        // A block's eight voxels lie in one brick of a sparse grid.
        ivec3 firstTexel = voxelLoadTexel(firstVoxel);
        vec3 firstCentre = uGridOrigin + (vec3(firstVoxel) + 0.5) * uVoxelSize;
        ivec3 base;
        vec3 unused;
#ifdef INCREMENT
        irradianceCellBlock(firstCentre, uGridOrigin, uHigherCellSize, base, unused);
        BlockCells higher
            = fetchBlockCells(uHigher, uHigherBack, uHigherNormal, uHigher, uHigherBack, false, uHigherCells, base);
        OwnCell higherOwn = ownCellOf(higher, ownCorner(firstVoxel, base, uHigherCellVoxels));
#endif
#if !defined(INCREMENT) && defined(BLOCK_CELLS)
        irradianceCellBlock(firstCentre, uGridOrigin, uCellSize, base, unused);
        BlockCells cells = fetchBlockCells(
            uIrradiance, uIrradianceBack, uCellNormal, uIrradiance, uIrradianceBack, false, uCells, base);
        OwnCell own = ownCellOf(cells, ownCorner(firstVoxel, base, uCellVoxels));
#endif
#ifdef HIGHER_BOUNCES
        ivec3 higherBase;
        irradianceCellBlock(firstCentre, uGridOrigin, uHigherCellSize, higherBase, unused);
        BlockCells higher = fetchBlockCells(
            uHigher, uHigherBack, uHigherNormal, uHigherBase, uHigherBaseBack, true, uHigherCells, higherBase);
        OwnCell higherOwn = ownCellOf(higher, ownCorner(firstVoxel, higherBase, uHigherCellVoxels));
#endif
        // Where bounce/DecideTail.comp found the tail q / (1 - q) trustworthy, each voxel stores L + tail * change:
        // the limit of the iteration when its change shrinks by q per step. The sums still measure the plain change.
        int at = BOUNCE_SUMS_PER_ITERATION * uIteration + BOUNCE_SUM_TAIL;
        vec3 tail = vec3(imageLoad(uSums, ivec2(at, 0)).r, imageLoad(uSums, ivec2(at + 1, 0)).r,
            imageLoad(uSums, ivec2(at + 2, 0)).r);
        bool addTail = any(greaterThan(tail, vec3(0.0)));
        for (int i = 0; i < 8; ++i) {
            ivec3 offset = ivec3(i & 1, (i >> 1) & 1, i >> 2);
            ivec3 voxel = firstVoxel + offset;
            ivec3 texel = firstTexel + offset;
            vec4 albedo = texelFetch(uAlbedo, texel, 0);
            vec3 normalSum = texelFetch(uNormal, texel, 0).xyz;
            // What the voxel holds: the previous iterate, or nothing after a clear (a cold start's, or of voxels
            // an earlier occupancy left).
            vec4 held = uCompare ? imageLoad(uBounced, texel) : vec4(0.0);
            vec4 value = held;
            // The voxels the voxelizer reached, and only those, have opacity.
            if (albedo.a > 0.0) {
#ifdef INCREMENT
                // Added to the previous iterate, which holds the first-bounce light's opacity (every reinjection
                // stores it): the first-bounce light itself is not needed.
                vec3 previous = held.rgb;
                vec4 result = held;
#else
                vec4 direct = texelFetch(uDirect, texel, 0);
                // A cold start's previous iterate is the first-bounce light.
                vec3 previous = uCompare ? held.rgb : direct.rgb;
                vec4 result = direct;
#endif
                if (max(albedo.r, max(albedo.g, albedo.b)) > 0.0) {
                    float normalLength = length(normalSum);
                    bool faced = normalLength >= 0.5;
                    vec3 n = normalLength > 1e-4 ? normalSum / normalLength : vec3(0.0);
                    vec3 p = uGridOrigin + (vec3(voxel) + 0.5) * uVoxelSize;
                    ivec3 sameBase;
                    vec3 f;
                    vec3 looked;
                    vec3 gathered;
#ifdef INCREMENT
                    irradianceCellBlock(p, uGridOrigin, uHigherCellSize, sameBase, f);
                    gathered = faced && lookUpBlock(higher, f, n, looked) ? looked
                                                                          : ownCellLight(higherOwn, n, faced, true);
#else
#ifdef BLOCK_CELLS
                    irradianceCellBlock(p, uGridOrigin, uCellSize, sameBase, f);
                    gathered = faced && lookUpBlock(cells, f, n, looked) ? looked : ownCellLight(own, n, faced, false);
#else
                    vec4 lookedHere;
                    gathered = faced && lookUpIrradiance(p, n, lookedHere)
                        ? lookedHere.rgb
                        : ownCellLight(ownCellAt(voxel / uCellVoxels), n, faced, false);
#endif
#ifdef HIGHER_BOUNCES
                    // Rounding can take a difference of two gathers of nearly the same light below zero.
                    irradianceCellBlock(p, uGridOrigin, uHigherCellSize, sameBase, f);
                    gathered += faced && lookUpBlock(higher, f, n, looked)
                        ? max(looked, vec3(0.0))
                        : ownCellLight(higherOwn, n, faced, false);
#endif
#endif
                    // A change may be negative (a light dimmed); rounding must not take the sum below zero.
                    result.rgb = max(result.rgb + albedo.rgb * gathered * albedo.a, vec3(0.0));
                }
                change += dot(abs(result.rgb - previous), vec3(1.0));
                total += dot(result.rgb, vec3(1.0));
                if (addTail)
                    result.rgb = max(result.rgb + tail * (result.rgb - previous), vec3(0.0));
                STORE_VOXEL(uBounced, voxel, result);
                value = result;
            }
            children[i] = value;
#ifdef DROP_BACK_FACES
            normals[i] = normalSum;
#endif
        }
#ifdef FILTER_DIRECTIONAL
        storeAllDirections(cell);
#endif
#ifdef FILTER_BOX
        vec4 sum = vec4(0.0);
        for (int i = 0; i < 8; ++i)
            sum += children[i];
        imageStore(uBoxLevel, cell, sum * 0.125);
#endif
    }
    addGroupSums(change, total, BOUNCE_SUMS_PER_ITERATION * uIteration + BOUNCE_SUM_VOXEL_CHANGE);
}
