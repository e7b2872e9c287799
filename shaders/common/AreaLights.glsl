// Area lights (core/AreaLightSet): emissive triangles grouped into lights, shared by the composite (per pixel)
// and light injection (per voxel), so the light that bounces is the light the pixels see.
//   AREA_LIGHT_COUNT  lights in the table (compile-time, as the other light kinds: llvmpipe unrolls the loop)
// Irradiance from each light's triangles is exact for a Lambertian receiver: the contour integral over each
// triangle's edges (Lambert's formula, as in Arvo 1995), after clipping the triangle to the receiver's upper
// hemisphere, and only from triangles whose front (counter-clockwise) face looks at the receiver: emission is
// one-sided. Visibility is one cone from the receiver toward the light through the voxel opacity, its aperture
// the light's angular size: soft shadows whose penumbra grows with the light and shrinks toward the occluder
// (Crassin et al. 2011). Units: radiance W/(m^2 sr) in, irradiance W/m^2 out.
#define kAreaLightCount AREA_LIGHT_COUNT
#include "common/Bindings.glsl"

// Four rgba32f texels per light, then three per triangle; each light's first texel holds in .w the texel of its
// first triangle, as a frame may light with a prefix of the table's lights.
layout(binding = AREA_LIGHT_UNIT) uniform samplerBuffer uAreaLights;
layout(binding = OPACITY_UNIT) uniform sampler3D uOpacity;         // VoxelVolume::opacity, full mip chain
uniform vec3 uOpacityOrigin;   // the voxel grid's corner, metres
uniform float uOpacityExtent;  // its side, metres
uniform float uOpacityVoxel;   // one voxel, metres
uniform float uOpacityMaxLevel;
#ifdef SHADOW_CLIP_LEVELS
// A clipmap's levels coarser than the grid above (core/ClipLevelPass), finest first: a shadow cone goes on
// into the next level before a lookup reaches past a grid, as the light's cones do (common/ConeTracing.glsl).
// They share the units of the coarser levels' radiance, which no shader that traces shadow cones samples.
layout(binding = CLIP_RADIANCE_UNIT) uniform sampler3D uClipOpacity[SHADOW_CLIP_LEVELS];
uniform vec4 uClipOpacityBox[SHADOW_CLIP_LEVELS];  // xyz: the level's corner, w: its side (metres)
// x: its voxel (metres), y: its top mip level, z: how far out its shadow cones start (metres)
uniform vec4 uClipOpacityGrid[SHADOW_CLIP_LEVELS];
#endif

const float kAreaPi = 3.14159265358979;
// The widest visibility cone: a light close by subtends a wide angle, and a cone wider than this starts
// sampling the receiver's own surface around it.
const float kMaxVisibilityTan = 0.58; // 30 degrees half-angle

// The part of segment (p0, p1) on the side of the plane through the origin that n points to, as its ends s0 and
// s1 (both p0 when none of it is there); where it leaves that side its crossing goes to `leaving`, where it enters,
// to `entering`. A convex polygon's edges clipped one by one, with the edge from `leaving` to `entering` where
// it was cut, are its clipped part's edges: no array of corners, which llvmpipe indexes lane by lane (an array
// of the clipped corners made the unshadowed light of the Cornell box's emitters half the composite's time).
void clipSegment(vec3 p0, vec3 p1, vec3 n, out vec3 s0, out vec3 s1, inout vec3 leaving, inout vec3 entering)
{
    float d0 = dot(p0, n), d1 = dot(p1, n);
    bool up0 = d0 >= 0.0, up1 = d1 >= 0.0;
    vec3 x = up0 != up1 ? p0 + (p1 - p0) * (d0 / (d0 - d1)) : p0;
    s0 = up0 ? p0 : x;
    s1 = up1 ? p1 : (up0 ? x : s0);
    if (up0 && !up1)
        leaving = x;
    if (!up0 && up1)
        entering = x;
}

