// How far, in footprints, a cone's samples keep from the tangent plane of the surface it leaves (traceCone).
// 1.5 measured best of 1 (no effect on 30-degree cones), 1.5, 3 and rays (docs/DESIGN.md).
#define CLEARANCE 1.5
// Tracing one cone through the radiance volume, shared by the per-pixel cone passes (cone/DiffuseCones.frag,
// cone/SpecularCone.frag), the irradiance cache's gather and the per-voxel bounce gather
// (bounce/GatherBounce.comp), so all see the volume the same way.
// A shader that counts texture fetches defines COUNT_FETCHES(n) before including this file.
#ifndef COUNT_FETCHES
#define COUNT_FETCHES(n)
#endif
#include "common/VoxelBricks.glsl"

layout(binding = 5) uniform sampler3D uRadiance;
#ifdef ANISOTROPIC
// Direction-dependent mips (RenderSettings::anisotropicMips): level k here is grid level k + 1.
// A compile-time variant, not a uniform branch: llvmpipe ran both sides of the branch and the plain
// path cost six times as much.
// The six chains are tiles of one texture stacked along z (+x, -x, +y, -y, +z, -z; VoxelVolume::directional),
// empty gaps between (common/DirectionalStack.glsl): a cone picks its side of each axis by coordinate. With six
// samplers, picking per pixel fetched from both sides of every axis: the cone pass took 1.7 times as long
// (docs/DESIGN.md, "Measured choices").
#include "common/DirectionalStack.glsl"
layout(binding = 6) uniform sampler3D uTowards;
uniform vec2 uStack; // in tiles: from one tile's start to the next, and the stack's depth

// Chain `tile` of stack `towards` at uvw (in the grid's [0, 1]^3) and level l; the gaps read as the border a
// texture of its own has.
vec4 sampleTowards(sampler3D towards, int tile, vec3 uvw, float l)
{
    uvw.z = (uvw.z + uStack.x * float(tile)) / uStack.y;
    return textureLod(towards, uvw, l);
}
#endif

#ifdef CLIP_LEVELS
// A clipmap's levels coarser than the grid above (core/ClipLevelPass), finest first, each a grid of the same
// resolution twice as wide: a cone whose footprint would reach past a grid's edge goes on in the next level.
#include "common/Bindings.glsl"
layout(binding = CLIP_RADIANCE_UNIT) uniform sampler3D uClipRadiance[CLIP_LEVELS];
#ifdef ANISOTROPIC
layout(binding = CLIP_TOWARDS_UNIT) uniform sampler3D uClipTowards[CLIP_LEVELS];
#endif
uniform vec4 uClipBox[CLIP_LEVELS];  // xyz: the level's corner, w: its side (metres)
uniform vec4 uClipGrid[CLIP_LEVELS]; // x: its voxel (metres), y: its top mip level
#endif

uniform vec3 uGridOrigin;
uniform float uGridExtent;
uniform float uVoxelSize;
uniform float uMaxLevel;
uniform float uStepFactor;
uniform float uMaxDistance;
uniform bool uAoEnabled;          // accumulate occlusion only when the AO view shows it
uniform float uAoDistance;        // occluders beyond this count half
uniform float uConeOffset;        // metres: where cones start along the surface normal

const int kMaxSteps = 256;

// A grid's volume (`radiance`, and with anisotropic mips the chains `towards` above its level 0) as a cone
// travelling along dir sees it at a (fractional) mip level. SAMPLE_GRID drops `towards` where there are no
// chains.
#ifdef ANISOTROPIC
// The three chains facing a cone, weighted by the squared components of its direction. Their transmittances
// multiply, each raised to its weight, so a wall the chain crossing it holds opaque stays opaque to an oblique
// cone: the weighted mean of the opacities let a cone at 45 degrees through half of a wall the other chains see
// edge-on, and every gather lost light through the walls around it, more with every bounce (docs/ACCURACY.md,
// "Oblique cones through walls"). The light keeps the weighted mean's colour at the new opacity.
vec4 blendChains(vec4 a, vec4 b, vec4 c, vec3 w)
{
    vec4 linear = w.x * a + w.y * b + w.z * c;
    vec3 t = max(vec3(1.0) - vec3(a.a, b.a, c.a), vec3(1e-4));
    float alpha = 1.0 - exp2(dot(w, log2(t)));
    return linear.a > 1e-6 ? vec4(linear.rgb * (alpha / linear.a), alpha) : linear;
}

