// The direct lights (render/preview/frame_passes.cpp, uploadLights), shared by the direct pass
// (direct.frag: lights it shades in full) and the VPL shading pass (shade_vpl.frag: lights dealt
// to the sub-buffers like VPLs). Needs brdf.glsl, gbuffer.glsl and cube_shadows.glsl before it.
// Compile-time switches: DIRECTIONAL, SPOT, AREA, LUMINAIRE: 1 when lights of that kind are in
// the range the pass evaluates; GLAZING: 1 when the scene has panes (the directional maps then
// have transmittance layers).
//
// kind: 0 point, 1 spot, 2 directional (a scene's directional light, or the sun: normalShadow.x
// 1), 3 area-light sample, 4 luminaire. intensity is W/sr in scene units (divided by
// meters_per_unit^2; a luminaire's per candela of its table), irradiance for directional lights,
// and for an area sample Le / (samples pdf_area) so that it lights like a one-sided cos-weighted
// point light. A luminaire keeps its table's layer in directionCosCone.w (direction = its nadir)
// and its C0 direction in normalShadow.xyz. normalShadow.w: the light's shadow cube
// (directional: its orthographic layer), -1 for none. The sky's directions are SkyLights, apart.
struct Light { vec4 positionKind; vec4 directionCosCone; vec4 intensityCosFalloff; vec4 normalShadow; };
layout(std430, binding = 2) readonly buffer Lights { Light lights[]; };
uniform float lightShadowBias;   // relative
uniform float lightTexelAngle;   // of the lights' cube shadow maps, at a face's centre (radians)
uniform float areaShadowSlack;   // scene units: the area samples' maps hold a proxy (shadow_proxy.h)
uniform int lightCubesPerArray;
layout(binding = 8) uniform samplerCubeArray lightShadows[4];
// Directional lights: orthographic depth maps (layer = normalShadow.w), looked up from the
// surface point pushed along its normal (a normal offset, against acne at grazing light); a
// matrix a layer.
layout(std430, binding = 3) readonly buffer DirShadowMatrices { mat4 dirShadowMatrix[]; };
uniform float dirNormalOffset;  // world units
uniform float dirDepthBias;     // in [0, 1] depth
uniform float planeDepthBias;   // texels of depth, for the lookups by the receiver's plane (the sun, the sky)
layout(binding = 12) uniform sampler2DArrayShadow dirShadows;
#if GLAZING
// render/preview/shadow_maps.h: the panes' transmittance in front of the opaque depth (rgb) and
// the nearest pane's depth (a).
layout(binding = 15) uniform sampler2DArray dirTransmittance;
layout(binding = 16) uniform sampler2DArray skyTransmittance;
#endif
// The sun's map read as numbers (a sampler object without comparison), and the sky's maps.
layout(binding = 17) uniform sampler2DArray dirDepth;
layout(binding = 14) uniform sampler2DArray skyDepth;
// One of the sky's directions (render/preview/daylight_samples.h, direct_lights.cpp): toward
// it and its layer of skyDepth, its irradiance, its map's matrix.
struct SkyLight { vec4 towardLayer; vec4 irradiance; mat4 shadow; };
// Luminaire tables (luminaire_textures.h): candela over (C / 360, gamma / 180), a layer each.
layout(binding = 13) uniform sampler2DArray luminaireTables;
uniform ivec2 luminaireTableSize;

// The table's candela toward unit w (leaving the luminaire); C90 = C0 x nadir (core/photometry/luminaire.h).
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