// theta * unit(a x b) for unit a, b: an edge's part of a polygon's vector irradiance.
vec3 edgeVector(vec3 a, vec3 b)
{
    vec3 c = cross(a, b);
    float s = length(c);
    float theta = atan(s, dot(a, b));
    return s > 1e-12 ? theta * c / s : vec3(0.0);
}

vec3 edgeVectorOf(vec3 p0, vec3 p1)
{
    return edgeVector(normalize(p0), normalize(p1));
}

// Triangle (a, b, c)'s vector irradiance over its radiance at the receiver, after clipping it to the plane
// with normal n: its component along n is the cosine-weighted solid angle (pi times the form factor), and its
// direction the mean direction the light arrives from.
vec3 clippedTriangleVector(vec3 a, vec3 b, vec3 c, vec3 n)
{
    if (dot(a, n) < 0.0 && dot(b, n) < 0.0 && dot(c, n) < 0.0)
        return vec3(0.0);
    vec3 leaving = a, entering = a; // an uncut triangle's closing edge has no length
    vec3 ab0, ab1, bc0, bc1, ca0, ca1;
    clipSegment(a, b, n, ab0, ab1, leaving, entering);
    clipSegment(b, c, n, bc0, bc1, leaving, entering);
    clipSegment(c, a, n, ca0, ca1, leaving, entering);
    vec3 sum = edgeVectorOf(ab0, ab1) + edgeVectorOf(bc0, bc1) + edgeVectorOf(ca0, ca1)
        + edgeVectorOf(leaving, entering);
    sum *= 0.5;
    return dot(sum, n) < 0.0 ? -sum : sum;
}

// Steps a shadow cone (see coneTransmittance) through one grid's opacity `opacity` (corner and side in box,
// voxel and top level in grid) from distance t on. True when the cone is done: at the light, opaque, or at the
// faces of a grid with nothing around it (margin 0); false when a lookup would reach past the grid's faces by
// `margin` footprints, to go on in the next level.
bool traceOpacity(sampler3D opacity, vec4 box, vec2 grid, float margin, vec3 p, vec3 dir, float tanHalf,
    float offset, float cosReceiver, float end, float cosLight, inout float t, inout float alpha)
{
    float voxel = grid.x;
    // A cone that starts in this grid starts half a voxel out, as in a grid of its own.
    t = max(t, 0.5 * voxel);
    for (int k = 0; k < 128 && alpha < 0.99; ++k) {
        // Done when the light's side leaves no room; near the receiver the footprint only stays small.
        // Ending there too ended every cone that starts under 1.5 voxels out at its first step: the voxels'
        // injection (one voxel out) and a clip level's coarser voxels had no area-light shadows.
        float lightSide = (end - t) * cosLight / 3.0;
        if (lightSide < 0.5 * voxel)
            return true;
        float clearance = min((offset + t * cosReceiver) / 3.0, lightSide);
        float diameter = clamp(2.0 * t * tanHalf, voxel, max(clearance, voxel));
        float level = clamp(log2(diameter / voxel), 0.0, grid.y);
        vec3 uvw = (p + t * dir - box.xyz) / box.w;
        float m = margin * diameter / box.w;
        if (any(lessThan(uvw, vec3(m))) || any(greaterThan(uvw, vec3(1.0 - m))))
            return margin == 0.0;
        // Level 0 holds the same opacity in every channel; above, the three axes' crossings weighted by how
        // much of the path runs along each.
        float a = dot(textureLod(opacity, uvw, level).rgb, dir * dir);
        a = 1.0 - pow(clamp(1.0 - a, 0.0, 1.0), diameter / (voxel * exp2(level)));
        alpha += (1.0 - alpha) * a;
        t += diameter;
    }
    return true;
}

