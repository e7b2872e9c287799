// The trilinear 3D sampling rate this machine can sustain (vct-bench perf): every fragment walks uRays rays
// of uSteps textureLod fetches through an RGBA16F volume with a full mip chain. Like cones, neighbouring
// fragments sample neighbouring texels and the level grows, fractionally, along each ray; unlike cones there
// is no early exit and no other work, so the fetches are the whole cost.
layout(binding = 0) uniform sampler3D uVolume;

uniform int uRays;
uniform int uSteps;
uniform float uMaxLevel;
uniform vec2 uSize; // target width, height in pixels

layout(location = 0) out vec4 oSum;

const vec3 kDirections[6] = vec3[6](vec3(0.0, 0.0, 1.0), vec3(0.8, 0.0, 0.6), vec3(-0.8, 0.0, 0.6),
    vec3(0.0, 0.8, 0.6), vec3(0.0, -0.8, 0.6), vec3(0.6, 0.6, -0.52915));

void main()
{
    vec2 p = gl_FragCoord.xy / uSize;
    vec3 origin = vec3(0.3 + 0.4 * p, 0.5);
    vec4 sum = vec4(0.0);
    for (int r = 0; r < uRays; ++r) {
        vec3 dir = kDirections[r % 6];
        for (int s = 0; s < uSteps; ++s) {
            float f = (float(s) + 0.5) / float(uSteps);
            // Stays inside [0.05, 0.95]^3, so no fetch is answered by the border colour alone.
            sum += textureLod(uVolume, origin + dir * (0.25 * f), uMaxLevel * f);
        }
    }
    // Written so the compiler cannot drop the fetches.
    oSum = sum;
}
