#version 450 core
// Indirect light from VPLs over the split G-buffer: every tile (sub-buffer) is shaded with its
// own subset of the VPLs, which the CPU ordered by subset with powers already scaled (by about
// n m) so that each subset alone estimates the whole indirect light. One draw per tile, all in
// this one pass: the tile's VPLs are then the same for every fragment of a draw, and with
// UNROLLED_VPLS > 0 they are read from a uniform block at constant indices (the loop unrolled by
// FOR_EACH_TILE_VPL), which llvmpipe loads once for all its SIMD lanes instead of gathering them
// lane by lane (docs/benchmarks-history.md, issue 5, "Session 5"). Otherwise, for tiles with more
// VPLs than an unrolled body should hold, a loop over [vplFirst, vplFirst + vplCount) of the
// storage buffer.
// Compile-time switches, set by the C++ side (frame_passes.cpp, shadeProgram) from the settings
// and the scene, so that an unrolled body holds only the code the scene needs (llvmpipe runs a
// SIMD vector of fragments through every branch any of them takes):
//   UNROLLED_VPLS, FOR_EACH_TILE_VPL(STEP)  as above;
//   VPL_VISIBILITY     1 when the VPLs have shadow maps (cube_shadows.glsl);
//   VPL_PANES          the pane triangles each VPL's light is tested against (0: none), which
//                      the shadow maps leave out: the light crossing one is times its
//                      transmittance;
//   GLOSSY             0 when the scene has no glossy material (all VPLs and receivers diffuse);
//   INTERLEAVED_LIGHTS 1 when lights are dealt to the sub-buffers and shaded here: the area
//                      lights' samples, and the delta lights when there are many;
//   UNROLLED_AREA      with INTERLEAVED_LIGHTS, when they are area samples only, the samples each
//                      sub-buffer gets, read at constant indices from a uniform block (as the
//                      VPLs); 0: a loop over the buffer, any kind of light;
//   SPOT, AREA, LUMINAIRE, GLAZING   lights.glsl's switches for the interleaved lights;
//   SKY_PER_TILE       the sky's directions each sub-buffer gets (lights.glsl's SkyLight), read at
//                      constant indices from a uniform block; 0: none here;
//   FIND_EDGES         1 when the box blur follows (the discontinuity bits go out in alpha);
//   FUSED_SPLIT        1: no split pass ran; each fragment of tile t at q reads its G-buffer texel
//                      q n + t straight from the image-layout G-buffer (and finds its
//                      discontinuity bits there), as split.frag's one-pass mode would have
//                      moved it. On llvmpipe, which has no texture cache to keep coherent, this
//                      saves the split's writes and reads (docs/benchmarks-history.md, issue 5,
//                      "Session 6").
// Lighting y from a VPL at x (render/vpl/vpl.h):
//   f_y(wo, y->x) power f_x(incident, x->y) min(cos_x cos_y / d^2, maxG) V(x, y),
// the geometric term clamped as in render/vpl/vpl_contribution.h (the energy the clamp loses is
// reported by the benchmarks).
#include_brdf
#include_gbuffer
#include_discontinuity
#include_cube_shadows
#include_lights
struct Vpl { vec4 positionIndex; vec4 normalAlpha; vec4 incident; vec4 power; vec4 albedo; vec4 specular; };
#if UNROLLED_VPLS > 0
layout(std140, binding = 0) uniform TileVpls { Vpl vpls[UNROLLED_VPLS]; };
#else
layout(std430, binding = 0) readonly buffer Vpls { Vpl vpls[]; };
#endif
uniform ivec2 tile;             // this draw's sub-buffer
uniform int vplFirst;           // its VPLs: vpls[vplFirst .. vplFirst + vplCount)
uniform int vplCount;
uniform ivec2 pattern;
uniform vec3 cameraPos;
uniform float maxG;
uniform float shadowBias;       // relative
uniform float texelAngle;       // of the VPL cube maps, at a face's centre (radians)
layout(binding = 0) uniform sampler2D g0Tex;
layout(binding = 1) uniform usampler2D g1Tex;
// VPL i's cube map (cube_shadows.glsl).
uniform int cubesPerChunk;
layout(binding = 4) uniform samplerCubeArray vplShadows[4];
uniform float vplShadowSlack;   // scene units: the VPLs' maps may hold a proxy (shadow_proxy.h)
layout(location = 0) out vec4 result;