// Transmittance along one cone from p (already `offset` along the receiver's normal n) in direction dir, of
// tangent half-angle tanHalf, up to the light: to its plane when it is planar (plane.w > 0.5 in `planar`), else to
// its bounding sphere. Each sample's footprint is kept clear of the receiver's tangent plane and of the light's
// own plane by three footprints (trilinear lookups reach up to one and a half texels of up to twice the
// footprint): otherwise coarse levels would take the receiver's own surface, or the ceiling a lamp is
// mounted on, for an occluder. The cone is therefore narrow at both ends and widest between.
float coneTransmittance(vec3 p, vec3 dir, float tanHalf, vec3 n, float offset, vec4 sphere, vec4 plane, bool planar)
{
    float cosReceiver = max(dot(dir, n), 0.05);
    float end, cosLight;
    if (planar) {
        cosLight = max(-dot(plane.xyz, dir), 0.05);
        end = (dot(plane.xyz, p) - plane.w) / cosLight;
    } else {
        cosLight = 1.0;
        end = length(sphere.xyz - p) - sphere.w;
    }
    float alpha = 0.0;
    float t = 0.0;
#ifdef SHADOW_CLIP_LEVELS
    // The grid above (in a clipmap the finest level, or a clip level's own), then each coarser level the cone
    // reaches, the same t going on; a cone whose receiver lies outside a grid goes straight on to the next.
    bool done = traceOpacity(uOpacity, vec4(uOpacityOrigin, uOpacityExtent), vec2(uOpacityVoxel, uOpacityMaxLevel),
        1.0, p, dir, tanHalf, offset, cosReceiver, end, cosLight, t, alpha);
    for (int k = 0; k < SHADOW_CLIP_LEVELS && !done; ++k)
        done = traceOpacity(uClipOpacity[k], uClipOpacityBox[k], uClipOpacityGrid[k].xy,
            k + 1 < SHADOW_CLIP_LEVELS ? 1.0 : 0.0, p, dir, tanHalf, offset, cosReceiver, end, cosLight, t, alpha);
#else
    traceOpacity(uOpacity, vec4(uOpacityOrigin, uOpacityExtent), vec2(uOpacityVoxel, uOpacityMaxLevel), 0.0, p,
        dir, tanHalf, offset, cosReceiver, end, cosLight, t, alpha);
#endif
    return clamp(1.0 - alpha, 0.0, 1.0);
}

// 1 where nothing lies between p (normal n) and light i, whose vector irradiance at p is `towards`, 0 behind
// opaque voxels, soft in between (Crassin et al. 2011's soft shadows). The light, taken as a disk of its area,
// is covered by four cones of half its angular radius around its centre: one cone as wide as the light would
// have to narrow to keep clear of the receiver (coneTransmittance) exactly where an occluder halfway decides
// the penumbra.
float areaLightVisibility(vec3 p, vec3 n, float offset, int i, vec3 towards)
{
    vec4 sphere = texelFetch(uAreaLights, 4 * i + 1);
    vec4 areaCount = texelFetch(uAreaLights, 4 * i + 2);
    vec4 plane = texelFetch(uAreaLights, 4 * i + 3);
    bool planar = areaCount.z > 0.5;
    if (areaCount.w < 0.5)
        return 1.0; // a light that casts no shadows
    vec3 d = sphere.xyz - p;
    float distance = length(d);
    if (distance <= 1e-30)
        return 1.0;
    // Toward the light's centre while all of it lies above the receiver's horizon; as it dips below, toward
    // where the light the receiver sees comes from (`towards`, its vector irradiance), fully so once the centre
    // is below. Aimed at a centre on the horizon, the cones left the surface almost along it and met its own
    // voxels, which stand out of an askew surface's plane: a wall beside a ceiling light read half its light
    // (tst_AreaLights::lightOnAWallsHorizonIsNotSelfShadowed).
    vec3 centre = d / distance;
    float radiusTan = sqrt(areaCount.x / kAreaPi) / distance;
    float sinRadius = radiusTan * inversesqrt(1.0 + radiusTan * radiusTan);
    float above = clamp(dot(centre, n) / max(sinRadius, 1e-4), 0.0, 1.0);
    vec3 dir = dot(towards, towards) > 1e-30 ? normalize(mix(normalize(towards), centre, above)) : centre;
    float tanHalf = min(radiusTan, kMaxVisibilityTan);
    vec3 u = normalize(abs(dir.x) < 0.9 ? cross(dir, vec3(1.0, 0.0, 0.0)) : cross(dir, vec3(0.0, 1.0, 0.0)));
    vec3 v = cross(dir, u);
#ifdef ONE_SHADOW_CONE
    // The voxels' injection (inject/InjectLight.comp): one cone as wide as the light costs a quarter, and on
    // a voxel's scale reads the umbra under a blocker as the path tracer does (16% of the unshadowed light,
    // four cones 36%; tst_AreaLights::voxelsAreShadowedToo).
    return coneTransmittance(p, dir, tanHalf, n, offset, sphere, plane, planar);
#endif
    float spread = 0.5 * tanHalf * 0.70710678;
    float visibility = 0.0;
    for (int k = 0; k < 4; ++k) {
        vec2 s = vec2((k & 1) == 0 ? -1.0 : 1.0, (k & 2) == 0 ? -1.0 : 1.0);
        vec3 sub = normalize(dir + spread * (s.x * u + s.y * v));
        visibility += 0.25 * coneTransmittance(p, sub, 0.5 * tanHalf, n, offset, sphere, plane, planar);
    }
    return visibility;
}

