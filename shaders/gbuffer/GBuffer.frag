in vec3 vWorld;
in vec3 vNormal;
in vec2 vUv;

uniform vec3 uAlbedo;
uniform vec3 uEmission;
uniform vec3 uSpecular;
uniform float uShininess;
layout(binding = 0) uniform sampler2D uAlbedoTexture;

layout(location = 0) out vec4 oPosition;
layout(location = 1) out vec4 oNormal;
layout(location = 2) out vec4 oAlbedo;
layout(location = 3) out vec4 oSpecular;
layout(location = 4) out vec4 oEmission;

void main()
{
    vec3 n = vNormal;
    float len = length(n);
    if (!(len > 1e-20))
        n = normalize(cross(dFdx(vWorld), dFdy(vWorld)));
    else
        n /= len;
    // Surfaces are shaded from the side the camera sees; emission is one-sided (front faces only).
    if (!gl_FrontFacing)
        n = -n;
    oPosition = vec4(vWorld, 1.0);
    oNormal = vec4(n, uShininess);
    oAlbedo = vec4(uAlbedo * texture(uAlbedoTexture, vUv).rgb, 1.0);
    oSpecular = vec4(uSpecular, 1.0);
    oEmission = vec4(gl_FrontFacing ? uEmission : vec3(0.0), 1.0);
}