// Lights "as VPLs of their own" (lights.glsl): with interleaving, light i of
// lights[firstInterleaved .. firstInterleaved + interleavedCount) lights sub-buffer i mod (n m)
// only, times n m, so that the box blur averages them back like the VPLs: the area lights'
// samples always, and the delta lights when there are many (frame_passes.cpp, uploadLights).
// Always shadowed (their cube maps), never clamped.
uniform int firstInterleaved;
uniform int interleavedCount;
#if UNROLLED_AREA > 0
layout(std140, binding = 1) uniform TileAreas { Light tileAreas[UNROLLED_AREA]; };  // this sub-buffer's
#endif
#if SKY_PER_TILE > 0
layout(std140, binding = 2) uniform TileSky { SkyLight tileSky[SKY_PER_TILE]; };  // this sub-buffer's
#endif

// An area sample's light at y: at `position`, facing normalShadow.xyz, its shadow cube
// normalShadow.w, intensity as direct.frag's. Without GLOSSY the receiver's BSDF (albedo / pi) is
// applied by the caller, once for all samples. One exit, as vplLight.
vec3 areaSampleLight(vec3 position, vec4 normalShadow, vec3 intensity, Surface sy, vec3 wo) {
    const vec3 d = position - sy.position;
    const float d2 = dot(d, d);
    const vec3 wi = d * inversesqrt(d2);
    const float cosY = dot(sy.normal, wi), cosE = -dot(wi, normalShadow.xyz);
    float g = cosY > 0.0 && cosE > 0.0 ? cosY * cosE / d2 : 0.0;
    if (g > 0.0 && sqrt(d2) * (1.0 - lightShadowBias) - areaShadowSlack >
                       cubeShadowDistance(lightShadows, lightCubesPerArray, -wi, int(normalShadow.w)))
        g = 0.0;
#if GLOSSY
    return evalBsdf(sy.normal, wo, wi, sy.albedo, sy.specular, sy.alpha) * intensity * g;
#else
    return intensity * g;
#endif
}

#if VPL_PANES > 0
// The pane triangles (render/preview/gpu_state.h, GpuPane), and the product of the
// transmittances of those the segment from a to b crosses (Moller and Trumbore, t in (0, 1)).
struct Pane { vec4 p0; vec4 e1; vec4 e2; vec4 transmittance; };
layout(std430, binding = 7) readonly buffer Panes { Pane panes[VPL_PANES]; };
vec3 paneTransmittance(vec3 a, vec3 b) {
    const vec3 d = b - a;
    vec3 t = vec3(1.0);
    for (int k = 0; k < VPL_PANES; ++k) {
        const vec3 e1 = panes[k].e1.xyz, e2 = panes[k].e2.xyz;
        const vec3 q = cross(d, e2);
        const float det = dot(e1, q);
        const vec3 s = a - panes[k].p0.xyz;
        const float b1 = dot(s, q) / det;
        const vec3 r = cross(s, e1);
        const float b2 = dot(d, r) / det, along = dot(e2, r) / det;
        if (abs(det) > 1e-20 && b1 >= 0.0 && b2 >= 0.0 && b1 + b2 <= 1.0 && along > 1e-4 && along < 1.0 - 1e-4)
            t *= panes[k].transmittance.rgb;
    }
    return t;
}
#endif

// VPL i's light at y (normal n, glossy receiver or not; a diffuse receiver's albedo / pi is
// applied by the caller), its fields read one by one as they are needed: a diffuse VPL (the
// common case) costs three of its six vec4s.
vec3 vplLight(int i, Surface sy, vec3 wo, bool glossyY) {
    const vec3 y = sy.position, n = sy.normal;
    const vec4 pos = vpls[i].positionIndex;
    const vec3 d = pos.xyz - y;
    const float d2 = dot(d, d);
    const vec3 wi = d * inversesqrt(d2);
    const vec4 nx = vpls[i].normalAlpha;
    const float cosY = dot(n, wi), cosX = -dot(nx.xyz, wi);
    // One exit, no early returns: llvmpipe runs a SIMD vector of fragments through every branch
    // that any of them takes, and returns from an inlined function cost it extra masks.
    float g = cosY > 0.0 && cosX > 0.0 ? min(cosX * cosY / d2, maxG) : 0.0;
#if VPL_VISIBILITY > 0
    if (g > 0.0) {
        // Normal offset: the low-resolution map's texel spans a range of distances on a
        // surface seen at a grazing angle; looking up from a point lifted off the surface by
        // a texel's footprint (distance times the texel angle, over cos) removes that acne.
        const vec3 e = y + n * (sqrt(d2) * texelAngle * min(2.0 / cosY, 8.0)) - pos.xyz;
        if (length(e) * (1.0 - shadowBias) - vplShadowSlack > cubeShadowDistance(vplShadows, cubesPerChunk, e, int(pos.w)))
            g = 0.0;
    }
#endif
    vec3 c = vpls[i].power.rgb * g;
#if VPL_PANES > 0
    if (g > 0.0) c *= paneTransmittance(pos.xyz, y);
#endif
#if GLOSSY
    const vec4 incident = vpls[i].incident;
    if (incident.w != 0.0)
        c *= evalBsdf(nx.xyz, incident.xyz, -wi, vpls[i].albedo.rgb, vpls[i].specular.rgb, nx.w);
    if (glossyY) c *= evalBsdf(n, wo, wi, sy.albedo, sy.specular, sy.alpha);
#endif
    return c;
}