// The chains a cone travelling along dir reads at grid level `level` (>= 1), blended (blendChains).
vec4 sampleChains(sampler3D towards, vec3 uvw, float level, vec3 dir)
{
    float l = max(level - 1.0, 0.0);
    return blendChains(sampleTowards(towards, dir.x > 0.0 ? 0 : 1, uvw, l),
        sampleTowards(towards, dir.y > 0.0 ? 2 : 3, uvw, l), sampleTowards(towards, dir.z > 0.0 ? 4 : 5, uvw, l),
        dir * dir);
}
#endif

#ifndef ANISOTROPIC
vec4 sampleGrid(sampler3D radiance, vec3 uvw, float level)
{
    COUNT_FETCHES(1);
    return textureLod(radiance, uvw, level);
}
#define SAMPLE_GRID(radiance, towards, uvw, level, dir) sampleGrid(radiance, uvw, level)
#else
vec4 sampleGrid(sampler3D radiance, sampler3D towards, vec3 uvw, float level, vec3 dir)
{
    // Level 0 and the three directional chains are fetched at every step, and blended by the level: llvmpipe
    // runs both sides of a branch on the level anyway, and written as a branch it fetched level 0 twice
    // (five fetches a step where four do; the cone loop ~20% faster). A cone's march goes by phases instead
    // (marchPhase), each a loop of its own that fetches only what its footprints need.
    COUNT_FETCHES(4);
    vec4 finest = sampleLevel0(radiance, uvw);
    return mix(finest, sampleChains(towards, uvw, level, dir), clamp(level, 0.0, 1.0));
}
#define SAMPLE_GRID(radiance, towards, uvw, level, dir) sampleGrid(radiance, towards, uvw, level, dir)
#endif

// Phases of a cone's march through a grid (traceCone): a footprint within a voxel reads level 0 alone, one
// between one and two voxels blends it with the chains, a wider one reads the chains alone. Each phase is a
// loop of its own with its own lookups (marchPhase), so that a step pays only for the fetches its phase needs.
const int kPhaseFinest = 0;
const int kPhaseBlend = 1;
const int kPhaseCoarse = 2;
const int kPhaseWhole = 3; // one loop, level 0 and the chains blended by the level at every step

// A grid's chains as a parameter, where there are chains.
#ifdef ANISOTROPIC
#define TOWARDS_PARAM , sampler3D towards
#define TOWARDS_ARG(chains) , chains
#else
#define TOWARDS_PARAM
#define TOWARDS_ARG(chains)
#endif

vec4 samplePhase(int phase, sampler3D radiance TOWARDS_PARAM, vec3 uvw, float level, vec3 dir)
{
#ifdef ANISOTROPIC
    if (phase == kPhaseFinest) {
        COUNT_FETCHES(1);
        return sampleLevel0(radiance, uvw);
    }
    if (phase == kPhaseCoarse) {
        COUNT_FETCHES(3);
        return sampleChains(towards, uvw, level, dir);
    }
#endif
    return SAMPLE_GRID(radiance, towards, uvw, level, dir);
}

bool inPhase(int phase, float level)
{
#ifdef ANISOTROPIC
    if (phase == kPhaseFinest)
        return level <= 0.0;
    if (phase == kPhaseBlend)
        return level < 1.0;
#endif
    return true;
}

// Whether uvw (in a grid's [0, 1]^3) is further than margin from the grid's faces.
bool insideGrid(vec3 uvw, float margin)
{
    return all(greaterThanEqual(uvw, vec3(margin))) && all(lessThanEqual(uvw, vec3(1.0 - margin)));
}

