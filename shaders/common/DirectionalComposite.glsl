// The first level of all six direction-dependent chains from one cell's eight children (Crassin et al.'s
// anisotropic voxels), shared by the mip filter (mipmap/DownsampleAllDirections.comp) and the bounce solve's
// reinjection, which filters the voxels it has just lit (bounce/ReinjectBounce.comp). The includer fills
// children[] (premultiplied radiance, a = opacity; index x + 2y + 4z) and, with DROP_BACK_FACES, normals[] (the
// voxels' averaged normals, shorter where they cancel), and declares uTowards: the chains' first level as tiles
// stacked along z, +x, -x, +y, -y, +z, -z (common/DirectionalStack.glsl).
#include "common/DirectionalStack.glsl"

uniform int uTileStride; // texels from one tile's start to the next at the level written

vec4 children[8];

#ifdef DROP_BACK_FACES
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

// Writes the six chains' texels of `cell` (one level above the children).
void storeAllDirections(ivec3 cell)
{
    // Spelled out, not looped: with constant arguments composite() indexes children[] statically, which
    // llvmpipe turns into registers; a loop variable made it index memory and doubled the mip pass.
    ivec3 tile = ivec3(0, 0, uTileStride); // a tile and the gap after it
    imageStore(uTowards, cell, composite(0, true));
    imageStore(uTowards, cell + tile, composite(0, false));
    imageStore(uTowards, cell + 2 * tile, composite(1, true));
    imageStore(uTowards, cell + 3 * tile, composite(1, false));
    imageStore(uTowards, cell + 4 * tile, composite(2, true));
    imageStore(uTowards, cell + 5 * tile, composite(2, false));
}
