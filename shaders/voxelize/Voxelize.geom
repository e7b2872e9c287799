// Projects each triangle along its dominant axis so it covers as many pixels (voxel columns) as possible,
// and, in conservative mode, enlarges it by the pixel square so every voxel it touches gets a fragment.
#include "common/ConeMath.glsl"

layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

in vec3 vGrid[];
in vec3 vNormal[];
in vec2 vUv[];

uniform int uResolution;
uniform ivec3 uRegionLo; // only voxels in [lo, hi) are being redone
uniform ivec3 uRegionHi;

out vec3 gNormal;
out vec2 gUv;
flat out int gAxis;
flat out vec4 gPixelBounds; // xy min, zw max, window pixels: clips the enlarged triangle's spikes
flat out float gDepthSlope; // voxel depth change across half a pixel in x plus half in y
// Depth in voxels, not clipped: the pass clamps depth instead of clipping (VoxelizePass::accumulate), so a
// triangle just beyond the grid's near or far face still reaches the outermost voxels within its depth
// spread, as it reaches any inner voxel; gl_FragCoord.z would read the clamped depth there.
noperspective out float gDepth;

vec3 swizzleToAxis(vec3 p, int axis)
{
    return axis == 0 ? p.yzx : (axis == 1 ? p.zxy : p.xyz);
}

void main()
{
    vec3 faceNormal = cross(vGrid[1] - vGrid[0], vGrid[2] - vGrid[0]);
    if (!(dot(faceNormal, faceNormal) > 0.0))
        return; // zero area or non-finite: nothing to voxelize
    // A triangle that cannot reach the region (conservative enlargement and the depth spread reach up to two
    // voxels beyond it, on a triangle sloped across both other axes) is not rasterised at all: a moving
    // object's update redraws the static triangles near it.
    vec3 lowest = min(vGrid[0], min(vGrid[1], vGrid[2])) * float(uResolution);
    vec3 highest = max(vGrid[0], max(vGrid[1], vGrid[2])) * float(uResolution);
    if (any(lessThan(highest + 2.0, vec3(uRegionLo))) || any(greaterThanEqual(lowest - 2.0, vec3(uRegionHi))))
        return;
    int axis = dominantAxis(faceNormal);
    vec3 p[3];
    for (int i = 0; i < 3; ++i)
        p[i] = swizzleToAxis(vGrid[i], axis) * 2.0 - 1.0;

    vec3 n = cross(p[1] - p[0], p[2] - p[0]); // n.z is the largest component: never zero here
    vec2 slope = -n.xy / n.z;                 // dz/dx, dz/dy in NDC; equal to voxel depth per pixel
    gDepthSlope = 0.5 * (abs(slope.x) + abs(slope.y));
    float halfPixel = 1.0 / float(uResolution);

    vec2 lo = min(p[0].xy, min(p[1].xy, p[2].xy)) - halfPixel;
    vec2 hi = max(p[0].xy, max(p[1].xy, p[2].xy)) + halfPixel;
    gPixelBounds = vec4((lo * 0.5 + 0.5) * float(uResolution), (hi * 0.5 + 0.5) * float(uResolution));

    vec2 q[3] = vec2[3](p[0].xy, p[1].xy, p[2].xy);
#ifdef CONSERVATIVE // (passes/VoxelizePass::voxelizer)
    float orientation = n.z > 0.0 ? 1.0 : -1.0;
    vec3 lines[3];
    for (int i = 0; i < 3; ++i) {
        vec2 e = p[(i + 1) % 3].xy - p[i].xy;
        vec2 outward = orientation * vec2(e.y, -e.x);
        // Shift the edge out by the pixel square's support in that direction: the exact Minkowski sum.
        float c = -dot(outward, p[i].xy) - halfPixel * (abs(outward.x) + abs(outward.y));
        lines[i] = vec3(outward, c);
    }
    for (int i = 0; i < 3; ++i) {
        vec3 h = cross(lines[(i + 2) % 3], lines[i]);
        vec2 moved = abs(h.z) > 1e-12 ? h.xy / h.z : p[i].xy;
        vec2 offset = moved - p[i].xy;
        // Needle tips shoot far out; the pixel bounds clip them anyway, so cap the spike.
        float limit = 8.0 * halfPixel;
        if (!(dot(offset, offset) <= limit * limit))
            offset = dot(offset, offset) > 0.0 && !isinf(offset.x) ? normalize(offset) * limit : vec2(0.0);
        q[i] = p[i].xy + offset;
    }
#endif
    for (int i = 0; i < 3; ++i) {
        float z = p[0].z + slope.x * (q[i].x - p[0].x) + slope.y * (q[i].y - p[0].y);
        gl_Position = vec4(q[i], z, 1.0);
        gDepth = (z * 0.5 + 0.5) * float(uResolution);
        gNormal = vNormal[i];
        gUv = vUv[i];
        gAxis = axis;
        EmitVertex();
    }
    EndPrimitive();
}
