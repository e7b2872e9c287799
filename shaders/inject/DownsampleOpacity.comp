// One level of the opacity volume (VoxelVolume::opacity) from the level below. Channel k holds the opacity a
// ray along axis k meets crossing the texel: each of the four pairs of children along that axis is composited
// (1 - (1 - a_front)(1 - a_back), the same either way), and the four are averaged. A wall one voxel thin then
// stays opaque at every level to a shadow cone crossing it, as it does to the radiance cones of the
// directional mips; box filtering would thin it to 1 / 2^level.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(binding = 0) uniform sampler3D uSource; // the opacity volume, level uSourceLevel read
layout(rgba8, binding = 0) writeonly uniform image3D uTarget;
uniform int uSourceLevel;

float crossing(vec3 a, vec3 b, int axis)
{
    return 1.0 - (1.0 - a[axis]) * (1.0 - b[axis]);
}

void main()
{
    ivec3 parent = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(parent, imageSize(uTarget))))
        return;
    vec3 c[8];
    for (int i = 0; i < 8; ++i)
        c[i] = texelFetch(uSource, 2 * parent + ivec3(i & 1, (i >> 1) & 1, i >> 2), uSourceLevel).rgb;
    // Child i has x = i & 1, y = (i >> 1) & 1, z = i >> 2: pairs along x differ by 1, along y by 2, along z by 4.
    vec3 result;
    result.x = 0.25 * (crossing(c[0], c[1], 0) + crossing(c[2], c[3], 0) + crossing(c[4], c[5], 0) + crossing(c[6], c[7], 0));
    result.y = 0.25 * (crossing(c[0], c[2], 1) + crossing(c[1], c[3], 1) + crossing(c[4], c[6], 1) + crossing(c[5], c[7], 1));
    result.z = 0.25 * (crossing(c[0], c[4], 2) + crossing(c[1], c[5], 2) + crossing(c[2], c[6], 2) + crossing(c[3], c[7], 2));
    imageStore(uTarget, parent, vec4(result, 1.0));
}
