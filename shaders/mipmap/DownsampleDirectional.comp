// One level of a direction-dependent mip chain (Crassin et al.'s anisotropic voxels): for a cone travelling
// along uAxisSign * axis, each pair of children along that axis is composited front to back before the four
// pairs are averaged, so a thin wall facing the cone stays opaque at coarse levels instead of fading to 1/2^k.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(binding = 0) uniform sampler3D uSource; // premultiplied radiance, a = opacity
layout(rgba16f, binding = 0) writeonly uniform image3D uTarget;
uniform int uSourceLevel;
uniform int uAxis;       // 0 = x, 1 = y, 2 = z
uniform int uAxisSign;   // +1: the cone travels towards +axis, so the lower child is in front

void main()
{
    ivec3 voxel = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(voxel, imageSize(uTarget))))
        return;
    ivec3 along = ivec3(uAxis == 0, uAxis == 1, uAxis == 2);
    ivec3 u = ivec3(uAxis == 1, uAxis == 2, uAxis == 0);
    ivec3 v = ivec3(uAxis == 2, uAxis == 0, uAxis == 1);
    ivec3 base = voxel * 2;
    ivec3 frontOffset = uAxisSign > 0 ? ivec3(0) : along;
    ivec3 backOffset = uAxisSign > 0 ? along : ivec3(0);
    vec4 sum = vec4(0.0);
    for (int i = 0; i < 4; ++i) {
        ivec3 lateral = u * (i & 1) + v * (i >> 1);
        vec4 front = texelFetch(uSource, base + lateral + frontOffset, uSourceLevel);
        vec4 back = texelFetch(uSource, base + lateral + backOffset, uSourceLevel);
        sum += front + (1.0 - front.a) * back;
    }
    imageStore(uTarget, voxel, sum * 0.25);
}
