// The first level of all six direction-dependent chains at once (see DownsampleDirectional.comp for one
// chain): all six start from the same eight children of the isotropic level 0, so fetching them once instead
// of once per direction takes the 3D fetches of the largest directional level from 48 to 8 per texel.
// Over the listed cells only (common/OccupiedCells.glsl, VoxelMipBuilder); the level is cleared first.
#include "common/OccupiedCells.glsl"
#include "common/VoxelBricks.glsl"

layout(local_size_x = 64) in;

layout(binding = 0) uniform sampler3D uSource; // premultiplied radiance, a = opacity
layout(rgba16f, binding = 0) writeonly uniform image3D uTowards;
#ifdef DROP_BACK_FACES
layout(binding = 1) uniform sampler3D uNormal; // the voxels' averaged normals (shorter where they cancel)
#endif
#include "common/DirectionalComposite.glsl"

void main()
{
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
    storeAllDirections(voxel);
}
