// The frame's linear radiance: emission + shadowed direct light + albedo * indirect diffuse
// + specular * indirect specular. Tone mapping happens later, only for 8-bit output.
#include "common/Lights.glsl"

layout(binding = 0) uniform sampler2D gPosition;
layout(binding = 1) uniform sampler2D gNormal;
layout(binding = 2) uniform sampler2D gAlbedo;
layout(binding = 3) uniform sampler2D gSpecular;
layout(binding = 4) uniform sampler2D gEmission;
layout(binding = 5) uniform sampler2D uIndirectDiffuse;
layout(binding = 6) uniform sampler2D uIndirectSpecular;

uniform vec3 uCameraPosition;
uniform bool uDirectEnabled;
uniform bool uIndirectDiffuseEnabled;
uniform bool uIndirectSpecularEnabled;
uniform bool uEmissionEnabled;
uniform bool uAoAvailable; // the cone pass computed ambient occlusion this frame
uniform int uView; // RenderSettings::view
uniform float uShadowOffset; // metres along the normal for shadow lookups

layout(location = 0) out vec4 oRadiance;

const float kPi = 3.14159265358979;

void main()
{
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec4 position = texelFetch(gPosition, pixel, 0);
    if (position.a <= 0.0) {
        oRadiance = vec4(0.0, 0.0, 0.0, 1.0);
        return;
    }
    vec3 p = position.xyz;
    vec4 normalShininess = texelFetch(gNormal, pixel, 0);
    vec3 n = normalShininess.xyz;
    float shininess = normalShininess.w;
    vec3 albedo = texelFetch(gAlbedo, pixel, 0).rgb;
    vec3 specular = texelFetch(gSpecular, pixel, 0).rgb;
    vec3 emission = texelFetch(gEmission, pixel, 0).rgb;
    vec4 indirectDiffuse = texelFetch(uIndirectDiffuse, pixel, 0);
    vec3 indirectSpecular = texelFetch(uIndirectSpecular, pixel, 0).rgb;
    vec3 toEye = normalize(uCameraPosition - p);
    bool glossy = shininess > 0.0 && max(specular.r, max(specular.g, specular.b)) > 0.0;

    vec3 direct = vec3(0.0);
    if (uDirectEnabled) {
        vec3 mirror = reflect(-toEye, n);
        for (int i = 0; i < lightCount(); ++i) {
            vec3 toLight = lightDirection(i, p);
            float cosTheta = dot(n, toLight);
            if (cosTheta <= 0.0)
                continue;
            vec3 irradiance = lightIrradiance(i, p, p + n * uShadowOffset) * cosTheta;
            vec3 brdf = albedo / kPi;
            if (glossy) // normalised modified Phong
                brdf += specular * (shininess + 2.0) / (2.0 * kPi) * pow(max(dot(mirror, toLight), 0.0), shininess);
            direct += brdf * irradiance;
        }
    }
    vec3 diffuseIndirect = uIndirectDiffuseEnabled ? albedo * indirectDiffuse.rgb : vec3(0.0);
    vec3 specularIndirect = uIndirectSpecularEnabled && glossy ? specular * indirectSpecular : vec3(0.0);
    vec3 emitted = uEmissionEnabled ? emission : vec3(0.0);

    vec3 result = emitted + direct + diffuseIndirect + specularIndirect;
    if (uView == 1) result = direct;
    else if (uView == 2) result = diffuseIndirect;
    else if (uView == 3) result = specularIndirect;
    else if (uView == 4) result = vec3(uAoAvailable ? indirectDiffuse.a : 1.0);
    else if (uView == 5) result = albedo;
    else if (uView == 6) result = n * 0.5 + 0.5;
    else if (uView == 7) result = emitted;
    oRadiance = vec4(result, 1.0);
}
