// Averages one pixel's material into every voxel of its column that its depth spread reaches
// (common/VoxelWords.glsl), so overlapping fragments, static and dynamic alike, average instead of the last one
// winning. The update that finds a voxel empty lists it (core/OccupiedCellList) for the resolve and, after a
// full rebuild, for light injection: no pass has to search the grid for the voxels drawn. Shared by the
// rasterised path (Voxelize.frag) and the compute path for small triangles (VoxelizeSmall.comp).
// Needs uResolution, uRegionLo, uRegionHi and unswizzle() (voxelize/ProjectTriangle.glsl); EMISSION_VOLUME as
// in Voxelize.frag.
#include "common/VoxelWords.glsl"
#include "common/AppendCell.glsl"
#include "common/VoxelBricks.glsl"

layout(r32ui, binding = 0) uniform coherent uimage3D uAlbedoWords;
layout(r32ui, binding = 1) uniform coherent uimage3D uNormalWords;
layout(r32ui, binding = 2) uniform coherent uimage3D uEmissionWords;

// A compare-and-swap only fails because another fragment's succeeded, so a few attempts are enough; one that
// still loses leaves its share out rather than stall the rasterizer.
const int kAttempts = 16;

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

// `pixel` is the column in the projection along `axis`; `depth` its depth in voxels, `spread` how far to either
// side of it the triangle reaches within the pixel.
void addToColumn(ivec2 pixel, float depth, float spread, int axis, vec3 albedo, vec3 normal, vec3 emission)
{
    int first = max(int(floor(depth - spread)), 0);
    int last = min(int(floor(depth + spread)), uResolution - 1);
    for (int z = first; z <= last; ++z) {
        ivec3 voxel = unswizzle(ivec3(pixel, z), axis);
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
