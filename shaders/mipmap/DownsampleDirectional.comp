// One level of the six direction-dependent mip chains (Crassin et al.'s anisotropic voxels), all tiles of the
// stack (gl::Texture::create3DStack: tile k starts at z = 2k tiles) in one dispatch: for a cone travelling along +-axis, each pair of children
// along that axis is composited front to back before the four pairs are averaged, so a thin wall facing the
// cone stays opaque at coarse levels instead of fading to 1/2^k.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(binding = 0) uniform sampler3D uSource; // the stack itself, read one level finer than written
layout(rgba16f, binding = 0) writeonly uniform image3D uTarget;
uniform int uSourceLevel;

const int kTiles = 6; // +x, -x, +y, -y, +z, -z

void main()
{
    ivec3 targetSize = imageSize(uTarget);
    int tileSize = targetSize.x;
    // The dispatch rounds each tile up to whole work groups: z runs over kTiles such padded tiles.
    int paddedTile = (tileSize + 3) / 4 * 4;
    ivec3 id = ivec3(gl_GlobalInvocationID);
    int tile = id.z / paddedTile;
    ivec3 voxel = ivec3(id.xy, id.z - tile * paddedTile);
    if (tile >= kTiles || any(greaterThanEqual(voxel, ivec3(tileSize))))
        return;
    int axis = tile / 2;
    bool positive = (tile & 1) == 0; // the cone travels towards +axis, so the lower child is in front
    ivec3 along = ivec3(axis == 0, axis == 1, axis == 2);
    ivec3 u = ivec3(axis == 1, axis == 2, axis == 0);
    ivec3 v = ivec3(axis == 2, axis == 0, axis == 1);
    ivec3 base = voxel * 2 + ivec3(0, 0, 2 * tile * tileSize * 2); // tile k starts at z = 2k tiles
    ivec3 frontOffset = positive ? ivec3(0) : along;
    ivec3 backOffset = positive ? along : ivec3(0);
    vec4 sum = vec4(0.0);
    for (int i = 0; i < 4; ++i) {
        ivec3 lateral = u * (i & 1) + v * (i >> 1);
        vec4 front = texelFetch(uSource, base + lateral + frontOffset, uSourceLevel);
        vec4 back = texelFetch(uSource, base + lateral + backOffset, uSourceLevel);
        sum += front + (1.0 - front.a) * back;
    }
    imageStore(uTarget, voxel + ivec3(0, 0, 2 * tile * tileSize), sum * 0.25);
}
