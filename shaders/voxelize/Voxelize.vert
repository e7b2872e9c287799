layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUv;

uniform mat4 uModel;
uniform mat4 uNormalMatrix;
// The grid's corner is the lattice's corner plus uLatticeOffset voxels (a clip level's placement, or zero).
// Positions are taken from the lattice's corner, which never moves, and the whole voxels subtracted after:
// that subtraction is exact, so a triangle lands on the same voxels, to the last bit, wherever the grid
// stands, and a grid that stepped and voxelized only its new slabs matches a rebuild there (a face lying on
// a voxel boundary would otherwise fall on either side of it as rounding took it).
uniform vec3 uLatticeOrigin;
uniform ivec3 uLatticeOffset;
uniform float uVoxelSize;
uniform int uResolution;

out vec3 vGrid; // position in the grid's unit cube
out vec3 vNormal;
out vec2 vUv;

void main()
{
    vec3 world = (uModel * vec4(aPosition, 1.0)).xyz;
    vGrid = ((world - uLatticeOrigin) / uVoxelSize - vec3(uLatticeOffset)) / float(uResolution);
    vNormal = mat3(uNormalMatrix) * aNormal;
    vUv = aUv;
}
