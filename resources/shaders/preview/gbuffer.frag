#version 450 core
// G-buffer: g0 = position, kind (0 nothing, 1 diffuse/glossy, 2 emitter, 3 mirror/glass: black
// in the preview); g1 = normal turned toward the camera, GGX alpha; g2 = albedo (an emitter's
// radiance when its front face is seen), distance to the camera; g3 = specular. With
// whiteReceivers, every diffuse and glossy surface becomes white Lambertian (albedo 1, no
// specular lobe) and emitters become nothing: the shaded frame is then E / pi, the irradiance
// over pi, under the same lights and VPLs (the illuminance layer).
struct Material { vec4 albedoKind; vec4 specularAlpha; vec4 radiance; };
layout(std430, binding = 0) readonly buffer Triangles { vec4 triangles[]; };  // normal, material
layout(std430, binding = 1) readonly buffer Materials { Material materials[]; };
uniform vec3 cameraPos;
uniform int whiteReceivers;
in vec3 worldPos;
layout(location = 0) out vec4 g0;
layout(location = 1) out vec4 g1;
layout(location = 2) out vec4 g2;
layout(location = 3) out vec4 g3;
void main() {
    const vec4 t = triangles[gl_PrimitiveID];
    const Material m = materials[int(t.w)];
    const vec3 toEye = cameraPos - worldPos;
    const float facing = dot(t.xyz, toEye);
    const vec3 n = facing >= 0.0 ? t.xyz : -t.xyz;
    const bool white = whiteReceivers != 0;
    const float kind = white && m.albedoKind.w == 2.0 ? 0.0 : m.albedoKind.w;
    g0 = vec4(worldPos, kind);
    g1 = vec4(n, m.specularAlpha.w);
    // SPEC: an emitter emits from its front face only, and reflects nothing.
    const vec3 colour = kind == 2.0 ? (facing > 0.0 ? m.radiance.rgb : vec3(0.0)) : white ? vec3(1.0) : m.albedoKind.rgb;
    g2 = vec4(colour, length(toEye));
    g3 = vec4(white ? vec3(0.0) : m.specularAlpha.rgb, 0.0);
}