// The triangle whose corners start at texel `base`, relative to p; false when its back faces p: emission is
// one-sided and the front is counter-clockwise.
bool emittingTriangle(int base, vec3 p, out vec3 a, out vec3 b, out vec3 c)
{
    a = texelFetch(uAreaLights, base).xyz - p;
    b = texelFetch(uAreaLights, base + 1).xyz - p;
    c = texelFetch(uAreaLights, base + 2).xyz - p;
    return dot(cross(b - a, c - a), -a) > 0.0;
}

// Light i's vector irradiance over its radiance at p above the plane of normal n (clippedTriangleVector): along n
// its irradiance over its radiance.
vec3 areaLightVector(int i, vec3 p, vec3 n)
{
    int first = int(texelFetch(uAreaLights, 4 * i).w + 0.5);
    int count = int(texelFetch(uAreaLights, 4 * i + 2).y + 0.5);
    vec3 sum = vec3(0.0);
    for (int k = 0; k < count; ++k) {
        vec3 a, b, c;
        if (emittingTriangle(first + 3 * k, p, a, b, c))
            sum += clippedTriangleVector(a, b, c, n);
    }
    return sum;
}

float areaLightFactor(int i, vec3 p, vec3 n)
{
    return dot(areaLightVector(i, p, n), n);
}

// Irradiance (W/m^2) at p on a surface with normal n from every area light, without shadows.
vec3 areaLightUnshadowed(vec3 p, vec3 n)
{
    vec3 irradiance = vec3(0.0);
    for (int i = 0; i < kAreaLightCount; ++i)
        irradiance += texelFetch(uAreaLights, 4 * i).rgb * areaLightFactor(i, p, n);
    return irradiance;
}

#ifdef SHADOW_CLIP_LEVELS
// A receiver outside the grid above starts its shadow cones in the first level holding it, and as far out as
// that level's cones start (its voxels are coarser: from the finer grid's offset the first lookups took the
// receiver's own surface for an occluder).
float shadowOffsetFor(vec3 p, float offset)
{
    vec3 uvw = (p - uOpacityOrigin) / uOpacityExtent;
    if (all(greaterThanEqual(uvw, vec3(0.0))) && all(lessThanEqual(uvw, vec3(1.0))))
        return offset;
    for (int k = 0; k < SHADOW_CLIP_LEVELS - 1; ++k) {
        uvw = (p - uClipOpacityBox[k].xyz) / uClipOpacityBox[k].w;
        if (all(greaterThanEqual(uvw, vec3(0.0))) && all(lessThanEqual(uvw, vec3(1.0))))
            return max(offset, uClipOpacityGrid[k].z);
    }
    return max(offset, uClipOpacityGrid[SHADOW_CLIP_LEVELS - 1].z);
}
#endif

