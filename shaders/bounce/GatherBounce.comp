// A second bounce, gathered per voxel: each surface voxel traces the diffuse cones from its own normal
// through the volume of first-bounce radiance (direct light and emission, filtered into mips) and stores
//   L = L_direct + albedo * sum_i w_i L_i,
// since the cone weights split the cosine lobe (sum_i w_i L_i = E / pi, and a Lambertian surface sends
// albedo / pi * E). Cones traced per pixel through this volume then see light that bounced twice.
#include "common/ConeMath.glsl"

#define MAX_CONES 32
#include "common/ConeTracing.glsl"

// Runs over the occupied voxels (core/OccupiedCellList); the list pass cleared the others to zero.
#include "common/OccupiedCells.glsl"

layout(local_size_x = 64) in;

layout(binding = 0) uniform sampler3D uAlbedo;
layout(binding = 1) uniform sampler3D uNormal;
layout(rgba16f, binding = 0) writeonly uniform image3D uBounced;

uniform float uConeOffset; // metres along the normal

void main()
{
    ivec3 voxel;
    if (!occupiedCell(voxel))
        return;
    vec4 albedo = texelFetch(uAlbedo, voxel, 0);
    vec4 first = texelFetch(uRadiance, voxel, 0); // premultiplied by opacity
    vec3 normalSum = texelFetch(uNormal, voxel, 0).xyz;
    float normalLength = length(normalSum);
    // Empty voxels, and voxels whose faces cancel (a two-sided sliver), keep their first-bounce value.
    if (albedo.a <= 0.0 || normalLength < 0.5 || max(albedo.r, max(albedo.g, albedo.b)) <= 0.0) {
        imageStore(uBounced, voxel, first);
        return;
    }
    vec3 n = normalSum / normalLength;
    vec3 origin = uGridOrigin + (vec3(voxel) + 0.5) * uVoxelSize + n * uConeOffset;
    vec3 gathered = gatherDiffuse(origin, n).rgb;
    imageStore(uBounced, voxel, vec4(first.rgb + albedo.rgb * gathered * albedo.a, first.a));
}
