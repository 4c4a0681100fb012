// The direct lights (render/preview/frame_passes.cpp, uploadLights), shared by the direct pass
// (direct.frag: lights it shades in full) and the VPL shading pass (shade_vpl.frag: lights dealt
// to the sub-buffers like VPLs). Needs brdf.glsl, gbuffer.glsl and cube_shadows.glsl before it.
// Compile-time switches: DIRECTIONAL, SPOT, AREA, LUMINAIRE: 1 when lights of that kind are in
// the range the pass evaluates.
//
// kind: 0 point, 1 spot, 2 directional, 3 area-light sample, 4 luminaire. intensity is W/sr in
// scene units (divided by meters_per_unit^2; a luminaire's per candela of its table), irradiance
// for a directional light, and for an area sample Le / (samples pdf_area) so that it lights like
// a one-sided cos-weighted point light. A luminaire keeps its table's layer in directionCosCone.w
// (direction = its nadir) and its C0 direction in normalShadow.xyz. normalShadow.w: the light's
// shadow cube (directional: its orthographic layer), -1 for none.
struct Light { vec4 positionKind; vec4 directionCosCone; vec4 intensityCosFalloff; vec4 normalShadow; };
layout(std430, binding = 2) readonly buffer Lights { Light lights[]; };
uniform float lightShadowBias;   // relative
uniform float lightTexelAngle;   // of the lights' cube shadow maps, at a face's centre (radians)
uniform float areaShadowSlack;   // scene units: the area samples' maps hold a proxy (shadow_proxy.h)
uniform int lightCubesPerArray;
layout(binding = 8) uniform samplerCubeArray lightShadows[4];
// Directional lights: orthographic depth maps (layer = normalShadow.w), looked up from the
// surface point pushed along its normal (a normal offset, against acne at grazing light).
const int MAX_DIRECTIONAL_SHADOWS = 4;
uniform mat4 dirShadowMatrix[MAX_DIRECTIONAL_SHADOWS];
uniform float dirNormalOffset;  // world units
uniform float dirDepthBias;     // in [0, 1] depth
layout(binding = 12) uniform sampler2DArrayShadow dirShadows;
// Luminaire tables (luminaire_textures.h): candela over (C / 360, gamma / 180), a layer each.
layout(binding = 13) uniform sampler2DArray luminaireTables;
uniform ivec2 luminaireTableSize;

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

// Light i's direct contribution at s (towards wo), shadowed.
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
        float slack = 0.0;
#if SPOT
        if (kind == 1) scale *= spotFactor(-dot(wi, l.directionCosCone.xyz), l.directionCosCone.w, l.intensityCosFalloff.w);
#endif
#if AREA
        if (kind == 3) {
            scale *= max(0.0, -dot(wi, l.normalShadow.xyz));
            slack = areaShadowSlack;
        }
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
            const vec3 e = y + n * (dist * lightTexelAngle * min(2.0 / cosY, 8.0)) - l.positionKind.xyz;
            if (length(e) * (1.0 - lightShadowBias) - slack >
                cubeShadowDistance(lightShadows, lightCubesPerArray, e, int(layer)))
                scale = 0.0;
        }
    }
    const float cosY = dot(n, wi);
    if (cosY <= 0.0 || scale <= 0.0) return vec3(0.0);
    return evalBsdf(n, wo, wi, s.albedo, s.specular, s.alpha) * l.intensityCosFalloff.rgb * (cosY * scale);
}