#ifdef CLIP_LEVELS
// A gather within kClipBand voxels of the faces of the finest grid holding its surface blends with the same
// gather started in the next level, fully so at the faces: as the finer levels follow the camera, a surface
// crossing out of one goes over smoothly instead of popping.
#include "common/ClipFaces.glsl"
const float kClipBand = float(CLIP_BAND_VOXELS);

// The finest grid holding p (-1: the grid above, k: clip level k), and how far in p is: 0 at its faces, 1 from
// kClipBand voxels in (always 1 in the coarsest level, which has nothing around it, and at faces a level shares
// with it).
int startLevelOf(vec3 p, out float depth)
{
    float inside = insideMovingFaces(p, uGridOrigin, uGridExtent, uClipBox[CLIP_LEVELS - 1]);
    if (inside >= 0.0) {
        depth = clamp(inside / (kClipBand * uVoxelSize), 0.0, 1.0);
        return -1;
    }
    for (int k = 0; k < CLIP_LEVELS; ++k) {
        inside = insideMovingFaces(p, uClipBox[k].xyz, uClipBox[k].w, uClipBox[CLIP_LEVELS - 1]);
        if (inside >= 0.0 || k == CLIP_LEVELS - 1) {
            depth = k == CLIP_LEVELS - 1 ? 1.0 : clamp(inside / (kClipBand * uClipGrid[k].x), 0.0, 1.0);
            return k;
        }
    }
    depth = 1.0;
    return CLIP_LEVELS - 1;
}
#endif

// How far along the normal cones start in grid `level` (-1: the grid above; k: clip level k): cone_offset of
// its voxels, so that a cone leaves its surface's voxels in any level.
float coneOffsetIn(int level)
{
#ifdef CLIP_LEVELS
    if (level >= 0)
        return uClipGrid[level].z;
#endif
    return uConeOffset;
}

// Adds sample s (premultiplied, of a texel `texel` metres wide) behind what a cone has gathered, over a step
// of stepLength at distance t.
void accumulate(vec4 s, float stepLength, float texel, float t, inout vec3 color, inout float alpha, inout float occlusion)
{
    if (s.a <= 1e-4)
        return;
    float a = correctOpacity(s.a, stepLength, texel);
    color += (1.0 - alpha) * s.rgb * (a / s.a);
    if (uAoEnabled)
        occlusion += (1.0 - alpha) * a / (1.0 + t / uAoDistance);
    alpha += (1.0 - alpha) * a;
}

// Where a cone's last sample lies, at uvw where it leaves the grid (in the grid's [0, 1]^3): the nearest point half a
// texel of its lookup inside, so the texels along the face count whole. The steps grow with the cone, and a wall
// closing the scene at the face lay between the last sample inside and the first outside; ending there without a
// sample let a closed room's cones out through their walls (a white furnace's gather captured 82%, 96% with this;
// docs/ACCURACY.md, "Back faces and the grid's faces").
vec3 lastSampleAtFace(vec3 uvw, float texel, float extent)
{
    float inset = 0.5 * texel / extent;
    return clamp(uvw, vec3(inset), vec3(1.0 - inset));
}

// Where a cone marches: a grid's corner, side and voxel (metres), its top mip level, how far from its faces
// (in footprints) the cone leaves it, and whether it is the last grid, whose faces end the cone with a sample
// on them (lastSampleAtFace) at `exit`, how far along the cone they are.
struct ConeGrid {
    vec3 origin;
    float extent;
    float voxel;
    float maxLevel;
    float margin;
    bool last;
    float exit;
};

// How far the ray origin + t * dir goes before it leaves the box [corner, corner + extent] (0 if it starts outside).
float exitDistance(vec3 origin, vec3 dir, vec3 corner, float extent)
{
    vec3 safe = mix(vec3(1e-20), dir, greaterThan(abs(dir), vec3(1e-20)));
    vec3 far = (corner + step(vec3(0.0), dir) * extent - origin) / safe;
    return max(min(far.x, min(far.y, far.z)), 0.0);
}

