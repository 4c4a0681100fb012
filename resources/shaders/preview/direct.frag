#version 450 core
// Direct light and the final blend: emitters show their radiance, pixels that see nothing the sky
// (sky.glsl); shaded surfaces get the direct light of the lights it shades in full (lights.glsl:
// point, spot and luminaire lights with cube shadow maps, directional lights and the sun with
// orthographic ones, and without interleaving the area lights' point samples and the sky's
// directions), plus the indirect light, which with interleaving also holds the area lights, the
// sky's directions and, when there are many, the delta lights, blurred vertically here (the
// second half of the box blur; blur.frag did the gather and the horizontal half). With panes in
// the scene, everything is seen through them: times the camera's transmittance texture.
// Compile-time switches (frame_passes.cpp, directProgram), so that the pass holds only the
// code the scene's lights need (on llvmpipe an unused light loop still halves this pass's speed):
//   LIGHT_LOOP   0 when this pass evaluates no light (all light is in the indirect texture);
//   SKY_LIGHTS   1 when the sky's directions are shaded here (no interleaving);
//   BLOCK_LIGHTS 1 when each block of the image shades its own delta lights in full
//                (light_blocks.glsl), besides lights[0 .. shadedHere);
//   DIRECTIONAL, SPOT, AREA, LUMINAIRE, GLAZING   lights.glsl's.
#include_brdf
#include_gbuffer
#include_box_blur
#include_cube_shadows
#include_lights
#include_sky
#if BLOCK_LIGHTS
#include_light_blocks
#endif
// With interleaving, the lights from firstInterleaved on (many delta lights, the area-light
// samples) were shaded with the VPLs (shade_vpl.frag) and are inside indirectTex.
uniform int shadedHere;  // lights[0 .. shadedHere) are evaluated here
#if SKY_LIGHTS
layout(std430, binding = 5) readonly buffer SkyLights { SkyLight skyLights[]; };
uniform int skyLightCount;
#endif
uniform vec3 cameraPos;
uniform int addIndirect;
layout(binding = 0) uniform sampler2D g0Tex;
layout(binding = 1) uniform usampler2D g1Tex;
// The indirect light in image layout, the discontinuity bits in alpha (bit 1: this pixel and
// the one below lie on different surfaces). boxHeight m, or 1: no vertical blur.
layout(binding = 3) uniform sampler2D indirectTex;
uniform int boxHeight;
uniform int boxFlip;  // box_blur.glsl
// The pixel's ray for the background: the pinhole's forward, right * tan(fov / 2) * aspect and
// up * tan(fov / 2), and the point of the pixel sampled (the frame's jitter).
uniform vec3 viewForward, viewRight, viewUp;
uniform vec2 viewJitter;
uniform int showBackground;  // 0 for white receivers (the illuminance layer)
#if GLAZING
layout(binding = 4) uniform sampler2D viewTransmittance;  // the panes in front of each pixel's surface
uniform int throughPanes;
#endif
layout(location = 0) out vec4 result;

void main() {
    const ivec2 p = ivec2(gl_FragCoord.xy);
    const vec4 g0 = texelFetch(g0Tex, p, 0);
    const int kind = surfaceKind(g0);
    vec3 c = vec3(0.0);
    if (kind == 2) {
        c = emitterRadiance(texelFetch(g1Tex, p, 0));
    } else if (kind == 0) {
        if (showBackground != 0) {
            const vec2 ndc = (vec2(p) + viewJitter) / vec2(textureSize(g0Tex, 0)) * 2.0 - 1.0;
            c = backgroundRadiance(normalize(viewForward + ndc.x * viewRight - ndc.y * viewUp));
        }
    } else if (kind == 1) {
        const Surface s = decodeSurface(g0, texelFetch(g1Tex, p, 0));
        const vec3 wo = normalize(cameraPos - s.position);
        // The vertical half of the box blur (box_blur.glsl), over the image layout.
        int up = 0, down = 0;
        if (addIndirect != 0)
            c = boxBlurWalk(indirectTex, p, ivec2(0, 1), boxHeight, ivec2(1), ivec2(1), boxFlip != 0, up, down).rgb;
#if LIGHT_LOOP
        for (int i = 0; i < shadedHere; ++i) c += lightContribution(i, s, wo);
#endif
#if BLOCK_LIGHTS
        // This block's lights in full, their dealt share taken back out of the blur.
        const int block = lightBlockOf(p);
        for (int k = 0; k < lightsPerBlock; ++k) {
            const int j = blockLights[block * lightsPerBlock + k];
            if (j < 0) continue;
            c += lightContribution(firstBlockLight + j, s, wo);
            if (addIndirect != 0 && dealtAt[j] >= 0) c -= dealtShareInBlur(dealtAt[j], p, up, down, indirectTex, g0Tex, g1Tex, cameraPos);
        }
#endif
#if SKY_LIGHTS
        for (int i = 0; i < skyLightCount; ++i)
            c += evalBsdf(s.normal, wo, skyLights[i].towardLayer.xyz, s.albedo, s.specular, s.alpha) * skyLight(skyLights[i], s);
#endif
    }
#if GLAZING
    if (throughPanes != 0) c *= texelFetch(viewTransmittance, p, 0).rgb;
#endif
    result = vec4(c, 1.0);
}
