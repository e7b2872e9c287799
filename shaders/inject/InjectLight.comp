// Outgoing radiance of each voxel: Lambertian reflection of the shadowed direct light plus emission,
// stored premultiplied by opacity so that box filtering and trilinear sampling stay correct. Runs over the
// occupied voxels common/ListOccupied.comp found (it has already cleared the empty ones).
#include "common/Lights.glsl"
#include "common/AreaLights.glsl"

#include "common/OccupiedCells.glsl"
#include "common/VoxelBricks.glsl"

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

// The side a voxel is lit on: its normal; for faces that cancel (a thin two-sided wall) whichever side the
// light is on, and a voxel with no normal at all faces the light.
vec3 facingLight(vec3 n, float normalLength, vec3 toLight)
{
    vec3 facing = normalLength > 0.5 ? n : (dot(n, toLight) >= 0.0 ? n : -n);
    return normalLength <= 1e-4 ? toLight : facing;
}

void main()
{
    ivec3 voxel;
    if (!occupiedCell(voxel))
        return;
    ivec3 texel = voxelLoadTexel(voxel);
    vec4 albedo = texelFetch(uAlbedo, texel, 0);
    vec3 normalSum = texelFetch(uNormal, texel, 0).xyz;
    float normalLength = length(normalSum);
    vec3 n = normalLength > 1e-4 ? normalSum / normalLength : vec3(0.0);
    vec3 p = uGridOrigin + (vec3(voxel) + 0.5) * uVoxelSize;

    // One loop per light kind with compile-time counts (passes/InjectLightPass): a loop over both kinds
    // branching on the index runs every kind's code for every voxel on llvmpipe.
    vec3 radiance = vec3(0.0);
    if (uDirectEnabled) {
        for (int i = 0; i < kPointLightCount; ++i) {
            vec3 d = uPointLightPosition[i].xyz - p;
            // A floor only at the light itself, relative to the scene as every bias is: an absolute one would bend
            // the light of a scene measured in 1e-4 units (tests/hardcases, scale invariance).
            float distance2 = max(dot(d, d), uPointShadowNear * uPointShadowNear);
            vec3 toLight = normalize(d);
            vec3 facing = facingLight(n, normalLength, toLight);
            float visibility = pointLightVisibility(i, p + facing * uVoxelSize, facing);
            radiance += albedo.rgb / kPi * uPointLightIntensity[i].rgb * spotFactor(i, p) / distance2 * visibility
                * max(dot(facing, toLight), 0.0);
        }
        for (int i = 0; i < kDirectionalLightCount; ++i) {
            vec3 toLight = -normalize(uDirectionalLightDirection[i].xyz);
            vec3 facing = facingLight(n, normalLength, toLight);
            float visibility = directionalLightVisibility(i, p + facing * uVoxelSize, facing);
            radiance += albedo.rgb / kPi * uDirectionalLightIrradiance[i].rgb * visibility * max(dot(facing, toLight), 0.0);
        }
        if (kAreaLightCount > 0) {
            // A voxel with no one normal faces the first light's way; the shadow cone starts a voxel out, as the
            // shadow-map lookups do.
            vec3 toLight = normalize(texelFetch(uAreaLights, 1).xyz - p);
            vec3 facing = facingLight(n, normalLength, toLight);
            radiance += albedo.rgb / kPi * areaLightIrradiance(p, facing, uVoxelSize);
        }
    }
    if (uEmissionEnabled)
        radiance += texelFetch(uEmission, texel, 0).rgb;
    STORE_VOXEL(uRadiance, voxel, vec4(radiance * albedo.a, albedo.a));
}
