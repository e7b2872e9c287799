// The first level of all six direction-dependent chains at once (see DownsampleDirectional.comp for one
// chain): all six start from the same eight children of the isotropic level 0, so fetching them once instead
// of once per direction takes the 3D fetches of the largest directional level from 48 to 8 per texel.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(binding = 0) uniform sampler3D uSource; // premultiplied radiance, a = opacity
layout(rgba16f, binding = 0) writeonly uniform image3D uTowardsPosX;
layout(rgba16f, binding = 1) writeonly uniform image3D uTowardsNegX;
layout(rgba16f, binding = 2) writeonly uniform image3D uTowardsPosY;
layout(rgba16f, binding = 3) writeonly uniform image3D uTowardsNegY;
layout(rgba16f, binding = 4) writeonly uniform image3D uTowardsPosZ;
layout(rgba16f, binding = 5) writeonly uniform image3D uTowardsNegZ;

vec4 children[8]; // index x + 2y + 4z

// For a cone travelling towards +axis (positive) the lower child of each pair along the axis is in front.
vec4 composite(int axis, bool positive)
{
    vec4 sum = vec4(0.0);
    for (int i = 0; i < 8; ++i) {
        if (((i >> axis) & 1) != 0)
            continue;
        vec4 lower = children[i];
        vec4 upper = children[i | (1 << axis)];
        vec4 front = positive ? lower : upper;
        vec4 back = positive ? upper : lower;
        sum += front + (1.0 - front.a) * back;
    }
    return sum * 0.25;
}

void main()
{
    ivec3 voxel = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(voxel, imageSize(uTowardsPosX))))
        return;
    for (int i = 0; i < 8; ++i)
        children[i] = texelFetch(uSource, voxel * 2 + ivec3(i & 1, (i >> 1) & 1, i >> 2), 0);
    imageStore(uTowardsPosX, voxel, composite(0, true));
    imageStore(uTowardsNegX, voxel, composite(0, false));
    imageStore(uTowardsPosY, voxel, composite(1, true));
    imageStore(uTowardsNegY, voxel, composite(1, false));
    imageStore(uTowardsPosZ, voxel, composite(2, true));
    imageStore(uTowardsNegZ, voxel, composite(2, false));
}