// A cone's footprint at distance t: its diameter, capped at 1 / CLEARANCE of its height above the tangent plane of
// the surface it leaves (traceCone), never under a voxel.
float footprint(float t, float tanHalf, float clearCos, float clearOffset, float voxel)
{
    return min(coneDiameter(t, tanHalf), max((clearOffset + t * clearCos) / CLEARANCE, voxel));
}

// One phase of a cone's march through a grid: steps while the footprint stays in the phase. Returns whether the
// cone goes on into the next phase; `outside` says it reached past the grid's faces.
bool marchPhase(int phase, ConeGrid grid, sampler3D radiance TOWARDS_PARAM, vec3 origin, vec3 dir, float tanHalf,
    float clearCos, float clearOffset, inout int step, inout float t, inout vec3 color, inout float alpha,
    inout float occlusion, inout bool outside)
{
    for (; step < kMaxSteps && t < uMaxDistance && alpha < 0.99; ++step) {
        float d = footprint(t, tanHalf, clearCos, clearOffset, grid.voxel);
        float level = coneMipLevel(d, grid.voxel, grid.maxLevel);
        if (!inPhase(phase, level))
            return true;
        vec3 uvw = (origin + t * dir - grid.origin) / grid.extent;
        float stepLength = coneStepLength(d, grid.voxel, uStepFactor);
        float texel = grid.voxel * exp2(level);
        // Before a lookup reaches past a grid with a coarser one around it, on into that one.
        if (!insideGrid(uvw, grid.margin * d / grid.extent)) {
            outside = true;
            return false;
        }
        // In the last grid a step that reaches past the face ends there. Counted whole, the stretch beyond
        // counted twice (this sample and the face's), and as the cone's start moved, whether a sample fell just
        // inside or just past the face switched between that double count and none: an edge of a third in the
        // light gathered across a face of the point-lit Cornell box's short box, which stands askew to the grid.
        float inside = grid.last ? clamp(grid.exit - t, 0.0, stepLength) : stepLength;
        accumulate(samplePhase(phase, radiance TOWARDS_ARG(towards), uvw, level, dir), inside, texel, t, color,
            alpha, occlusion);
        t += stepLength;
    }
    return false;
}

// The last grid's face sample, once a cone has left it: the cone's at the point it leaves the grid, not at the
// first sample past it, so a gather varies smoothly with where it starts (docs/ACCURACY.md, "The cone's last
// step"). Taken after the grid's march loops, not in them: llvmpipe runs a branch's lookups for all the lanes
// of a loop iteration whenever one of them takes it, and lanes leave the grid at different steps, so inside the
// loops the face's lookups cost about as much as the march's own (docs/BENCHMARKS.md, "The face sample out of
// the march's loops"). In a clipmap it stays in the loop over levels, once per level: after that loop, the
// coarsest level's lookup read NaN on llvmpipe (Mesa 22.3; tst_Clipmap).
void sampleAtFace(ConeGrid grid, sampler3D radiance TOWARDS_PARAM, vec3 origin, vec3 dir, float tanHalf,
    float clearCos, float clearOffset, inout vec3 color, inout float alpha, inout float occlusion)
{
    float faceFootprint = footprint(grid.exit, tanHalf, clearCos, clearOffset, grid.voxel);
    float faceLevel = coneMipLevel(faceFootprint, grid.voxel, grid.maxLevel);
    float faceTexel = grid.voxel * exp2(faceLevel);
    vec3 faceUvw = (origin + grid.exit * dir - grid.origin) / grid.extent;
    accumulate(SAMPLE_GRID(radiance, towards, lastSampleAtFace(faceUvw, faceTexel, grid.extent), faceLevel, dir),
        coneStepLength(faceFootprint, grid.voxel, uStepFactor), faceTexel, grid.exit, color, alpha, occlusion);
}

// A cone's march through one grid from t on: phase after phase in a single grid; in a clipmap one loop per
// level, since there the phases' loops (three per level) made the bounce gathers on the Sponza no faster and the
// per-pixel cones 2-5% slower (docs/DESIGN.md, "A loop per phase of the march").
#ifdef CLIP_LEVELS
#define MARCH_GRID(grid, radiance, towards)                                                                        \
    {                                                                                                              \
        int step = 0;                                                                                              \
        marchPhase(kPhaseWhole, grid, radiance TOWARDS_ARG(towards), origin, dir, tanHalf, clearCos, clearOffset,  \
            step, t, color, alpha, occlusion, outside);                                                            \
    }
