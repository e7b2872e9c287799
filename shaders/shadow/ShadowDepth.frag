// Point lights store distance / far so one cube lookup answers "is anything closer to the light?";
// directional lights keep the rasterised depth.
in vec3 vWorld;

uniform bool uLinearDistance;
uniform vec3 uLightPosition;
uniform float uFar;

void main()
{
    gl_FragDepth = uLinearDistance ? clamp(length(vWorld - uLightPosition) / uFar, 0.0, 1.0) : gl_FragCoord.z;
}
