in vec4 vValue;
in vec3 vNormal;

uniform int uChannelKind; // as in CompactVoxels.comp
uniform float uExposure;

layout(location = 0) out vec4 oColor;

vec3 srgbOetf(vec3 c)
{
    return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}

void main()
{
    vec3 c = vValue.rgb;
    if (uChannelKind == 3)
        c = c * 0.5 + 0.5; // normals as colours
    else if (uChannelKind == 1 || uChannelKind == 4)
        c = c * uExposure / (1.0 + c * uExposure); // HDR radiance: a simple curve keeps bright voxels readable
    // Fixed shading by face so the cubes read as solids.
    float shade = 0.75 + 0.25 * abs(dot(vNormal, normalize(vec3(0.3, 0.8, 0.5))));
    oColor = vec4(srgbOetf(clamp(c * shade, 0.0, 1.0)), 1.0);
}
