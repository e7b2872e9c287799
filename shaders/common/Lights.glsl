// Analytic lights with shadow maps, shared by voxel injection and the per-pixel composite.
// Units: point intensity W/sr, directional irradiance W/m^2; results are irradiance (W/m^2) or radiance.
#include "common/Bindings.glsl"

// Compile-time light counts (POINT_LIGHT_COUNT, DIRECTIONAL_LIGHT_COUNT: the composite and injection variants):
// with a loop per kind and a count known to the compiler, llvmpipe unrolls each loop and drops the code of a
// kind the scene does not have. A loop over both kinds that branches on the index ran every kind's code in
// every lane instead (docs/DESIGN.md, "Measured choices").
#define kPointLightCount POINT_LIGHT_COUNT
#define kDirectionalLightCount DIRECTIONAL_LIGHT_COUNT
uniform vec4 uPointLightPosition[MAX_POINT_LIGHTS];  // w = 1 when it casts shadows
uniform vec4 uPointLightIntensity[MAX_POINT_LIGHTS]; // w: the cosine of a spot's inner angle (-1: not a spot)
uniform vec4 uPointLightSpot[MAX_POINT_LIGHTS];      // a spot's axis, w: the cosine of its outer angle (-2: none)
uniform float uPointShadowNear;
uniform float uPointShadowFar;
uniform vec4 uDirectionalLightDirection[MAX_DIRECTIONAL_LIGHTS]; // travel direction, w = shadows
uniform vec4 uDirectionalLightIrradiance[MAX_DIRECTIONAL_LIGHTS];
uniform mat4 uDirectionalLightMatrix[MAX_DIRECTIONAL_LIGHTS];
// Light sizes for soft shadows: a point light's radius (metres) and the tangent of a directional light's angular
// radius; 0 keeps the hard shadow filtered to the texel.
uniform float uPointLightRadius[MAX_POINT_LIGHTS];
uniform float uDirectionalLightTanHalf[MAX_DIRECTIONAL_LIGHTS];
// Comparison samplers (gl::Texture::setDepthComparison): each lookup is the bilinear average of the four nearest
// texels' depth tests, so shadow edges are texel-area averages, as a reference image's are, not steps.
layout(binding = POINT_SHADOW_UNIT) uniform samplerCubeArrayShadow uPointShadow;
layout(binding = DIRECTIONAL_SHADOW_UNIT) uniform sampler2DArrayShadow uDirectionalShadow;
// The same maps as raw depth (a sampler object without comparison), for the soft shadows' blocker search.
layout(binding = POINT_DEPTH_UNIT) uniform samplerCubeArray uPointShadowDepth;
layout(binding = DIRECTIONAL_DEPTH_UNIT) uniform sampler2DArray uDirectionalShadowDepth;

// Soft shadows of lights with a size (percentage-closer soft shadows, Fernando 2005): the mean depth of the
// blockers found around the receiver's direction sets the penumbra, light size x (receiver - blocker) /
// blocker, and a percentage-closer filter of that width gives the share of the light the receiver sees. A
// uniform disk kernel over a straight edge gives the same profile as a disk light behind it. Taps on a Vogel
// spiral (uniform over the disk), the same at every pixel: no noise, and with each tap a bilinear comparison
// the steps between taps stay below a 24th of the light.
// Compiled in only where some shadow-casting light has a size (SOFT_SHADOWS, renderer/core/LightUniforms.h):
// llvmpipe runs both sides of a uniform branch, so the blocker search and filter would cost every pixel of a
// scene whose lights are all points (measured in docs/BENCHMARKS.md, "Light transport").
const int kSoftShadowTaps = 24;
const float kGoldenAngle = 2.39996323;

vec2 softShadowTap(int k)
{
    float r = sqrt((float(k) + 0.5) / float(kSoftShadowTaps));
    float a = float(k) * kGoldenAngle;
    return r * vec2(cos(a), sin(a));
}

// Window depth of a cube face for view depth z (the major-axis component), and back.
float pointWindowDepth(float z)
{
    float n = uPointShadowNear, f = uPointShadowFar;
    return f * (z - n) / (z * (f - n));
}
float pointViewDepth(float w)
{
    float n = uPointShadowNear, f = uPointShadowFar;
    return f * n / (f - w * (f - n));
}
float majorAxis(vec3 v)
{
    vec3 a = abs(v);
    return max(a.x, max(a.y, a.z));
}

