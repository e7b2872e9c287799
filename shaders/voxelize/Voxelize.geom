// Projects each triangle along its dominant axis so it covers as many pixels (voxel columns) as possible,
// and, in conservative mode, enlarges it by the pixel square so every voxel it touches gets a fragment
// (voxelize/ProjectTriangle.glsl). Where small triangles go through VoxelizeSmall.comp, the pass draws only the
// triangles it listed.
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

in vec3 vGrid[];
in vec3 vNormal[];
in vec2 vUv[];

uniform int uResolution;
uniform ivec3 uRegionLo; // only voxels in [lo, hi) are being redone
uniform ivec3 uRegionHi;

#include "voxelize/ProjectTriangle.glsl"

out vec3 gNormal;
out vec2 gUv;
flat out int gAxis;
flat out vec4 gPixelBounds; // ProjectedTriangle::pixelBounds
flat out float gDepthSlope; // ProjectedTriangle::depthSlope
// Depth in voxels, not clipped: the pass clamps depth instead of clipping (VoxelizePass::accumulate), so a
// triangle just beyond the grid's near or far face still reaches the outermost voxels within its depth
// spread, as it reaches any inner voxel; gl_FragCoord.z would read the clamped depth there.
noperspective out float gDepth;

void main()
{
    ProjectedTriangle t;
    if (!projectTriangle(vGrid[0], vGrid[1], vGrid[2], t))
        return;
    for (int i = 0; i < 3; ++i) {
        gl_Position = vec4(t.q[i], t.z[i], 1.0);
        gDepth = (t.z[i] * 0.5 + 0.5) * float(uResolution);
        gNormal = vNormal[i];
        gUv = vUv[i];
        gAxis = t.axis;
        gPixelBounds = t.pixelBounds;
        gDepthSlope = t.depthSlope;
        EmitVertex();
    }
    EndPrimitive();
}
