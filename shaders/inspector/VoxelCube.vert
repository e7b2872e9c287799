// One instance per listed voxel; the cube's 36 corners come from gl_VertexID, so no vertex buffer.
struct VoxelEntry {
    ivec4 coord;
    vec4 value;
};
layout(std430, binding = 0) readonly buffer Entries { VoxelEntry entries[]; };

uniform mat4 uViewProjection;
uniform vec3 uGridOrigin;
uniform float uCellSize; // metres at the inspected level

out vec4 vValue;
out vec3 vNormal;

const ivec3 kCorners[8] = ivec3[8](ivec3(0, 0, 0), ivec3(1, 0, 0), ivec3(1, 1, 0), ivec3(0, 1, 0),
    ivec3(0, 0, 1), ivec3(1, 0, 1), ivec3(1, 1, 1), ivec3(0, 1, 1));
const int kIndices[36] = int[36](0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
    3, 7, 6, 3, 6, 2, 0, 4, 7, 0, 7, 3, 1, 2, 6, 1, 6, 5);
const vec3 kFaceNormals[6] = vec3[6](vec3(0, 0, -1), vec3(0, 0, 1), vec3(0, -1, 0), vec3(0, 1, 0),
    vec3(-1, 0, 0), vec3(1, 0, 0));

void main()
{
    VoxelEntry entry = entries[gl_InstanceID];
    vec3 corner = vec3(kCorners[kIndices[gl_VertexID]]);
    // Slightly smaller than the cell so neighbouring cubes stay distinguishable.
    vec3 local = 0.5 + (corner - 0.5) * 0.92;
    vec3 world = uGridOrigin + (vec3(entry.coord.xyz) + local) * uCellSize;
    vValue = entry.value;
    vNormal = kFaceNormals[gl_VertexID / 6];
    gl_Position = uViewProjection * vec4(world, 1.0);
}
