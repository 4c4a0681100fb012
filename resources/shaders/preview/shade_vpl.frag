#version 450 core
// Indirect light from VPLs over the split G-buffer: every tile (sub-buffer) is shaded with its
// own subset of the VPLs, which the CPU ordered by subset with powers already scaled (by about
// n m) so that each subset alone estimates the whole indirect light. One draw per tile, all in
// this one pass: the tile's VPLs are then the same for every fragment of a draw, and with
// UNROLLED_VPLS > 0 they are read from a uniform block at constant indices (the loop unrolled by
// FOR_EACH_TILE_VPL), which llvmpipe loads once for all its SIMD lanes instead of gathering them
// lane by lane (BENCHMARKS.md, issue 5). Otherwise, for tiles with more VPLs than an unrolled body
// should hold, a loop over [vplFirst, vplFirst + vplCount) of the storage buffer.
// Compile-time switches, set by the C++ side (frame_passes.cpp, shadeProgram) from the settings
// and the scene, so that an unrolled body holds only the code the scene needs (llvmpipe runs a
// SIMD vector of fragments through every branch any of them takes):
//   UNROLLED_VPLS, FOR_EACH_TILE_VPL(STEP)  as above;
//   VPL_SHADOW_CHUNKS  0: VPL visibility off; else the cube map arrays holding the VPLs' maps;
//   GLOSSY             0 when the scene has no glossy material (all VPLs and receivers diffuse);
//   AREA_SAMPLES       1 when the area lights' samples are shaded here (interleaved);
//   UNROLLED_AREA      with AREA_SAMPLES, the samples each sub-buffer gets, read at constant
//                      indices from a uniform block (as the VPLs); 0: a loop over the buffer;
//   FIND_EDGES         1 when the box blur follows (the discontinuity bits go out in alpha);
//   FUSED_SPLIT        1: no split pass ran; each fragment of tile t at q reads its G-buffer texel
//                      q n + t straight from the image-layout G-buffer (and finds its
//                      discontinuity bits there), as split.frag's one-pass mode would have
//                      moved it. On llvmpipe, which has no texture cache to keep coherent, this
//                      saves the split's writes and reads (BENCHMARKS.md, issue 5).
// Lighting y from a VPL at x (render/vpl/vpl.h):
//   f_y(wo, y->x) power f_x(incident, x->y) min(cos_x cos_y / d^2, maxG) V(x, y),
// the geometric term clamped as in render/vpl/vpl_contribution.h (the energy the clamp loses is
// reported by the benchmarks).
#include_brdf
#include_gbuffer
#include_discontinuity
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
// VPL i's cube map: cube i mod cubesPerChunk of array i / cubesPerChunk (a cube map array holds
// at most GL_MAX_ARRAY_TEXTURE_LAYERS / 6 cubes). Samplers cannot be indexed by a non-uniform
// value, hence the branches, only as many as there are arrays.
uniform int cubesPerChunk;
layout(binding = 4) uniform samplerCubeArray vplShadows0;
layout(binding = 6) uniform samplerCubeArray vplShadows1;
layout(binding = 7) uniform samplerCubeArray vplShadows2;
layout(binding = 8) uniform samplerCubeArray vplShadows3;

float vplShadowDistance(vec3 dir, int index) {
#if VPL_SHADOW_CHUNKS <= 1
    return texture(vplShadows0, vec4(dir, float(index))).r;
#else
    const int chunk = index / cubesPerChunk;
    const vec4 c = vec4(dir, float(index - chunk * cubesPerChunk));
    if (chunk == 0) return texture(vplShadows0, c).r;
#if VPL_SHADOW_CHUNKS > 2
    if (chunk == 2) return texture(vplShadows2, c).r;
#endif
#if VPL_SHADOW_CHUNKS > 3
    if (chunk == 3) return texture(vplShadows3, c).r;
#endif
    return texture(vplShadows1, c).r;
#endif
}
layout(location = 0) out vec4 result;

// Area lights "as VPLs of their own" (direct.frag's lights[]): with interleaving, sample i of
// lights[firstArea .. firstArea + areaCount) lights sub-buffer i mod (n m) only, times n m, so
// the box blur averages them back like the VPLs. Always shadowed (their cube maps), never clamped.
struct Light { vec4 positionKind; vec4 directionCosCone; vec4 intensityCosFalloff; vec4 normalShadow; };
#if UNROLLED_AREA > 0
layout(std140, binding = 1) uniform TileAreas { Light tileAreas[UNROLLED_AREA]; };  // this sub-buffer's
#else
layout(std430, binding = 2) readonly buffer Lights { Light lights[]; };
#endif
uniform int firstArea;
uniform int areaCount;
uniform float areaShadowBias;    // relative
layout(binding = 5) uniform samplerCubeArray areaShadows;

// An area sample's light at y: at `position`, facing normalShadow.xyz, its shadow cube
// normalShadow.w, intensity as direct.frag's. Without GLOSSY the receiver's BSDF (albedo / pi) is
// applied by the caller, once for all samples. One exit, as vplLight.
vec3 areaSampleLight(vec3 position, vec4 normalShadow, vec3 intensity, Surface sy, vec3 wo) {
    const vec3 d = position - sy.position;
    const float d2 = dot(d, d);
    const vec3 wi = d * inversesqrt(d2);
    const float cosY = dot(sy.normal, wi), cosE = -dot(wi, normalShadow.xyz);
    float g = cosY > 0.0 && cosE > 0.0 ? cosY * cosE / d2 : 0.0;
    if (g > 0.0 && sqrt(d2) * (1.0 - areaShadowBias) > texture(areaShadows, vec4(-wi, normalShadow.w)).r) g = 0.0;
#if GLOSSY
    return evalBsdf(sy.normal, wo, wi, sy.albedo, sy.specular, sy.alpha) * intensity * g;
#else
    return intensity * g;
#endif
}

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
#if VPL_SHADOW_CHUNKS > 0
    if (g > 0.0) {
        // Normal offset: the low-resolution map's texel spans a range of distances on a
        // surface seen at a grazing angle; looking up from a point lifted off the surface by
        // a texel's footprint (distance times the texel angle, over cos) removes that acne.
        const vec3 e = y + n * (sqrt(d2) * texelAngle * min(2.0 / cosY, 8.0)) - pos.xyz;
        if (length(e) * (1.0 - shadowBias) > vplShadowDistance(e, int(pos.w))) g = 0.0;
    }
#endif
    vec3 c = vpls[i].power.rgb * g;
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
#if AREA_SAMPLES
    const int subsets = pattern.x * pattern.y;
#if UNROLLED_AREA > 0
    for (int j = 0; j < UNROLLED_AREA; ++j)
        area += areaSampleLight(tileAreas[j].positionKind.xyz, tileAreas[j].normalShadow, tileAreas[j].intensityCosFalloff.rgb, sy, wo);
#else
    // Field by field: three of the light's four vec4s, each gathered lane by lane on llvmpipe.
    for (int i = firstArea + tile.y * pattern.x + tile.x; i < firstArea + areaCount; i += subsets)
        area += areaSampleLight(lights[i].positionKind.xyz, lights[i].normalShadow, lights[i].intensityCosFalloff.rgb, sy, wo);
#endif
#if !GLOSSY
    area *= sy.albedo * (1.0 / PI);
#endif
    area *= float(subsets);
#endif
    result = vec4(sum + area, edges);
}