// What reaches y from a directional map's light: the opaque depth compared (2 x 2 PCF), and with
// glazing each texel's panes' transmittance when y lies behind its nearest pane.
#if GLAZING
#define DIRECTIONAL_LIGHT(maps, panes, m, layer, y, bias) directionalLight(maps, panes, m, layer, y, bias)
vec3 directionalLight(sampler2DArrayShadow maps, sampler2DArray panes, mat4 m, int layer, vec3 y, float bias) {
#else
#define DIRECTIONAL_LIGHT(maps, panes, m, layer, y, bias) directionalLight(maps, m, layer, y, bias)
vec3 directionalLight(sampler2DArrayShadow maps, mat4 m, int layer, vec3 y, float bias) {
#endif
    const vec4 q = m * vec4(y, 1.0);
    const vec3 c = q.xyz * 0.5 + 0.5;
#if GLAZING
    // The 2 x 2 PCF by hand, texel by texel: each texel's comparison times its panes'
    // transmittance when y is behind its nearest pane, weighted bilinearly. (Filtering the two
    // apart would let a lit texel at a window's edge pair with its unglazed opaque neighbour's
    // transmittance of 1: a leak of untinted light along every window's border.)
    const vec3 at = vec3(c.xy, float(layer));
    const vec2 f = fract(c.xy * vec2(textureSize(maps, 0).xy) - 0.5);
    const vec4 w = vec4((1.0 - f.x) * f.y, f.x * f.y, f.x * (1.0 - f.y), (1.0 - f.x) * (1.0 - f.y));  // gather's order
    const vec4 lit = textureGather(maps, at, c.z - bias) * w;
    const vec4 behind = vec4(greaterThan(vec4(c.z - bias), textureGather(panes, at, 3)));
    const vec4 one = vec4(1.0);
    return vec3(dot(lit, mix(one, textureGather(panes, at, 0), behind)), dot(lit, mix(one, textureGather(panes, at, 1), behind)),
                dot(lit, mix(one, textureGather(panes, at, 2), behind)));
#else
    return vec3(texture(maps, vec4(c.xy, float(layer), c.z - bias)));
#endif
}

// What reaches y from a direction at the nearest texel of a map read as numbers (the sun's and
// the sky's), by the receiver's plane: y's depth carried along its surface (normal n) to that
// texel's centre, where the map holds the depth of whatever the texel's centre saw, so that a
// surface lit by the direction meets its own depth there to float precision at any slope, and
// `bias` (texels of depth) stays small. A bias of many texels instead let the ground's light in
// through the joints of thin walls (a room glowed along every edge at 17 texels); a normal offset
// moved every direction's pool of light toward the foot of its window (2 texels: +1% under a
// skylight). With glazing, the panes of the same texel.
#if GLAZING
#define NEAREST_DIRECTIONAL_LIGHT(maps, panes, m, layer, y, n, bias) nearestDirectionalLight(maps, panes, m, layer, y, n, bias)
vec3 nearestDirectionalLight(sampler2DArray maps, sampler2DArray panes, mat4 m, int layer, vec3 y, vec3 n, float bias) {
#else
#define NEAREST_DIRECTIONAL_LIGHT(maps, panes, m, layer, y, n, bias) nearestDirectionalLight(maps, m, layer, y, n, bias)
vec3 nearestDirectionalLight(sampler2DArray maps, mat4 m, int layer, vec3 y, vec3 n, float bias) {
#endif
    const vec3 c = (m * vec4(y, 1.0)).xyz * 0.5 + 0.5;
    // The plane's depth gradient in map space (the map scales x, y and depth alike).
    const vec3 nm = mat3(m) * n;
    const vec2 gradient = clamp(-nm.xy / min(nm.z, -1e-6), vec2(-16.0), vec2(16.0));
    const ivec2 size = textureSize(maps, 0).xy;
    const float texel = 1.0 / float(size.x);
    ivec2 at = clamp(ivec2(floor(c.xy * vec2(size))), ivec2(0), size - 1);
    const float depth = c.z + dot(gradient, (vec2(at) + 0.5) * texel - c.xy) - bias * texel;
    const float stored = texelFetch(maps, ivec3(at, layer), 0).r;
    float lit = depth <= stored ? 1.0 : 0.0;
    // Near the edge of y's surface the texel's centre may lie off it, where the map saw something
    // behind the surface's plane or nothing: that texel says nothing about y. The 2 x 2 texels
    // around y decide, y in shadow if any of them is, which at a joint of thin walls finds the
    // wall that meets this surface (the nearest texel alone let light in along every edge of a
    // closed room, a texel wide). Rare: only where the map shows the surface's edge.
    if (stored >= depth + 0.5 * texel) {
        const ivec2 base = ivec2(floor(c.xy * vec2(size) - 0.5));
        for (int k = 0; k < 4; ++k) {
            const ivec2 o = clamp(base + ivec2(k & 1, k >> 1), ivec2(0), size - 1);
            if (c.z + dot(gradient, (vec2(o) + 0.5) * texel - c.xy) - bias * texel > texelFetch(maps, ivec3(o, layer), 0).r) {
                lit = 0.0;
                at = o;
            }
        }
    }
#if GLAZING
    const vec4 t = texelFetch(panes, ivec3(at, layer), 0);
    return depth > t.a ? lit * t.rgb : vec3(lit);
#else
    return vec3(lit);
#endif
}

// Sky direction l's irradiance at surface s, times cos and what reaches it (the BSDF is the
// caller's); one exit, as the other lights.
vec3 skyLight(SkyLight l, Surface s) {
    const float cosY = dot(s.normal, l.towardLayer.xyz);
    vec3 c = vec3(0.0);
    if (cosY > 0.0)
        c = l.irradiance.rgb * cosY *
            NEAREST_DIRECTIONAL_LIGHT(skyDepth, skyTransmittance, l.shadow, int(l.towardLayer.w), s.position, s.normal, planeDepthBias);
    return c;
}

// Light i's direct contribution at s (towards wo), shadowed.
vec3 lightContribution(int i, Surface s, vec3 wo) {
    const vec3 y = s.position, n = s.normal;
    const Light l = lights[i];
    const int kind = int(l.positionKind.w);
    vec3 wi;
    float scale;
    vec3 tint = vec3(1.0);
#if DIRECTIONAL
    if (kind == 2) {
        wi = -l.directionCosCone.xyz;
        scale = 1.0;
        const int layer = int(l.normalShadow.w);
        if (layer >= 0 && dot(n, wi) > 0.0) {
            const mat4 m = dirShadowMatrix[layer];
            // The sun (normalShadow.x 1): by the receiver's plane, at the nearest texel (its
            // disc's jitter over frames softens the edge); other directional lights with the
            // 2 x 2 PCF and a normal offset.
            if (l.normalShadow.x > 0.0)
                tint = NEAREST_DIRECTIONAL_LIGHT(dirDepth, dirTransmittance, m, layer, y, n, planeDepthBias);
            else
                tint = DIRECTIONAL_LIGHT(dirShadows, dirTransmittance, m, layer, y + n * dirNormalOffset, dirDepthBias);
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
    return evalBsdf(n, wo, wi, s.albedo, s.specular, s.alpha) * l.intensityCosFalloff.rgb * tint * (cosY * scale);
}