// The share of point light i's intensity sent toward p: 1 for an isotropic light; for a spot, a smoothstep in
// the cosine from its outer to its inner angle (scene/PointLight.h::spotFactor, the same function).
float spotFactor(int i, vec3 p)
{
    float outer = uPointLightSpot[i].w, inner = uPointLightIntensity[i].w;
    float c = dot(normalize(p - uPointLightPosition[i].xyz), uPointLightSpot[i].xyz);
    if (inner - outer <= 1e-6)
        return c >= outer ? 1.0 : 0.0;
    float t = clamp((c - outer) / (inner - outer), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

// Where a pixel's shadow lookup starts: off its surface along the normal by half the map's texel there (a cube
// face's texel grows with the distance along its major axis, an orthographic map's does not), so that a
// surface does not shadow itself between the texel centres that sample it. An offset in voxels let every
// surface within that distance of its blocker, or lit at a grazing angle, escape its shadow on coarse grids
// (the Sponza's direct light 8.5% over the path tracer's at 128^3); below half a texel a point light's
// receivers shadow themselves (docs/ACCURACY.md, "Shadow lookups at the shadow map's scale").
const float kShadowNormalTexels = 0.5;
// Never less than a few steps of float at p: far from the origin (a scene placed at 1e5) positions round to
// more than a texel, and a surface shadowed itself (tst_HardCases::scaleAndOffsetInvariance).
const float kShadowPositionSteps = 4.0;
// A directional map's depth bias, in window depth (its range spans the scene): with the lookup off the surface
// it only absorbs depth quantisation, and 2e-3 (8 cm on the Sponza) let contact shadows through.
const float kDirectionalDepthBias = 5e-4;
vec3 shadowOrigin(vec3 p, vec3 n, float texel)
{
    float floatStep = majorAxis(p) * exp2(-23.0);
    return p + n * max(kShadowNormalTexels * texel, kShadowPositionSteps * floatStep);
}
vec3 pointShadowOrigin(int i, vec3 p, vec3 n)
{
    return shadowOrigin(p, n, 2.0 * majorAxis(p - uPointLightPosition[i].xyz) / float(textureSize(uPointShadow, 0).x));
}
vec3 directionalShadowOrigin(int i, vec3 p, vec3 n)
{
    mat4 m = uDirectionalLightMatrix[i];
    return shadowOrigin(p, n, 1.0 / (length(0.5 * vec3(m[0][0], m[1][0], m[2][0])) * float(textureSize(uDirectionalShadow, 0).x)));
}

// p is already pushed off the surface by the caller; the bias absorbs depth quantisation only.
float pointLightHardVisibility(int i, vec3 fromLight)
{
    float viewDepth = majorAxis(fromLight);
    // The bias is in view depth (it absorbs depth quantisation only); the face's perspective projection then
    // turns the biased depth into the window depth the map stores.
    float biased = max(viewDepth - 1e-3 * uPointShadowFar, uPointShadowNear);
    return texture(uPointShadow, vec4(fromLight, float(i)), pointWindowDepth(biased));
}

// A sphere light of radius R seen from p on a surface of normal n. Offsets are angles about the light's
// centre (the cube map's directions); each tap compares against the receiver's tangent plane where the tap's
// ray meets it, so a wide kernel does not shadow a tilted receiver with itself.
float pointLightSoftVisibility(int i, vec3 p, vec3 n, float radius)
{
    vec3 light = uPointLightPosition[i].xyz;
    vec3 fromLight = p - light;
    float receiver = length(fromLight);
    if (receiver <= radius)
        return 1.0; // inside the light
    vec3 axis = fromLight / receiver;
    vec3 u = normalize(abs(axis.x) < 0.9 ? cross(axis, vec3(1.0, 0.0, 0.0)) : cross(axis, vec3(0.0, 1.0, 0.0)));
    vec3 v = cross(axis, u);
    float bias = 1e-3 * uPointShadowFar;
    // Blockers between a tenth of the way and the receiver: nearer ones would ask for an unbounded search.
    float nearest = max(0.1 * receiver, uPointShadowNear);
    float searchAngle = min(radius * (receiver - nearest) / (receiver * nearest), 0.5);
    float blockerSum = 0.0;
    int blockers = 0;
    for (int k = 0; k < kSoftShadowTaps; ++k) {
        vec2 o = softShadowTap(k) * searchAngle;
        vec3 dir = axis + o.x * u + o.y * v;
        float stored = pointViewDepth(texture(uPointShadowDepth, vec4(dir, float(i))).r);
        // The stored major-axis depth as a distance along the tap's direction.
        float distance = stored * length(dir) / majorAxis(dir);
        if (distance < receiver - bias) {
            blockerSum += distance;
            ++blockers;
        }
    }
    if (blockers == 0)
        return 1.0;
    float blocker = blockerSum / float(blockers);
    float kernel = clamp(radius * (receiver - blocker) / (blocker * receiver), 0.0, 0.5);
    float lit = 0.0;
    for (int k = 0; k < kSoftShadowTaps; ++k) {
        vec2 o = softShadowTap(k) * kernel;
        vec3 dir = normalize(axis + o.x * u + o.y * v);
        float across = dot(dir, n);
        // Where the tap's ray meets the receiver's plane; a plane facing away (t <= 0) or edge-on takes the
        // receiver's own distance, as a negative t would read the opposite cube face.
        float t = across < -1e-3 ? dot(fromLight, n) / across : -1.0;
        t = t > 0.0 ? min(t, 2.0 * receiver) : receiver;
        lit += pointLightHardVisibility(i, dir * t);
    }
    return lit / float(kSoftShadowTaps);
}

float pointLightVisibility(int i, vec3 p, vec3 n)
{
    if (uPointLightPosition[i].w < 0.5)
        return 1.0;
#ifdef SOFT_SHADOWS
    float radius = uPointLightRadius[i];
    if (radius > 0.0)
        return pointLightSoftVisibility(i, p, n, radius);
#endif
    return pointLightHardVisibility(i, p - uPointLightPosition[i].xyz);
}

// A light of angular radius atan(tanHalf) along an orthographic map. The map's window coordinates are affine
// in world space; its rows give metres per unit of window x, y and depth, and the receiver's plane as a depth
// gradient in window coordinates.
float directionalLightSoftVisibility(int i, vec3 coord, vec3 p, vec3 n, float tanHalf)
{
    mat4 m = uDirectionalLightMatrix[i];
    // Window = 0.5 * clip + 0.5: rows of the linear part, halved.
    vec3 rowX = 0.5 * vec3(m[0][0], m[1][0], m[2][0]);
    vec3 rowY = 0.5 * vec3(m[0][1], m[1][1], m[2][1]);
    vec3 rowZ = 0.5 * vec3(m[0][2], m[1][2], m[2][2]);
    vec3 metresPerUnit = 1.0 / vec3(length(rowX), length(rowY), length(rowZ));
    // The normal in window coordinates (inverse transpose of a rotation times a scale), then the plane's
    // depth change per unit of window x and y, limited where the receiver is nearly edge-on.
    vec3 nw = vec3(dot(rowX, n), dot(rowY, n), dot(rowZ, n)) * metresPerUnit * metresPerUnit;
    vec2 gradient = abs(nw.z) > 1e-6 ? clamp(-nw.xy / nw.z, vec2(-4.0), vec2(4.0)) : vec2(0.0);
    float bias = kDirectionalDepthBias;
    // Blockers anywhere between the light's side of the map and the receiver.
    vec2 search = vec2(coord.z * metresPerUnit.z * tanHalf) / metresPerUnit.xy;
    search = min(search, vec2(0.05));
    float blockerSum = 0.0;
    int blockers = 0;
    for (int k = 0; k < kSoftShadowTaps; ++k) {
        vec2 o = softShadowTap(k) * search;
        float stored = texture(uDirectionalShadowDepth, vec3(coord.xy + o, float(i))).r;
        if (stored < coord.z + dot(gradient, o) - bias) {
            blockerSum += stored;
            ++blockers;
        }
    }
    if (blockers == 0)
        return 1.0;
    float blocker = blockerSum / float(blockers);
    vec2 kernel = min(vec2((coord.z - blocker) * metresPerUnit.z * tanHalf) / metresPerUnit.xy, vec2(0.05));
    float lit = 0.0;
    for (int k = 0; k < kSoftShadowTaps; ++k) {
        vec2 o = softShadowTap(k) * kernel;
        lit += texture(uDirectionalShadow, vec4(coord.xy + o, float(i), coord.z + dot(gradient, o) - bias));
    }
    return lit / float(kSoftShadowTaps);
}

float directionalLightVisibility(int i, vec3 p, vec3 n)
{
    if (uDirectionalLightDirection[i].w < 0.5)
        return 1.0;
    vec4 clip = uDirectionalLightMatrix[i] * vec4(p, 1.0);
    vec3 coord = clip.xyz / clip.w * 0.5 + 0.5;
    if (any(lessThan(coord.xy, vec2(0.0))) || any(greaterThan(coord.xy, vec2(1.0))))
        return 1.0;
#ifdef SOFT_SHADOWS
    float tanHalf = uDirectionalLightTanHalf[i];
    if (tanHalf > 0.0)
        return directionalLightSoftVisibility(i, coord, p, n, tanHalf);
#endif
    return texture(uDirectionalShadow, vec4(coord.xy, float(i), coord.z - kDirectionalDepthBias));
}
