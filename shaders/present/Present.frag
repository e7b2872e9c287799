// Shows the linear frame on screen: exposure, the Narkowicz ACES fit and the sRGB curve, matching
// app/imageio/ToneMapper (the PNG writer) so the viewport and an exported PNG agree.
layout(binding = 0) uniform sampler2D uRadiance;
uniform float uExposure;
uniform vec4 uTarget; // x, y, width, height of the target rectangle in window pixels

layout(location = 0) out vec4 oColor;

vec3 filmic(vec3 x)
{
    return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

vec3 srgbOetf(vec3 c)
{
    return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}

void main()
{
    vec2 uv = (gl_FragCoord.xy - uTarget.xy) / uTarget.zw;
    vec3 radiance = texture(uRadiance, uv).rgb;
    // Non-finite values show as magenta instead of poisoning the filter.
    if (any(isnan(radiance)) || any(isinf(radiance)))
        radiance = vec3(1.0, 0.0, 1.0);
    oColor = vec4(srgbOetf(filmic(max(radiance, 0.0) * uExposure)), 1.0);
}