// Split layout (interleaved, a split pass ran): the discontinuity bits found by split.frag,
// passed through to the blur in the output's alpha.
layout(binding = 2) uniform usampler2D edgesTex;
uniform ivec2 subSize;      // FUSED_SPLIT: a tile's size in the output
uniform ivec2 sourceSize;   // FUSED_SPLIT: the G-buffer's size

void main() {
#if FUSED_SPLIT
    const ivec2 p = (ivec2(gl_FragCoord.xy) - tile * subSize) * pattern + tile;
    if (any(greaterThanEqual(p, sourceSize))) { result = vec4(0.0, 0.0, 0.0, 3.0); return; }
#else
    const ivec2 p = ivec2(gl_FragCoord.xy);
#endif
    const vec4 g0 = texelFetch(g0Tex, p, 0);
    const uvec4 g1 = texelFetch(g1Tex, p, 0);
#if FIND_EDGES && FUSED_SPLIT
    const float edges = float(edgeBits(g0Tex, g1Tex, sourceSize, cameraPos, p, g0, decodeNormal(g1)));
#elif FIND_EDGES
    const float edges = float(texelFetch(edgesTex, p, 0).r);
#else
    const float edges = 0.0;
#endif
    if (surfaceKind(g0) != 1) { result = vec4(0.0, 0.0, 0.0, edges); return; }
    const Surface sy = decodeSurface(g0, g1);
    const vec3 y = sy.position, n = sy.normal, wo = normalize(cameraPos - y);
    // Diffuse receivers and diffuse VPLs (the common case) have constant BSDFs: their albedo / pi
    // is taken out of the loop (receiver) or premultiplied into the power on the CPU (VPL,
    // incident.w == 0), which more than halves the loop's cost on llvmpipe.
    const bool glossyY = max(sy.specular.r, max(sy.specular.g, sy.specular.b)) > 0.0;
    vec3 sum = vec3(0.0);
#if UNROLLED_VPLS > 0
#define TILE_VPL(k) if (k < vplCount) sum += vplLight(k, sy, wo, glossyY);
    FOR_EACH_TILE_VPL(TILE_VPL)
#else
    for (int i = vplFirst; i < vplFirst + vplCount; ++i) sum += vplLight(i, sy, wo, glossyY);
#endif
    if (!glossyY) sum *= sy.albedo * (1.0 / PI);
    vec3 area = vec3(0.0);
#if INTERLEAVED_LIGHTS
    const int subsets = pattern.x * pattern.y;
#if UNROLLED_AREA > 0
    for (int j = 0; j < UNROLLED_AREA; ++j)
        area += areaSampleLight(tileAreas[j].positionKind.xyz, tileAreas[j].normalShadow, tileAreas[j].intensityCosFalloff.rgb, sy, wo);
#if !GLOSSY
    area *= sy.albedo * (1.0 / PI);
#endif
#else
    // Any kind of light (lights.glsl), its BSDF included.
    for (int i = firstInterleaved + tile.y * pattern.x + tile.x; i < firstInterleaved + interleavedCount; i += subsets)
        area += lightContribution(i, sy, wo);
#endif
    area *= float(subsets);
#endif
    // The sky's directions dealt to this sub-buffer, times n m like the lights above.
    vec3 sky = vec3(0.0);
#if SKY_PER_TILE > 0
    for (int j = 0; j < SKY_PER_TILE; ++j)
#if GLOSSY
        sky += evalBsdf(sy.normal, wo, tileSky[j].towardLayer.xyz, sy.albedo, sy.specular, sy.alpha) * skyLight(tileSky[j], sy);
#else
        sky += skyLight(tileSky[j], sy);
    sky *= sy.albedo * (1.0 / PI);
#endif
    sky *= float(pattern.x * pattern.y);
#endif
    result = vec4(sum + area + sky, edges);
}
