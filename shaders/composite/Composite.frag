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
uniform int uDivisor;        // the indirect targets are 1/uDivisor of the screen per axis

// Joint bilateral upsampling: the four nearest traced pixels, weighted bilinearly and by how well their
// surface (the full-resolution pixel each was traced from) matches this pixel's plane and normal, so light
// does not bleed across depth or orientation edges.
void fetchIndirect(ivec2 pixel, vec3 p, vec3 n, out vec4 diffuse, out vec3 specular)
{
    if (uDivisor == 1) {
        diffuse = texelFetch(uIndirectDiffuse, pixel, 0);
        specular = texelFetch(uIndirectSpecular, pixel, 0).rgb;
        return;
    }
    ivec2 lowSize = textureSize(uIndirectDiffuse, 0);
    ivec2 fullSize = textureSize(gPosition, 0);
    vec2 low = (vec2(pixel) + 0.5) / float(uDivisor) - 0.5;
    ivec2 base = ivec2(floor(low));
    vec2 f = low - vec2(base);
    vec4 diffuseSum = vec4(0.0);
    vec3 specularSum = vec3(0.0);
    float weightSum = 0.0;
    float bestWeight = -1.0;
    vec4 bestDiffuse = vec4(0.0, 0.0, 0.0, 1.0);
    vec3 bestSpecular = vec3(0.0);
    for (int i = 0; i < 4; ++i) {
        ivec2 offset = ivec2(i & 1, i >> 1);
        ivec2 q = clamp(base + offset, ivec2(0), lowSize - 1);
        ivec2 source = min(q * uDivisor + uDivisor / 2, fullSize - 1);
        vec4 qp = texelFetch(gPosition, source, 0);
        vec3 qn = texelFetch(gNormal, source, 0).xyz;
        float bilinear = (offset.x == 1 ? f.x : 1.0 - f.x) * (offset.y == 1 ? f.y : 1.0 - f.y);
        float planeDistance = abs(dot(qp.xyz - p, n)) / max(uShadowOffset * 2.0, 1e-6); // in voxels
        float similarity = qp.a > 0.0 ? pow(max(dot(qn, n), 0.0), 8.0) * exp(-planeDistance) : 0.0;
        float w = (bilinear + 1e-3) * similarity;
        vec4 d = texelFetch(uIndirectDiffuse, q, 0);
        vec3 s = texelFetch(uIndirectSpecular, q, 0).rgb;
        diffuseSum += w * d;
        specularSum += w * s;
        weightSum += w;
        if (similarity > bestWeight) {
            bestWeight = similarity;
            bestDiffuse = d;
            bestSpecular = s;
        }
    }
    if (weightSum > 1e-4) {
        diffuse = diffuseSum / weightSum;
        specular = specularSum / weightSum;
    } else { // no neighbour lies on this surface: take the closest match rather than nothing
        diffuse = bestDiffuse;
        specular = bestSpecular;
    }
}

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
    vec4 indirectDiffuse;
    vec3 indirectSpecular;
    fetchIndirect(pixel, p, n, indirectDiffuse, indirectSpecular);
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
