// The irradiance cache (passes/VoxelIrradiancePass): one gather of the diffuse cones per cell of uCellSize^3
// voxels that holds a single-sided surface. The cell's surface is summarised by the mean position and mean
// normal of its surface voxels; the cones start there, as a pixel's would, and what they gather,
// sum_i w_i L_i, is stored with the ambient visibility in alpha (a = -1: no such surface in the cell).
// Irradiance varies slowly over a surface, so a 2^3 cell costs an eighth of a per-voxel gather and
// pixels interpolate between cells.
#include "common/ConeMath.glsl"

#define MAX_CONES 32
#include "common/ConeTracing.glsl"

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(binding = 0) uniform sampler3D uAlbedo;
layout(binding = 1) uniform sampler3D uNormal;
layout(rgba16f, binding = 0) writeonly uniform image3D uIrradiance;
layout(rgba16f, binding = 1) writeonly uniform image3D uCellNormal; // xyz: mean unit normal, w: 1 = valid

uniform int uResolution; // voxels per side
uniform int uCellSize;   // voxels per cell side
uniform float uConeOffset; // metres along the normal

void main()
{
    ivec3 cell = ivec3(gl_GlobalInvocationID);
    int cells = uResolution / uCellSize;
    if (any(greaterThanEqual(cell, ivec3(cells))))
        return;
    vec3 normalSum = vec3(0.0);
    vec3 positionSum = vec3(0.0);
    float count = 0.0;
    for (int z = 0; z < uCellSize; ++z)
        for (int y = 0; y < uCellSize; ++y)
            for (int x = 0; x < uCellSize; ++x) {
                ivec3 voxel = cell * uCellSize + ivec3(x, y, z);
                if (texelFetch(uAlbedo, voxel, 0).a <= 0.0)
                    continue;
                vec3 n = texelFetch(uNormal, voxel, 0).xyz;
                // Voxels whose faces cancel (a two-sided sliver) say nothing about which way the surface faces.
                if (dot(n, n) < 0.25)
                    continue;
                normalSum += normalize(n);
                positionSum += vec3(voxel) + 0.5;
                count += 1.0;
            }
    float normalLength = length(normalSum);
    // Faces that disagree (a corner, both sides of a wall) average to a short normal: no single surface.
    if (count == 0.0 || normalLength < 0.5 * count) {
        imageStore(uIrradiance, cell, vec4(0.0, 0.0, 0.0, -1.0));
        imageStore(uCellNormal, cell, vec4(0.0));
        return;
    }
    vec3 n = normalSum / normalLength;
    vec3 origin = uGridOrigin + positionSum / count * uVoxelSize + n * uConeOffset;
    imageStore(uIrradiance, cell, gatherDiffuse(origin, n));
    imageStore(uCellNormal, cell, vec4(n, 1.0));
}
