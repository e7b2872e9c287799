layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUv;

uniform mat4 uModel;
uniform mat4 uNormalMatrix;
// From coordinates relative to the camera: with the camera's position inside the view matrix, large terms
// cancel in the projected depth of a scene far from the origin, and with a near plane that suits a small scene
// every depth came out beyond the far plane (a room 1e5 m out drew nothing).
uniform mat4 uViewProjection;
uniform vec3 uCameraPosition;

out vec3 vWorld;
out vec3 vNormal;
out vec2 vUv;

void main()
{
    vec4 world = uModel * vec4(aPosition, 1.0);
    vWorld = world.xyz;
    vNormal = mat3(uNormalMatrix) * aNormal;
    vUv = aUv;
    gl_Position = uViewProjection * vec4(world.xyz - uCameraPosition, 1.0);
}
