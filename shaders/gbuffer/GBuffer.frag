in vec3 vWorld;
in vec3 vNormal;
in vec2 vUv;

// TEXTURED: the variant for materials with an albedo texture (passes/GBufferPass); the others skip the fetch,
// which cost the atrium's untextured g-buffer ~17 ms at 1280x720.
uniform vec3 uAlbedo;
uniform int uMaterialIndex; // into the material table (common/MaterialTable.glsl): specular, emission
#ifdef TEXTURED
layout(binding = 0) uniform sampler2D uAlbedoTexture;
#endif

layout(location = 0) out vec4 oPosition; // world position, a = material index + 1 (0 = no geometry)
layout(location = 1) out vec4 oNormal;   // unit normal facing the camera, w = 1 front face, 0 back face
layout(location = 2) out vec4 oAlbedo;

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
    oPosition = vec4(vWorld, float(uMaterialIndex + 1));
    oNormal = vec4(n, gl_FrontFacing ? 1.0 : 0.0);
#ifdef TEXTURED
    oAlbedo = vec4(uAlbedo * texture(uAlbedoTexture, vUv).rgb, 1.0);
#else
    oAlbedo = vec4(uAlbedo, 1.0);
#endif
}
