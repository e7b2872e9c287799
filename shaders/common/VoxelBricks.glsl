// Where level 0 of the grid's voxel textures keeps voxel v. A dense grid keeps it at texel v. A sparse grid
// (voxel_mode=sparse, core/BrickPool) keeps only the bricks of 8^3 voxels that geometry can reach, each as
// 9^3 texels of a pool texture: its voxels and, on the high side of each axis, a copy of the next brick's
// first layer, so that a trilinear lookup anywhere inside a brick reads that brick alone. uBrickTable (r32ui,
// a texel per brick) holds each brick's place in the pool (1 << 31 | x | y << 10 | z << 20, in bricks), 0
// where it has none. Pool brick 0 is kept zero: loads from empty space read it; stores there are dropped.
// The same defines make every level-0 access work in both, so a pass's code does not know which it runs on.
#ifndef VOXEL_BRICKS_GLSL
#define VOXEL_BRICKS_GLSL

#include "common/Bindings.glsl"

#ifdef SPARSE_VOXELS
layout(binding = BRICK_TABLE_UNIT) uniform usampler3D uBrickTable;
const int kBrickVoxels = 8;
const int kBrickTexels = 9;

// The pool texel at the brick's first voxel, or -1 where the brick has no storage (or lies outside the grid).
ivec3 brickCorner(ivec3 brick)
{
    if (any(lessThan(brick, ivec3(0))) || any(greaterThanEqual(brick, textureSize(uBrickTable, 0))))
        return ivec3(-1);
    uint word = texelFetch(uBrickTable, brick, 0).r;
    if (word == 0u)
        return ivec3(-1);
    return ivec3(int(word & 1023u), int((word >> 10) & 1023u), int((word >> 20) & 1023u)) * kBrickTexels;
}

// Where voxel v is read: the zero brick where it has no storage.
ivec3 voxelLoadTexel(ivec3 v)
{
    ivec3 corner = brickCorner(v >> 3);
    return corner.x < 0 ? ivec3(0) : corner + (v & 7);
}

// Where voxel v is written: -1 (outside every image, so the store is dropped) where it has no storage.
ivec3 voxelStoreTexel(ivec3 v)
{
    ivec3 corner = brickCorner(v >> 3);
    return corner.x < 0 ? ivec3(-1) : corner + (v & 7);
}

// A voxel on a brick's low face is also kept in the borders of the bricks below it: a light value stored
// there goes to every copy, or lookups near the face would blend in stale light.
#define STORE_VOXEL(image, voxel, value)                                                                  \
    {                                                                                                     \
        ivec3 storeAt_ = (voxel);                                                                         \
        ivec3 onLowFace_ = ivec3(equal(storeAt_ & 7, ivec3(0)));                                          \
        for (int copy_ = 0; copy_ < 8; ++copy_) {                                                         \
            ivec3 below_ = ivec3(copy_ & 1, (copy_ >> 1) & 1, copy_ >> 2);                                \
            if (all(lessThanEqual(below_, onLowFace_))) {                                                 \
                ivec3 corner_ = brickCorner((storeAt_ >> 3) - below_);                                    \
                if (corner_.x >= 0)                                                                       \
                    imageStore(image, corner_ + (storeAt_ & 7) + below_ * kBrickVoxels, value);           \
            }                                                                                             \
        }                                                                                                 \
    }

// Level 0 of `pool` at uvw (the grid's [0, 1]^3), trilinear, as a dense volume with a zero border reads it.
// Lookups are placed by the texel below-left of uvw, whose brick holds all eight texels the lookup blends;
// below the first texel centre a dense volume fades into its border, which the weight does here.
vec4 sampleLevel0(sampler3D pool, vec3 uvw)
{
    vec3 p = uvw * vec3(textureSize(uBrickTable, 0) * kBrickVoxels);
    vec3 fade = clamp(p + 0.5, 0.0, 1.0);
    vec3 q = max(p, vec3(0.5));
    ivec3 brick = ivec3(floor(q - 0.5)) >> 3;
    ivec3 corner = brickCorner(brick);
    if (corner.x < 0)
        return vec4(0.0);
    vec3 texel = vec3(corner) + q - vec3(brick * kBrickVoxels);
    return textureLod(pool, texel / vec3(textureSize(pool, 0)), 0.0) * (fade.x * fade.y * fade.z);
}
#else
ivec3 voxelLoadTexel(ivec3 v)
{
    return v;
}
ivec3 voxelStoreTexel(ivec3 v)
{
    return v;
}
#define STORE_VOXEL(image, voxel, value) imageStore(image, voxel, value)
#define sampleLevel0(volume, uvw) textureLod(volume, uvw, 0.0)
#endif

#endif
