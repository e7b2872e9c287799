layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUv;

uniform mat4 uModel;
uniform mat4 uNormalMatrix;
uniform vec3 uGridOrigin;
uniform float uGridExtent;

out vec3 vGrid; // position in the grid's unit cube
out vec3 vNormal;
out vec2 vUv;

void main()
{
    vec3 world = (uModel * vec4(aPosition, 1.0)).xyz;
    vGrid = (world - uGridOrigin) / uGridExtent;
    vNormal = mat3(uNormalMatrix) * aNormal;
    vUv = aUv;
}
