// Averages this fragment's material into every voxel its pixel column crosses (common/VoxelWords.glsl), so
// overlapping fragments, static and dynamic alike, average instead of the last one winning. The fragment whose
// update finds a voxel empty lists it (core/OccupiedCellList) for the resolve and, after a full rebuild, for
// light injection: no pass has to search the grid for the voxels drawn.
// Variants (passes/VoxelizePass::voxelizer): EMISSIVE for emissive materials (other materials leave the emission
// word alone unless it holds light, so most fragments skip its compare-and-swap); EMISSION_VOLUME when the scene
// has emissive materials (passes/VoxelizePass::ensureEmission), so that the grid has an emission word at all;
// CONSERVATIVE when the geometry shader enlarged the triangle (clipped here to its pixel bounds).
#include "common/VoxelWords.glsl"
#include "common/AppendCell.glsl"
#include "common/VoxelBricks.glsl"

in vec3 gNormal;
in vec2 gUv;
flat in int gAxis;
flat in vec4 gPixelBounds;
flat in float gDepthSlope;
noperspective in float gDepth;

uniform int uResolution;
uniform vec3 uAlbedo;
#ifdef EMISSIVE
uniform vec3 uEmission;
#endif
layout(binding = 0) uniform sampler2D uAlbedoTexture;
layout(r32ui, binding = 0) uniform coherent uimage3D uAlbedoWords;
layout(r32ui, binding = 1) uniform coherent uimage3D uNormalWords;
layout(r32ui, binding = 2) uniform coherent uimage3D uEmissionWords;
uniform ivec3 uRegionLo; // voxels outside [lo, hi) are being kept
uniform ivec3 uRegionHi;

// A compare-and-swap only fails because another fragment's succeeded, so a few attempts are enough; one that
// still loses leaves its share out rather than stall the rasterizer.
const int kAttempts = 16;

ivec3 unswizzle(ivec3 c, int axis)
{
    return axis == 0 ? c.zxy : (axis == 1 ? c.yzx : c.xyz);
}

// Returns how many fragments the voxel held before this one (0: it was empty), or -1 if every attempt lost.
int addAlbedo(ivec3 voxel, vec3 albedo)
{
    uint seen = imageLoad(uAlbedoWords, voxel).r;
    for (int attempt = 0; attempt < kAttempts; ++attempt) {
        uint old = seen;
        uint n = old >> 24;
        vec3 mean = n == 0u ? albedo : mix(unpackUnorm4x8(old).rgb, albedo, 1.0 / float(n + 1u));
        seen = imageAtomicCompSwap(uAlbedoWords, voxel, old, packAlbedoWord(mean, min(n + 1u, kMaxCount)));
        if (seen == old)
            return int(n);
    }
    return -1;
}

void addNormal(ivec3 voxel, vec3 normal)
{
    uint seen = imageLoad(uNormalWords, voxel).r;
    for (int attempt = 0; attempt < kAttempts; ++attempt) {
        uint old = seen;
        uint n = old >> 24;
        vec3 mean = n == 0u ? normal : mix(unpackNormalWord(old), normal, 1.0 / float(n + 1u));
        seen = imageAtomicCompSwap(uNormalWords, voxel, old, packNormalWord(mean, min(n + 1u, kMaxCount)));
        if (seen == old)
            return;
    }
}

// `before` fragments reached the voxel ahead of this one (by the albedo word's count).
void addEmission(ivec3 voxel, vec3 emission, int before)
{
    uint seen = imageLoad(uEmissionWords, voxel).r;
    if (seen == 0u && all(equal(emission, vec3(0.0))))
        return;
    for (int attempt = 0; attempt < kAttempts; ++attempt) {
        uint old = seen;
        vec3 mean = before == 0 ? emission : mix(unpackR11G11B10F(old), emission, 1.0 / float(before + 1));
        uint next = packR11G11B10F(mean);
        if (next == old)
            return;
        seen = imageAtomicCompSwap(uEmissionWords, voxel, old, next);
        if (seen == old)
            return;
    }
}

void main()
{
#ifdef CONSERVATIVE
    if (gl_FragCoord.x < gPixelBounds.x || gl_FragCoord.y < gPixelBounds.y || gl_FragCoord.x > gPixelBounds.z
        || gl_FragCoord.y > gPixelBounds.w)
        discard;
    float spread = gDepthSlope;
#else
    float spread = 0.0;
#endif
    vec3 albedo = uAlbedo * texture(uAlbedoTexture, gUv).rgb;
    vec3 normal = gNormal;
    float len = length(normal);
    normal = len > 1e-20 ? normal / len : vec3(0.0);
#ifdef EMISSIVE
    vec3 emission = uEmission;
#else
    vec3 emission = vec3(0.0);
#endif

    float depth = gDepth;
    int first = max(int(floor(depth - spread)), 0);
    int last = min(int(floor(depth + spread)), uResolution - 1);
    for (int z = first; z <= last; ++z) {
        ivec3 voxel = unswizzle(ivec3(ivec2(gl_FragCoord.xy), z), gAxis);
        if (any(lessThan(voxel, uRegionLo)) || any(greaterThanEqual(voxel, uRegionHi)))
            continue;
        // A sparse grid's bricks hold every voxel a triangle can reach (core/BrickPool), so none is lost
        // here; tst_SparseVoxels compares the voxels listed with a dense grid's.
        ivec3 texel = voxelStoreTexel(voxel);
        if (texel.x < 0)
            continue;
        int before = addAlbedo(texel, albedo);
        if (before < 0)
            continue;
        if (before == 0)
            appendCell(voxel);
        addNormal(texel, normal);
#ifdef EMISSION_VOLUME
        addEmission(texel, emission, before);
#endif
    }
}
