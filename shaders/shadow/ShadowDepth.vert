layout(location = 0) in vec3 aPosition;

uniform mat4 uModel;
uniform mat4 uViewProjection; // from coordinates relative to uOrigin
// The point light's position for its cube faces, zero for directional maps. Subtracting it before the view
// and projection keeps a scene far from the world origin precise: a view matrix that carries the light's
// position itself makes large terms cancel in the projected depth (tests/hardcases, offset 1e5).
uniform vec3 uOrigin;

void main()
{
    gl_Position = uViewProjection * vec4((uModel * vec4(aPosition, 1.0)).xyz - uOrigin, 1.0);
}