#else
#define MARCH_GRID(grid, radiance, towards)                                                                        \
    {                                                                                                              \
        int step = 0;                                                                                              \
        if (marchPhase(kPhaseFinest, grid, radiance TOWARDS_ARG(towards), origin, dir, tanHalf, clearCos,          \
                clearOffset, step, t, color, alpha, occlusion, outside)                                            \
            && marchPhase(kPhaseBlend, grid, radiance TOWARDS_ARG(towards), origin, dir, tanHalf, clearCos,        \
                clearOffset, step, t, color, alpha, occlusion, outside))                                           \
            marchPhase(kPhaseCoarse, grid, radiance TOWARDS_ARG(towards), origin, dir, tanHalf, clearCos,          \
                clearOffset, step, t, color, alpha, occlusion, outside);                                           \
    }
#endif

// Front-to-back compositing along one cone; returns premultiplied radiance and opacity. The cone starts
// `clearOffset` metres off a surface it leaves at cosine `clearCos` to its normal; its footprint stays within
// 1 / CLEARANCE of its height above that surface's tangent plane, so that coarse lookups gather less of the
// surface the cone starts from. A cone leaving at a low angle thus narrows.
vec4 traceCone(vec3 origin, vec3 dir, float tanHalf, float clearCos, float clearOffset, int firstLevel, out float occlusion)
{
    vec3 color = vec3(0.0);
    float alpha = 0.0;
    occlusion = 0.0;
    float t = uVoxelSize;
    // A cone that starts in a clip level skips the grids finer than it.
    bool outside = firstLevel >= 0;
#ifdef CLIP_LEVELS
    const bool onlyGrid = false;
#else
    const bool onlyGrid = true;
#endif
    if (firstLevel < 0) {
        ConeGrid grid = ConeGrid(uGridOrigin, uGridExtent, uVoxelSize, uMaxLevel, onlyGrid ? 0.0 : 1.0, onlyGrid,
            exitDistance(origin, dir, uGridOrigin, uGridExtent));
        MARCH_GRID(grid, uRadiance, uTowards)
#ifndef CLIP_LEVELS
        if (outside && alpha < 0.99)
            sampleAtFace(grid, uRadiance TOWARDS_ARG(uTowards), origin, dir, tanHalf, clearCos, clearOffset, color,
                alpha, occlusion);
#endif
    }
#ifdef CLIP_LEVELS
    // The same in each coarser level the cone reaches, the same t going on; the coarsest ends at its faces.
    for (int k = 0; k < CLIP_LEVELS; ++k) {
        if (k < firstLevel)
            continue;
        if (!outside || alpha >= 0.99 || t >= uMaxDistance)
            break;
        outside = false;
        bool coarsest = k + 1 == CLIP_LEVELS;
        ConeGrid grid = ConeGrid(uClipBox[k].xyz, uClipBox[k].w, uClipGrid[k].x, uClipGrid[k].y,
            coarsest ? 0.0 : 1.0, coarsest, coarsest ? exitDistance(origin, dir, uClipBox[k].xyz, uClipBox[k].w) : 0.0);
        MARCH_GRID(grid, uClipRadiance[k], uClipTowards[k])
        if (coarsest && outside && alpha < 0.99)
            sampleAtFace(grid, uClipRadiance[k] TOWARDS_ARG(uClipTowards[k]), origin, dir, tanHalf, clearCos,
                clearOffset, color, alpha, occlusion);
    }
#endif
    return vec4(color, alpha);
}

// Orthonormal basis around n without a branch on a reference axis (Duff et al. 2017).
void tangentBasis(vec3 n, out vec3 t, out vec3 b)
{
    float s = n.z >= 0.0 ? 1.0 : -1.0;
    float a = -1.0 / (s + n.z);
    float c = n.x * n.y * a;
    t = vec3(1.0 + s * n.x * n.x * a, s * c, -s * n.x);
    b = vec3(c, s + n.y * n.y * a, -n.y);
}

