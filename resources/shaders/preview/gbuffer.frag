#version 450 core
// The G-buffer (gbuffer.glsl's encoding). With whiteReceivers, every diffuse and glossy surface
// becomes white Lambertian (albedo 1, no specular lobe) and emitters become nothing: the shaded
// frame is then E / pi, the irradiance over pi, under the same lights and VPLs (the illuminance
// layer).
#include_gbuffer
struct Material { vec4 albedoKind; vec4 specularAlpha; vec4 radiance; };
layout(std430, binding = 0) readonly buffer Triangles { vec4 triangles[]; };  // normal, material
layout(std430, binding = 1) readonly buffer Materials { Material materials[]; };
uniform vec3 cameraPos;
uniform int whiteReceivers;
in vec3 worldPos;
layout(location = 0) out vec4 g0;
layout(location = 1) out uvec4 g1;
void main() {
    const vec4 t = triangles[gl_PrimitiveID];
    const Material m = materials[int(t.w)];
    const float facing = dot(t.xyz, cameraPos - worldPos);
    const bool white = whiteReceivers != 0;
    int kind = int(m.albedoKind.w);
    // SPEC: an emitter emits from its front face only, and reflects nothing: black from behind
    // (kind 3; kind 0 would show the sky through it).
    if (kind == 2 && (white || facing <= 0.0)) kind = 3;
    if (kind == 2) {
        g0 = vec4(worldPos, 2.0);
        g1 = uvec4(floatBitsToUint(m.radiance.rgb), 0u);
        return;
    }
    const vec3 n = facing >= 0.0 ? t.xyz : -t.xyz;
    const vec3 albedo = white ? vec3(1.0) : m.albedoKind.rgb, specular = white ? vec3(0.0) : m.specularAlpha.rgb;
    g0 = vec4(worldPos, kind == 1 ? 1.0 + 0.5 * m.specularAlpha.w : float(kind));
    g1 = uvec4(packSnorm2x16(octEncode(n)), packUnorm2x16(albedo.rg), packUnorm2x16(vec2(albedo.b, specular.r)),
               packUnorm2x16(specular.gb));
}
