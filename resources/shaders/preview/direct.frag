#version 450 core
// Direct light and the final blend: emitters show their radiance; shaded surfaces get the direct
// light of every point and spot light (cube shadow maps), directional light (orthographic shadow
// maps) and, without interleaving, of the area lights' point samples (cube shadow maps), plus the
// indirect light, which with interleaving also holds the area lights, blurred vertically here
// (the second half of the box blur; blur.frag did the gather and the horizontal half).
// Compile-time switches (frame_passes.cpp, directProgram), so that the pass holds only the
// code the scene's lights need (on llvmpipe an unused light loop still halves this pass's speed):
//   LIGHT_LOOP   0 when this pass evaluates no light (all light is in the indirect texture);
//   DIRECTIONAL, SPOT, AREA, LUMINAIRE   1 when lights of that kind are in the light buffer.
#include_brdf
#include_gbuffer
#include_box_blur
// kind: 0 point, 1 spot, 2 directional, 3 area-light sample, 4 luminaire. intensity is W/sr in
// scene units (divided by meters_per_unit^2; a luminaire's per candela of its table), irradiance
// for a directional light, and for an area sample Le / (samples pdf_area) so that it lights like
// a one-sided cos-weighted point light. A luminaire keeps its table's layer in directionCosCone.w
// (direction = its nadir) and its C0 direction in normalShadow.xyz.
struct Light { vec4 positionKind; vec4 directionCosCone; vec4 intensityCosFalloff; vec4 normalShadow; };
layout(std430, binding = 0) readonly buffer Lights { Light lights[]; };
uniform int lightCount;
uniform vec3 cameraPos;
uniform float shadowBias;
uniform float texelAngle;  // of the cube shadow maps, at a face's centre (radians)
uniform int addIndirect;
uniform int addDirect;
// With interleaving, the area-light samples lights[firstArea ..] were shaded with the VPLs
// (shade_vpl.frag) and are inside indirectTex: areaMode 1 leaves them out here; 0 shades them.
uniform int areaMode;
uniform int firstArea;
layout(binding = 0) uniform sampler2D g0Tex;
layout(binding = 1) uniform usampler2D g1Tex;
// The indirect light in image layout, the discontinuity bits in alpha (bit 1: this pixel and
// the one below lie on different surfaces). boxHeight m, or 1: no vertical blur.
layout(binding = 4) uniform sampler2D indirectTex;
uniform int boxHeight;
layout(binding = 5) uniform samplerCubeArray shadows;
// Directional lights: orthographic depth maps (layer = normalShadow.w), looked up from the
// surface point pushed along its normal (a normal offset, against acne at grazing light).
const int MAX_DIRECTIONAL_SHADOWS = 4;
uniform mat4 dirShadowMatrix[MAX_DIRECTIONAL_SHADOWS];
uniform float dirNormalOffset;  // world units
uniform float dirDepthBias;     // in [0, 1] depth
layout(binding = 6) uniform sampler2DArrayShadow dirShadows;
// Luminaire tables (luminaire_textures.h): candela over (C / 360, gamma / 180), a layer each.
layout(binding = 7) uniform sampler2DArray luminaireTables;
uniform ivec2 luminaireTableSize;
layout(location = 0) out vec4 result;

// The table's candela toward unit w (leaving the luminaire); C90 = C0 x nadir (core/luminaire.h).
float luminaireCandela(vec3 w, vec3 nadir, vec3 c0, float layer) {
    const vec3 c90 = cross(c0, nadir);
    const float gammaDeg = degrees(acos(clamp(dot(w, nadir), -1.0, 1.0)));
    float cDeg = degrees(atan(dot(w, c90), dot(w, c0)));
    if (cDeg < 0.0) cDeg += 360.0;
    const vec2 size = vec2(luminaireTableSize);
    const vec2 uv = (vec2(cDeg / 360.0, gammaDeg / 180.0) * (size - 1.0) + 0.5) / size;
    return texture(luminaireTables, vec3(uv, layer)).r;
}

float spotFactor(float cosTheta, float cosCone, float cosFalloff) {
    if (cosFalloff <= cosCone) return cosTheta >= cosCone ? 1.0 : 0.0;  // a hard edge
    const float t = clamp((cosTheta - cosCone) / (cosFalloff - cosCone), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

// Light i's direct contribution at y (normal n, towards wo), shadowed.
vec3 lightContribution(int i, Surface s, vec3 wo) {
    const vec3 y = s.position, n = s.normal;
    const Light l = lights[i];
    const int kind = int(l.positionKind.w);
    vec3 wi;
    float scale;
#if DIRECTIONAL
    if (kind == 2) {
        wi = -l.directionCosCone.xyz;
        scale = 1.0;
        const int layer = int(l.normalShadow.w);
        if (layer >= 0 && dot(n, wi) > 0.0) {
            const vec4 q = dirShadowMatrix[layer] * vec4(y + n * dirNormalOffset, 1.0);
            const vec3 c = q.xyz * 0.5 + 0.5;
            scale = texture(dirShadows, vec4(c.xy, float(layer), c.z - dirDepthBias));
        }
    } else
#endif
    {
        const vec3 d = l.positionKind.xyz - y;
        const float d2 = dot(d, d);
        wi = d * inversesqrt(d2);
        scale = 1.0 / d2;
#if SPOT
        if (kind == 1) scale *= spotFactor(-dot(wi, l.directionCosCone.xyz), l.directionCosCone.w, l.intensityCosFalloff.w);
#endif
#if AREA
        if (kind == 3) scale *= max(0.0, -dot(wi, l.normalShadow.xyz));
#endif
#if LUMINAIRE
        if (kind == 4) scale *= luminaireCandela(-wi, l.directionCosCone.xyz, l.normalShadow.xyz, l.directionCosCone.w);
#endif
        const float layer = l.normalShadow.w;
        const float cosY = dot(n, wi);
        if (scale > 0.0 && layer >= 0.0 && cosY > 0.0) {
            // Normal offset, as for the VPLs (shade_vpl.frag): a surface the light grazes spans
            // a range of distances within one texel of the map; looking up from a point lifted
            // by a texel's footprint removes the acne that a constant bias leaves.
            const float dist = sqrt(d2);
            const vec3 e = y + n * (dist * texelAngle * min(2.0 / cosY, 8.0)) - l.positionKind.xyz;
            if (length(e) * (1.0 - shadowBias) > texture(shadows, vec4(e, layer)).r) scale = 0.0;
        }
    }
    const float cosY = dot(n, wi);
    if (cosY <= 0.0 || scale <= 0.0) return vec3(0.0);
    return evalBsdf(n, wo, wi, s.albedo, s.specular, s.alpha) * l.intensityCosFalloff.rgb * (cosY * scale);
}

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
    const int end = addDirect == 0 ? 0 : areaMode == 1 ? firstArea : lightCount;
    for (int i = 0; i < end; ++i) sum += lightContribution(i, s, wo);
#endif
    result = vec4(sum, 1.0);
}
