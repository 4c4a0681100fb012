#version 450 core
// Panes (SPEC.md glazing), drawn after the opaque surfaces with the depth test on, no depth
// written, and the framebuffer multiplied by the output (blend DST_COLOR, ZERO): the camera's
// transmittance texture (gbuffer.vert) and a directional shadow map's companion layer
// (shadow_dir.vert) hold the product of the transmittances of the panes in front of the nearest
// opaque surface. Alpha carries the fragment's depth, which the shadow maps keep the least of
// (GL_MIN): how far the nearest pane is from the light.
struct Material { vec4 albedoKind; vec4 specularAlpha; vec4 radiance; };
layout(std430, binding = 0) readonly buffer Triangles { vec4 triangles[]; };  // normal, material
layout(std430, binding = 1) readonly buffer Materials { Material materials[]; };  // a pane's albedo: its transmittance
uniform int firstTriangle;  // the panes follow the opaque triangles; gl_PrimitiveID counts from the draw's first
layout(location = 0) out vec4 result;
void main() {
    const vec4 t = triangles[firstTriangle + gl_PrimitiveID];
    result = vec4(materials[int(t.w)].albedoKind.rgb, gl_FragCoord.z);
}