// The same without and with shadows: the visibility cones start `offset` metres along n (in a clipmap, the
// offset of the finest level holding p if that is coarser).
void areaLightIrradiance(vec3 p, vec3 n, float offset, out vec3 unshadowed, out vec3 shadowed)
{
#ifdef SHADOW_CLIP_LEVELS
    offset = shadowOffsetFor(p, offset);
#endif
    unshadowed = vec3(0.0);
    shadowed = vec3(0.0);
    for (int i = 0; i < kAreaLightCount; ++i) {
        vec3 towards = areaLightVector(i, p, n);
        float factor = dot(towards, n);
        if (factor <= 0.0)
            continue;
        vec3 light = texelFetch(uAreaLights, 4 * i).rgb * factor;
        unshadowed += light;
        shadowed += light * areaLightVisibility(p + n * offset, n, offset, i, towards);
    }
}

// The shadowed irradiance alone.
vec3 areaLightIrradiance(vec3 p, vec3 n, float offset)
{
    vec3 unshadowed, shadowed;
    areaLightIrradiance(p, n, offset, unshadowed, shadowed);
    return shadowed;
}

// The Phong lobe's linearly transformed cosines (scene/PhongLtcTable, fitted offline by vct-fit-ltc): a grid over
// x = sqrt(1 - cos(view angle)) across and the lobe width sqrt(2 / (shininess + 2)) down, from
// uPhongLtcMinWidth to 1, texel centres on the grid points.
layout(binding = PHONG_LTC_UNIT) uniform sampler2D uPhongLtc;              // M^-1 (0,0), (0,2), (2,0), (2,2)
layout(binding = PHONG_LTC_ALBEDO_UNIT) uniform sampler2D uPhongLtcAlbedo; // the lobe's albedo
uniform float uPhongLtcSize;
uniform float uPhongLtcMinWidth;

// Edge (p0, p1)'s part of ltcTriangleIntegral's two sums, its corners taken to the unit sphere: Lambert's contour
// term and the integral of z^2 along the edge.
void addLtcEdge(vec3 p0, vec3 p1, inout float lambert, inout float cubic)
{
    vec3 u = normalize(p0);
    vec3 v = normalize(p1);
    vec3 normal = cross(u, v);
    float sine = length(normal);
    if (sine <= 1e-9)
        return;
    float cosine = dot(u, v);
    float theta = atan(sine, cosine);
    float nz = normal.z / sine;
    lambert += theta * nz;
    float zu = u.z, zt = (v.z - cosine * u.z) / sine;
    float sin2 = 2.0 * sine * cosine;
    cubic += nz * (zu * zu * (0.5 * theta + 0.25 * sin2) + zt * zt * (0.5 * theta - 0.25 * sin2) + zu * zt * sine * sine);
}

