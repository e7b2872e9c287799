// Lists the non-empty voxels of one mip level with the value of the chosen channel, for the inspector's
// instanced cubes. Radiance and opacity come from the real mip chain; albedo, normal and emission have no
// mips, so their coarse levels are box-filtered here from level 0 (only when the inspector asks).
#define CHANNEL_ALBEDO 0
#define CHANNEL_RADIANCE 1
#define CHANNEL_OPACITY 2
#define CHANNEL_NORMAL 3
#define CHANNEL_EMISSION 4

#include "common/VoxelBricks.glsl"

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(binding = 0) uniform sampler3D uRadiance;
layout(binding = 1) uniform sampler3D uChannel; // level 0 of albedo, normal or emission
layout(binding = 2) uniform sampler3D uAlbedo;  // its alpha is the level-0 opacity

struct VoxelEntry {
    ivec4 coord; // xyz at the chosen level
    vec4 value;
};
layout(std430, binding = 0) writeonly buffer Entries { VoxelEntry entries[]; };
layout(std430, binding = 1) buffer Counter { uint count; };

uniform int uLevel;
uniform int uChannelKind;
uniform int uLevelSize;
uniform uint uCapacity;

void main()
{
    ivec3 voxel = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(voxel, ivec3(uLevelSize))))
        return;
    float opacity;
    vec4 value;
    if (uChannelKind == CHANNEL_RADIANCE || uChannelKind == CHANNEL_OPACITY) {
        vec4 r = texelFetch(uRadiance, voxel, uLevel);
        opacity = r.a;
        value = uChannelKind == CHANNEL_RADIANCE ? vec4(r.a > 0.0 ? r.rgb / r.a : vec3(0.0), r.a) : vec4(r.aaa, r.a);
    } else {
        int block = 1 << uLevel;
        vec4 sum = vec4(0.0);
        float covered = 0.0;
        for (int z = 0; z < block; ++z)
            for (int y = 0; y < block; ++y)
                for (int x = 0; x < block; ++x) {
                    ivec3 c = voxelLoadTexel(voxel * block + ivec3(x, y, z));
                    float a = texelFetch(uAlbedo, c, 0).a;
                    if (a > 0.0) {
                        sum += texelFetch(uChannel, c, 0);
                        covered += 1.0;
                    }
                }
        opacity = covered / float(block * block * block);
        // The mean over the surface voxels in the block, which is what the user compares with level 0.
        value = vec4(covered > 0.0 ? sum.rgb / covered : vec3(0.0), opacity);
    }
    if (opacity <= 0.0)
        return;
    uint slot = atomicAdd(count, 1u);
    if (slot < uCapacity)
        entries[slot] = VoxelEntry(ivec4(voxel, 0), value);
}
