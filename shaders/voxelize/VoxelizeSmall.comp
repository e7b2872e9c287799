// Voxelizes the small triangles of a run (core/GpuScene::dispatchTriangles), one invocation each, without the
// rasteriser: the triangle is projected as the geometry shader projects it (voxelize/ProjectTriangle.glsl),
// and the pixel centres inside it, within its pixel bounds, get what Voxelize.frag gives a fragment there.
// llvmpipe spends a triangle setup and a block of mostly idle fragment lanes on a triangle of a pixel or two;
// here it is a few loop iterations in one lane (docs/BENCHMARKS.md, "Small triangles voxelized in a compute
// shader"). Larger triangles are listed for the rasteriser (core/ListedTriangles), which then draws only
// those: the vertex and geometry shaders do not run for the small ones either.
// Variants as Voxelize.frag's (passes/VoxelizePass::voxelizer).
layout(local_size_x = 64) in;

layout(std430, binding = 2) readonly buffer Vertices { float uVertices[]; }; // position, normal, uv
layout(std430, binding = 3) readonly buffer Indices { uint uIndices[]; };

uniform uint uFirstIndex;
uniform uint uTriangleCount;
uniform uint uVertexCount;

// Where the larger triangles go: this run's segment of an index buffer and its draw command, whose count
// (the first of five words) each listed triangle raises by three.
layout(std430, binding = 4) writeonly buffer ListedIndices { uint uListed[]; };
layout(std430, binding = 5) buffer ListedCommands { uint uCommands[]; };
uniform uint uListRun;
uniform uint uListFirst;

uniform mat4 uModel;
uniform mat4 uNormalMatrix;
uniform vec3 uLatticeOrigin; // as in Voxelize.vert
uniform ivec3 uLatticeOffset;
uniform float uVoxelSize;
uniform int uResolution;
uniform ivec3 uRegionLo;
uniform ivec3 uRegionHi;
uniform vec3 uAlbedo;
#ifdef EMISSIVE
uniform vec3 uEmission;
#endif
#ifdef TEXTURED
layout(binding = 0) uniform sampler2D uAlbedoTexture;
#endif

#include "voxelize/ProjectTriangle.glsl"
#include "voxelize/VoxelColumn.glsl"

struct Corner {
    vec3 grid;
    vec3 normal;
    vec2 uv;
};

// What Voxelize.vert computes for a vertex, in the same operations, so that both paths put a corner in the
// same place (GLSL does not promise the same rounding in two stages, which tst_Voxelization checks on llvmpipe).
Corner cornerAt(uint index)
{
    uint base = 8u * index;
    vec3 position = vec3(uVertices[base], uVertices[base + 1u], uVertices[base + 2u]);
    vec3 normal = vec3(uVertices[base + 3u], uVertices[base + 4u], uVertices[base + 5u]);
    Corner c;
    vec3 world = (uModel * vec4(position, 1.0)).xyz;
    c.grid = ((world - uLatticeOrigin) / uVoxelSize - vec3(uLatticeOffset)) / float(uResolution);
    c.normal = mat3(uNormalMatrix) * normal;
    c.uv = vec2(uVertices[base + 6u], uVertices[base + 7u]);
    return c;
}

