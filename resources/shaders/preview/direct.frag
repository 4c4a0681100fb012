#version 450 core
// Direct light and the final blend: emitters show their radiance; shaded surfaces get the direct
// light of the lights it shades in full (lights.glsl: point, spot and luminaire lights with cube
// shadow maps, directional lights with orthographic ones, and without interleaving the area
// lights' point samples), plus the indirect light, which with interleaving also holds the area
// lights and, when there are many, the delta lights, blurred vertically here
// (the second half of the box blur; blur.frag did the gather and the horizontal half).
// Compile-time switches (frame_passes.cpp, directProgram), so that the pass holds only the
// code the scene's lights need (on llvmpipe an unused light loop still halves this pass's speed):
//   LIGHT_LOOP   0 when this pass evaluates no light (all light is in the indirect texture);
//   DIRECTIONAL, SPOT, AREA, LUMINAIRE   1 when lights of that kind are among those it shades.
#include_brdf
#include_gbuffer
#include_box_blur
#include_cube_shadows
#include_lights
// With interleaving, the lights from firstInterleaved on (many delta lights, the area-light
// samples) were shaded with the VPLs (shade_vpl.frag) and are inside indirectTex.
uniform int shadedHere;  // lights[0 .. shadedHere) are evaluated here
uniform vec3 cameraPos;
uniform int addIndirect;
layout(binding = 0) uniform sampler2D g0Tex;
layout(binding = 1) uniform usampler2D g1Tex;
// The indirect light in image layout, the discontinuity bits in alpha (bit 1: this pixel and
// the one below lie on different surfaces). boxHeight m, or 1: no vertical blur.
layout(binding = 3) uniform sampler2D indirectTex;
uniform int boxHeight;
layout(location = 0) out vec4 result;

void main() {
    const ivec2 p = ivec2(gl_FragCoord.xy);
    const vec4 g0 = texelFetch(g0Tex, p, 0);
    const int kind = surfaceKind(g0);
    if (kind == 2) { result = vec4(emitterRadiance(texelFetch(g1Tex, p, 0)), 1.0); return; }
    if (kind != 1) { result = vec4(0.0, 0.0, 0.0, 1.0); return; }
    const Surface s = decodeSurface(g0, texelFetch(g1Tex, p, 0));
    const vec3 wo = normalize(cameraPos - s.position);
    // The vertical half of the box blur (box_blur.glsl), over the image layout.
    vec3 sum = addIndirect != 0 ? boxBlur(indirectTex, p, ivec2(0, 1), boxHeight, ivec2(1), ivec2(1)).rgb : vec3(0.0);
#if LIGHT_LOOP
    for (int i = 0; i < shadedHere; ++i) sum += lightContribution(i, s, wo);
#endif
    result = vec4(sum, 1.0);
}
