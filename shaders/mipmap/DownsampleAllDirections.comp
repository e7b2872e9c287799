// The first level of all six direction-dependent chains at once (see DownsampleDirectional.comp for one
// chain): all six start from the same eight children of the isotropic level 0, so fetching them once instead
// of once per direction takes the 3D fetches of the largest directional level from 48 to 8 per texel.
// Over the listed cells only (common/OccupiedCells.glsl, VoxelMipBuilder); the level is cleared first.
#include "common/DirectionalStack.glsl"
#include "common/OccupiedCells.glsl"
#include "common/VoxelBricks.glsl"

layout(local_size_x = 64) in;
uniform int uTileStride; // texels from one tile's start to the next at the level written

layout(binding = 0) uniform sampler3D uSource; // premultiplied radiance, a = opacity
// The six chains' first level as tiles stacked along z: +x, -x, +y, -y, +z, -z (common/DirectionalStack.glsl).
layout(rgba16f, binding = 0) writeonly uniform image3D uTowards;

vec4 children[8]; // index x + 2y + 4z

#ifdef DROP_BACK_FACES
layout(binding = 1) uniform sampler3D uNormal; // the voxels' averaged normals (shorter where they cancel)
vec3 normals[8];

// A voxel's light leaves its surface's front side, and a cone travelling the way that surface faces has left it
// behind: the cone's own surface, which coarse lookups near its start reach, or the back of one seen from
// behind. Such a voxel gives that chain neither light nor opacity (its own surface lit and shaded every cone
// that left it: ceilings beside a light's hot spot gathered over twice the path tracer's light;
// docs/ACCURACY.md, "Back faces and the grid's faces"). It fades out over the first 15 degrees past
// edge-on; a voxel whose normals cancel (a wall thinner than a voxel, seen from both sides) shows on every
// side.
vec4 seenTravelling(int child, vec3 travel)
{
    vec3 normalSum = normals[child];
    float oneSided = step(0.5, length(normalSum));
    return children[child] * (1.0 - oneSided * clamp(4.0 * dot(normalize(normalSum + 1e-6), travel), 0.0, 1.0));
}
#else
#define seenTravelling(child, travel) children[child]
#endif

// For a cone travelling towards +axis (positive) the lower child of each pair along the axis is in front.
vec4 composite(int axis, bool positive)
{
    vec4 sum = vec4(0.0);
    for (int i = 0; i < 8; ++i) {
        if (((i >> axis) & 1) != 0)
            continue;
        vec3 travel = vec3(0.0);
        travel[axis] = positive ? 1.0 : -1.0;
        vec4 lower = seenTravelling(i, travel);
        vec4 upper = seenTravelling(i | (1 << axis), travel);
        vec4 front = positive ? lower : upper;
        vec4 back = positive ? upper : lower;
        sum += front + (1.0 - front.a) * back;
    }
    return sum * 0.25;
}

void main()
{
    int tileSize = imageSize(uTowards).x;
    ivec3 voxel;
    if (!occupiedCell(voxel))
        return;
    // A parent's eight children lie in one brick of a sparse grid.
    ivec3 first = voxelLoadTexel(voxel * 2);
    for (int i = 0; i < 8; ++i) {
        ivec3 child = first + ivec3(i & 1, (i >> 1) & 1, i >> 2);
        children[i] = texelFetch(uSource, child, 0);
#ifdef DROP_BACK_FACES
        normals[i] = texelFetch(uNormal, child, 0).xyz;
#endif
    }
    // Spelled out, not looped: with constant arguments composite() indexes children[] statically, which
    // llvmpipe turns into registers; a loop variable made it index memory and doubled the mip pass.
    ivec3 tile = ivec3(0, 0, uTileStride); // a tile and the gap after it
    imageStore(uTowards, voxel, composite(0, true));
    imageStore(uTowards, voxel + tile, composite(0, false));
    imageStore(uTowards, voxel + 2 * tile, composite(1, true));
    imageStore(uTowards, voxel + 3 * tile, composite(1, false));
    imageStore(uTowards, voxel + 4 * tile, composite(2, true));
    imageStore(uTowards, voxel + 5 * tile, composite(2, false));
}