// Twice the signed area of the triangle a, b, c.
float edgeFunction(vec2 a, vec2 b, vec2 c)
{
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// Whether a pixel centre exactly on the edge from a to b of a triangle wound counter-clockwise (window
// coordinates, y up) is inside it: on its left and bottom edges, so that of two triangles sharing an edge one
// takes the centres on it (neither would leave a hole without conservative enlargement, both would count twice
// in the voxels' means). GL leaves the rule to the implementation; this is the one llvmpipe applies to a
// framebuffer object such as the voxelizer's, which tst_Voxelization::edgesThroughPixelCentresMatchTheRasterizer
// holds the two paths to (the top-left rule failed it).
bool takesTies(vec2 a, vec2 b)
{
    vec2 d = b - a;
    return d.y < 0.0 || (d.y == 0.0 && d.x > 0.0);
}

void main()
{
    uint triangle = gl_GlobalInvocationID.x;
    if (triangle >= uTriangleCount)
        return;
    uint first = uFirstIndex + 3u * triangle;
    uvec3 index = uvec3(uIndices[first], uIndices[first + 1u], uIndices[first + 2u]);
    if (any(greaterThanEqual(index, uvec3(uVertexCount))))
        return; // an index past the mesh's vertices: drawn, what the GL made of it would be undefined
    Corner c0 = cornerAt(index.x), c1 = cornerAt(index.y), c2 = cornerAt(index.z);
    ProjectedTriangle t;
    if (!projectTriangle(c0.grid, c1.grid, c2.grid, t))
        return;
    if (!(t.extentPixels <= kSmallTrianglePixels)) {
        uint slot = uListFirst + atomicAdd(uCommands[5u * uListRun], 3u);
        uListed[slot] = index.x;
        uListed[slot + 1u] = index.y;
        uListed[slot + 2u] = index.z;
        return;
    }

    // The corners the rasteriser would get, in window pixels, and each corner's weight as a plane over them.
    vec2 w0 = (t.q[0] * 0.5 + 0.5) * float(uResolution);
    vec2 w1 = (t.q[1] * 0.5 + 0.5) * float(uResolution);
    vec2 w2 = (t.q[2] * 0.5 + 0.5) * float(uResolution);
    float area = edgeFunction(w0, w1, w2);
    if (!(abs(area) > 0.0))
        return;
    float inverseArea = 1.0 / area;
    // Which edges keep the pixel centres lying exactly on them, counter-clockwise: x for the edge w1 -> w2
    // (opposite corner 0), y for w2 -> w0, z for w0 -> w1.
    bool counterClockwise = area > 0.0;
    bvec3 ties = bvec3(counterClockwise ? takesTies(w1, w2) : takesTies(w2, w1),
        counterClockwise ? takesTies(w2, w0) : takesTies(w0, w2),
        counterClockwise ? takesTies(w0, w1) : takesTies(w1, w0));
    // d(weight)/dx and d(weight)/dy of the three corners' weights: the derivatives a fragment's quad would see.
    vec3 dWeightDx = vec3(w1.y - w2.y, w2.y - w0.y, w0.y - w1.y) * inverseArea;
    vec3 dWeightDy = vec3(w2.x - w1.x, w0.x - w2.x, w1.x - w0.x) * inverseArea;
    vec2 dUvDx = dWeightDx.x * c0.uv + dWeightDx.y * c1.uv + dWeightDx.z * c2.uv;
    vec2 dUvDy = dWeightDy.x * c0.uv + dWeightDy.y * c1.uv + dWeightDy.z * c2.uv;
    vec3 depths = (vec3(t.z[0], t.z[1], t.z[2]) * 0.5 + 0.5) * float(uResolution);
#ifdef CONSERVATIVE
    float spread = t.depthSlope;
#else
    float spread = 0.0;
#endif
#ifdef EMISSIVE
    vec3 emission = uEmission;
#else
    vec3 emission = vec3(0.0);
#endif

    // Pixel centres within the bounds, as the fragment shader's test keeps them (and within the viewport).
    ivec2 lo = max(ivec2(ceil(t.pixelBounds.xy - 0.5)), ivec2(0));
    ivec2 hi = min(ivec2(floor(t.pixelBounds.zw - 0.5)), ivec2(uResolution - 1));
    for (int y = lo.y; y <= hi.y; ++y) {
        for (int x = lo.x; x <= hi.x; ++x) {
            vec2 centre = vec2(x, y) + 0.5;
            vec3 weight = vec3(edgeFunction(w1, w2, centre), edgeFunction(w2, w0, centre),
                              edgeFunction(w0, w1, centre))
                * inverseArea;
            if (any(lessThan(weight, vec3(0.0))) || (weight.x == 0.0 && !ties.x) || (weight.y == 0.0 && !ties.y)
                || (weight.z == 0.0 && !ties.z))
                continue;
            vec2 uv = weight.x * c0.uv + weight.y * c1.uv + weight.z * c2.uv;
#ifdef TEXTURED
            vec3 albedo = uAlbedo * textureGrad(uAlbedoTexture, uv, dUvDx, dUvDy).rgb;
#else
            vec3 albedo = uAlbedo;
#endif
            vec3 normal = weight.x * c0.normal + weight.y * c1.normal + weight.z * c2.normal;
            float len = length(normal);
            normal = len > 1e-20 ? normal / len : vec3(0.0);
            // From the first corner, as llvmpipe's plane equations go: a triangle at one depth (a wall
            // on a voxel boundary) gets exactly its corners' depth, where weights summing to a hair under
            // one would put it in the voxel below.
            float depth = depths.x + weight.y * (depths.y - depths.x) + weight.z * (depths.z - depths.x);
            addToColumn(ivec2(x, y), depth, spread, t.axis, albedo, normal, emission);
        }
    }
}
