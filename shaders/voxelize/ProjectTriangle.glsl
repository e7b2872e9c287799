// A triangle projected along its dominant axis for voxelization: the geometry shader rasterises it
// (Voxelize.geom), the compute path walks the pixels of a small one itself (VoxelizeSmall.comp). Both take the
// corners from here, so a triangle covers the same pixel columns either way.
// Needs uResolution, uRegionLo, uRegionHi; CONSERVATIVE enlarges the triangle by the pixel square.
#include "common/ConeMath.glsl"

// Triangles whose pixel bounds (conservative enlargement included) span at most this many pixels on both axes
// are voxelized by VoxelizeSmall.comp when the pass asks for it (passes/VoxelizePass), which lists the others
// for the rasteriser: rasterising a triangle of a pixel or two costs llvmpipe a setup and a mostly idle block
// of fragment lanes.
const float kSmallTrianglePixels = 5.5;

struct ProjectedTriangle {
    int axis;            // 0, 1, 2: x, y, z is the depth axis
    vec3 p[3];           // corners in NDC, swizzled so that the depth axis is z
    vec2 q[3];           // corners to rasterise: p's, moved out by the pixel square when conservative
    float z[3];          // NDC depth at q, on the triangle's plane
    vec4 pixelBounds;    // xy min, zw max, window pixels: clips the enlarged triangle's spikes
    float depthSlope;    // voxel depth change across half a pixel in x plus half in y
    float extentPixels;  // the larger side of pixelBounds
};

vec3 swizzleToAxis(vec3 p, int axis)
{
    return axis == 0 ? p.yzx : (axis == 1 ? p.zxy : p.xyz);
}

ivec3 unswizzle(ivec3 c, int axis)
{
    return axis == 0 ? c.zxy : (axis == 1 ? c.yzx : c.xyz);
}

// Corners in the grid's unit cube. False for a triangle with nothing to voxelize: zero area, non-finite, or
// too far from the region being redone to reach it.
bool projectTriangle(vec3 grid0, vec3 grid1, vec3 grid2, out ProjectedTriangle t)
{
    vec3 grid[3] = vec3[3](grid0, grid1, grid2);
    vec3 faceNormal = cross(grid[1] - grid[0], grid[2] - grid[0]);
    if (!(dot(faceNormal, faceNormal) > 0.0))
        return false;
    // A triangle that cannot reach the region (conservative enlargement and the depth spread reach up to two
    // voxels beyond it, on a triangle sloped across both other axes) is not voxelized at all: a moving
    // object's update redraws the static triangles near it.
    vec3 lowest = min(grid[0], min(grid[1], grid[2])) * float(uResolution);
    vec3 highest = max(grid[0], max(grid[1], grid[2])) * float(uResolution);
    if (any(lessThan(highest + 2.0, vec3(uRegionLo))) || any(greaterThanEqual(lowest - 2.0, vec3(uRegionHi))))
        return false;
    t.axis = dominantAxis(faceNormal);
    for (int i = 0; i < 3; ++i)
        t.p[i] = swizzleToAxis(grid[i], t.axis) * 2.0 - 1.0;

    vec3 n = cross(t.p[1] - t.p[0], t.p[2] - t.p[0]); // n.z is the largest component: never zero here
    vec2 slope = -n.xy / n.z;                         // dz/dx, dz/dy in NDC; equal to voxel depth per pixel
    t.depthSlope = 0.5 * (abs(slope.x) + abs(slope.y));
    float halfPixel = 1.0 / float(uResolution);

    vec2 lo = min(t.p[0].xy, min(t.p[1].xy, t.p[2].xy)) - halfPixel;
    vec2 hi = max(t.p[0].xy, max(t.p[1].xy, t.p[2].xy)) + halfPixel;
    t.pixelBounds = vec4((lo * 0.5 + 0.5) * float(uResolution), (hi * 0.5 + 0.5) * float(uResolution));
    t.extentPixels = max(t.pixelBounds.z - t.pixelBounds.x, t.pixelBounds.w - t.pixelBounds.y);

    for (int i = 0; i < 3; ++i)
        t.q[i] = t.p[i].xy;
#ifdef CONSERVATIVE
    float orientation = n.z > 0.0 ? 1.0 : -1.0;
    vec3 lines[3];
    for (int i = 0; i < 3; ++i) {
        vec2 e = t.p[(i + 1) % 3].xy - t.p[i].xy;
        vec2 outward = orientation * vec2(e.y, -e.x);
        // Shift the edge out by the pixel square's support in that direction: the exact Minkowski sum.
        float c = -dot(outward, t.p[i].xy) - halfPixel * (abs(outward.x) + abs(outward.y));
        lines[i] = vec3(outward, c);
    }
    for (int i = 0; i < 3; ++i) {
        vec3 h = cross(lines[(i + 2) % 3], lines[i]);
        vec2 moved = abs(h.z) > 1e-12 ? h.xy / h.z : t.p[i].xy;
        vec2 offset = moved - t.p[i].xy;
        // Needle tips shoot far out; the pixel bounds clip them anyway, so cap the spike.
        float limit = 8.0 * halfPixel;
        if (!(dot(offset, offset) <= limit * limit))
            offset = dot(offset, offset) > 0.0 && !isinf(offset.x) ? normalize(offset) * limit : vec2(0.0);
        t.q[i] = t.p[i].xy + offset;
    }
#endif
    for (int i = 0; i < 3; ++i)
        t.z[i] = t.p[0].z + slope.x * (t.q[i].x - t.p[0].x) + slope.y * (t.q[i].y - t.p[0].y);
    return true;
}
