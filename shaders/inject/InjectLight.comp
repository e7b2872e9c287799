// Outgoing radiance of each voxel: Lambertian reflection of the shadowed direct light plus emission,
// stored premultiplied by opacity so that box filtering and trilinear sampling stay correct. Runs over the
// occupied voxels common/ListOccupied.comp found (it has already cleared the empty ones).
#include "common/Lights.glsl"

#include "common/OccupiedCells.glsl"

layout(local_size_x = 64) in;

layout(binding = 0) uniform sampler3D uAlbedo;
layout(binding = 1) uniform sampler3D uNormal;
layout(binding = 2) uniform sampler3D uEmission;
layout(rgba16f, binding = 0) writeonly uniform image3D uRadiance;

uniform vec3 uGridOrigin;
uniform float uVoxelSize;
uniform bool uEmissionEnabled;
uniform bool uDirectEnabled;

const float kPi = 3.14159265358979;

void main()
{
    ivec3 voxel;
    if (!occupiedCell(voxel))
        return;
    vec4 albedo = texelFetch(uAlbedo, voxel, 0);
    vec3 normalSum = texelFetch(uNormal, voxel, 0).xyz;
    float normalLength = length(normalSum);
    vec3 n = normalLength > 1e-4 ? normalSum / normalLength : vec3(0.0);
    vec3 p = uGridOrigin + (vec3(voxel) + 0.5) * uVoxelSize;

    vec3 radiance = vec3(0.0);
    if (uDirectEnabled) {
        for (int i = 0; i < lightCount(); ++i) {
            vec3 toLight = lightDirection(i, p);
            // Faces that cancel (a thin two-sided wall) are lit from whichever side the light is on.
            vec3 facing = normalLength > 0.5 ? n : (dot(n, toLight) >= 0.0 ? n : -n);
            if (normalLength <= 1e-4)
                facing = toLight;
            float cosTheta = max(dot(facing, toLight), 0.0);
            if (cosTheta <= 0.0)
                continue;
            vec3 shadowPoint = p + facing * uVoxelSize;
            radiance += albedo.rgb / kPi * lightIrradiance(i, p, shadowPoint) * cosTheta;
        }
    }
    if (uEmissionEnabled)
        radiance += texelFetch(uEmission, voxel, 0).rgb;
    imageStore(uRadiance, voxel, vec4(radiance * albedo.a, albedo.a));
}