// The fitted density's integral over triangle (a, b, c), given in the lobe's frame (normal +z): the triangle
// clipped to the receiver's side, mapped by M^-1, clipped to the base's hemisphere, then the integral of the
// base cos^3(theta) 2 / pi (scene/PhongLtcTable::kPower) over it: from Lambert's contour sum and, per edge, the
// integral of z^2 along it (scene/LinearlyTransformedCosine.cpp has the derivation).
float ltcTriangleIntegral(vec3 a, vec3 b, vec3 c, mat3 inverse)
{
    const vec3 up = vec3(0.0, 0.0, 1.0);
    if (a.z < 0.0 && b.z < 0.0 && c.z < 0.0)
        return 0.0;
    // Clipped to the receiver's side: three edges and the cut (clipSegment).
    vec3 leaving = a, entering = a;
    vec3 ab0, ab1, bc0, bc1, ca0, ca1;
    clipSegment(a, b, up, ab0, ab1, leaving, entering);
    clipSegment(b, c, up, bc0, bc1, leaving, entering);
    clipSegment(c, a, up, ca0, ca1, leaving, entering);
    // Mapped by M^-1, those four edges clipped to the base's hemisphere, and its cut.
    vec3 mappedLeaving = inverse * ab0, mappedEntering = mappedLeaving;
    float lambert = 0.0, cubic = 0.0;
    vec3 s0, s1;
    clipSegment(inverse * ab0, inverse * ab1, up, s0, s1, mappedLeaving, mappedEntering);
    addLtcEdge(s0, s1, lambert, cubic);
    clipSegment(inverse * bc0, inverse * bc1, up, s0, s1, mappedLeaving, mappedEntering);
    addLtcEdge(s0, s1, lambert, cubic);
    clipSegment(inverse * ca0, inverse * ca1, up, s0, s1, mappedLeaving, mappedEntering);
    addLtcEdge(s0, s1, lambert, cubic);
    clipSegment(inverse * leaving, inverse * entering, up, s0, s1, mappedLeaving, mappedEntering);
    addLtcEdge(s0, s1, lambert, cubic);
    addLtcEdge(mappedLeaving, mappedEntering, lambert, cubic);
    float side = lambert >= 0.0 ? 1.0 : -1.0;
    return (side * lambert + side * cubic) / (2.0 * kAreaPi);
}

// Radiance the normalised Phong lobe (exponent `shininess`, per unit specular colour) reflects toward
// `toViewer` from every area light, unshadowed: for each light, its radiance times the lobe's albedo times the
// fitted density's integral over its triangles, exact for the fitted lobe (Heitz et al. 2016). The fit's own
// error against cos^n is in docs/DESIGN.md ("Area lights").
vec3 areaLightSpecular(vec3 p, vec3 n, vec3 toViewer, float shininess)
{
    float cosView = clamp(dot(n, toViewer), 0.0, 1.0);
    // The lobe's frame: the normal up, the viewer in the xz-plane on the +x side.
    vec3 tangent = toViewer - n * cosView;
    tangent = dot(tangent, tangent) > 1e-12 ? normalize(tangent)
                                            : normalize(abs(n.x) < 0.9 ? cross(n, vec3(1.0, 0.0, 0.0)) : cross(n, vec3(0.0, 1.0, 0.0)));
    mat3 toLobe = transpose(mat3(tangent, cross(n, tangent), n));
    float width = sqrt(2.0 / (max(shininess, 0.0) + 2.0));
    vec2 grid = vec2(sqrt(1.0 - cosView), clamp((width - uPhongLtcMinWidth) / (1.0 - uPhongLtcMinWidth), 0.0, 1.0));
    vec2 uv = (grid * (uPhongLtcSize - 1.0) + 0.5) / uPhongLtcSize;
    vec4 m = textureLod(uPhongLtc, uv, 0.0);
    float albedo = textureLod(uPhongLtcAlbedo, uv, 0.0).r;
    mat3 inverse = mat3(m.x, 0.0, m.z, 0.0, 1.0, 0.0, m.y, 0.0, m.w); // columns: M^-1 with (1, 1) = 1
    vec3 reflected = vec3(0.0);
    for (int i = 0; i < kAreaLightCount; ++i) {
        vec4 radianceFirst = texelFetch(uAreaLights, 4 * i);
        int first = int(radianceFirst.w + 0.5);
        int count = int(texelFetch(uAreaLights, 4 * i + 2).y + 0.5);
        float integral = 0.0;
        for (int k = 0; k < count; ++k) {
            vec3 a, b, c;
            if (emittingTriangle(first + 3 * k, p, a, b, c))
                integral += ltcTriangleIntegral(toLobe * a, toLobe * b, toLobe * c, inverse);
        }
        reflected += radianceFirst.rgb * albedo * integral;
    }
    return reflected;
}