// One cone from surface point p (normal n), starting coneOffsetIn() out along n in the finest grid holding p;
// in a clipmap, near that grid's faces, blended with the same cone started in the next level.
vec4 traceSurfaceCone(vec3 p, vec3 n, vec3 dir, float tanHalf, float clearCos, out float occlusion)
{
    int level = -1;
#ifdef CLIP_LEVELS
    float depth;
    level = startLevelOf(p, depth);
#endif
    float offset = coneOffsetIn(level);
    vec4 traced = traceCone(p + n * offset, dir, tanHalf, clearCos, offset, level, occlusion);
#ifdef CLIP_LEVELS
    if (depth < 1.0) {
        float coarseOcclusion;
        float coarseOffset = coneOffsetIn(level + 1);
        vec4 coarse = traceCone(p + n * coarseOffset, dir, tanHalf, clearCos, coarseOffset, level + 1, coarseOcclusion);
        traced = mix(coarse, traced, depth);
        occlusion = mix(coarseOcclusion, occlusion, depth);
    }
#endif
    return traced;
}

#ifdef MAX_CONES
// The diffuse cone set (core/ConeSet): tangent-space axes whose weights split the cosine lobe, summing to one.
uniform int uConeCount;
uniform vec4 uCones[MAX_CONES]; // tangent-space axis, w = weight
uniform float uDiffuseTanHalf;

// Where the grid around the scene is closed in (core/EnclosedSpace): 1 in empty cells no light can leave.
#include "common/Bindings.glsl"
layout(binding = ENCLOSURE_UNIT) uniform sampler3D uEnclosure;
uniform bool uEnclosureUsed;
uniform vec4 uEnclosureBox; // xyz: the map's corner, w: its side (metres)
uniform float uEnclosureLift; // metres along the normal to the cell that decides: 1.5 of the map's cells

// Whether a gather from surface point p (normal n) starts in space no light can leave. There every cone ends
// on a surface, so what the voxels let through (a wall one voxel thick, seen at a coarse level, is part
// transparent) is light of the walls the cone reached: its opacity-weighted mean stands for it.
bool startsEnclosed(vec3 p, vec3 n)
{
    if (!uEnclosureUsed)
        return false;
    vec3 uvw = (p + n * uEnclosureLift - uEnclosureBox.xyz) / uEnclosureBox.w;
    if (any(lessThan(uvw, vec3(0.0))) || any(greaterThanEqual(uvw, vec3(1.0))))
        return false;
    return textureLod(uEnclosure, uvw, 0.0).r > 0.25;
}

// What a cone that starts in enclosed space gathers: its light over its opacity, the scale capped at 4 so a
// cone that met almost nothing (through a crack the map cannot see) is not blown up.
vec3 closedIn(vec4 traced)
{
    return traced.rgb / max(traced.a, 0.25);
}

// The diffuse cones around n from surface point p: rgb = sum_i w_i L_i (irradiance / pi), a = ambient
// visibility.
vec4 gatherDiffuse(vec3 p, vec3 n)
{
    vec3 t, b;
    tangentBasis(n, t, b);
    vec3 sum = vec3(0.0);
    float occlusion = 0.0;
    bool enclosed = startsEnclosed(p, n);
    for (int i = 0; i < uConeCount; ++i) {
        vec3 axis = uCones[i].xyz;
        vec3 dir = normalize(t * axis.x + b * axis.y + n * axis.z);
        float coneOcclusion;
        vec4 traced = traceSurfaceCone(p, n, dir, uDiffuseTanHalf, max(axis.z, 0.05), coneOcclusion);
        sum += uCones[i].w * (enclosed ? closedIn(traced) : traced.rgb);
        occlusion += uCones[i].w * coneOcclusion;
    }
    return vec4(sum, clamp(1.0 - occlusion, 0.0, 1.0));
}
#endif
