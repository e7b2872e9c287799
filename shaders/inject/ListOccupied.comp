// First half of light injection: lists the occupied voxels of the region for InjectLight.comp and clears the
// radiance of the empty ones. Split off because llvmpipe runs a compute shader that holds the lighting code
// about four times slower per invocation even where that code is skipped (measured on the atrium: 183 ms for
// the whole grid in one shader, against 54 ms for the same dispatch without it), and most voxels are empty.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(binding = 0) uniform sampler3D uAlbedo;
layout(rgba16f, binding = 0) writeonly uniform image3D uRadiance;
// x = workgroups for the lighting dispatch (glDispatchComputeIndirect), then y and z = 1, then the count.
layout(std430, binding = 0) buffer Dispatch { uint uGroupsX; uint uGroupsY; uint uGroupsZ; uint uCount; };
layout(std430, binding = 1) writeonly buffer Occupied { uint uVoxels[]; };

uniform ivec3 uRegionOrigin;
uniform ivec3 uRegionSize;

const uint kLightingGroupSize = 64u; // InjectLight.comp's local_size_x

void main()
{
    if (any(greaterThanEqual(ivec3(gl_GlobalInvocationID), uRegionSize)))
        return;
    ivec3 voxel = uRegionOrigin + ivec3(gl_GlobalInvocationID);
    if (texelFetch(uAlbedo, voxel, 0).a <= 0.0) {
        imageStore(uRadiance, voxel, vec4(0.0));
        return;
    }
    uint index = atomicAdd(uCount, 1u);
    uVoxels[index] = uint(voxel.x) | (uint(voxel.y) << 10) | (uint(voxel.z) << 20);
    // The invocation that starts a new lighting workgroup raises the count of workgroups to include it.
    if (index % kLightingGroupSize == 0u)
        atomicMax(uGroupsX, index / kLightingGroupSize + 1u);
}
