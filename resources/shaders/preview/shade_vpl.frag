#version 450 core
// Indirect light from VPLs over the split G-buffer: every tile (sub-buffer) is shaded with its
// own subset of the VPLs, all tiles in this one pass. ranges[tile] = (first VPL, count) in the
// VPL buffer, which the CPU ordered by subset with powers already scaled (by about n m) so that each
// subset alone estimates the whole indirect light.
// Lighting y from a VPL at x (render/vpl/vpl.h):
//   f_y(wo, y->x) power f_x(incident, x->y) min(cos_x cos_y / d^2, maxG) V(x, y),
// the geometric term clamped as in render/vpl/vpl_contribution.h (the energy the clamp loses is
// reported by the benchmarks).
#include_brdf
struct Vpl { vec4 positionIndex; vec4 normalAlpha; vec4 incident; vec4 power; vec4 albedo; vec4 specular; };
layout(std430, binding = 0) readonly buffer Vpls { Vpl vpls[]; };
layout(std430, binding = 1) readonly buffer Ranges { ivec2 ranges[]; };
uniform ivec2 pattern;
uniform ivec2 subSize;
uniform vec3 cameraPos;
uniform float maxG;
uniform int visibility;         // 1: look up each VPL's cube shadow map
uniform float shadowBias;       // relative
uniform float texelAngle;       // of the VPL cube maps, at a face's centre (radians)
layout(binding = 0) uniform sampler2D g0Tex;
layout(binding = 1) uniform sampler2D g1Tex;
layout(binding = 2) uniform sampler2D g2Tex;
layout(binding = 3) uniform sampler2D g3Tex;
// VPL i's cube map: cube i mod cubesPerChunk of array i / cubesPerChunk (a cube map array holds
// at most GL_MAX_ARRAY_TEXTURE_LAYERS / 6 cubes). Samplers cannot be indexed by a non-uniform
// value, hence the branches.
uniform int cubesPerChunk;
layout(binding = 4) uniform samplerCubeArray vplShadows0;
layout(binding = 6) uniform samplerCubeArray vplShadows1;
layout(binding = 7) uniform samplerCubeArray vplShadows2;
layout(binding = 8) uniform samplerCubeArray vplShadows3;

float vplShadowDistance(vec3 dir, int index) {
    const int chunk = index / cubesPerChunk;
    const vec4 c = vec4(dir, float(index - chunk * cubesPerChunk));
    if (chunk == 0) return texture(vplShadows0, c).r;
    if (chunk == 1) return texture(vplShadows1, c).r;
    if (chunk == 2) return texture(vplShadows2, c).r;
    return texture(vplShadows3, c).r;
}
layout(location = 0) out vec4 result;

// Area lights "as VPLs of their own" (direct.frag's lights[]): with interleaving, sample i of
// lights[firstArea .. firstArea + areaCount) lights sub-buffer i mod (n m) only, times n m, so
// the box blur averages them back like the VPLs. Always shadowed (their cube maps), never clamped.
struct Light { vec4 positionKind; vec4 directionCosCone; vec4 intensityCosFalloff; vec4 normalShadow; };
layout(std430, binding = 2) readonly buffer Lights { Light lights[]; };
uniform int firstArea;
uniform int areaCount;           // 0: the direct pass does the area lights
uniform float areaShadowBias;    // relative
layout(binding = 5) uniform samplerCubeArray areaShadows;

void main() {
    const ivec2 p = ivec2(gl_FragCoord.xy);
    const vec4 g0 = texelFetch(g0Tex, p, 0);
    if (g0.w != 1.0) { result = vec4(0.0); return; }
    const vec4 g1 = texelFetch(g1Tex, p, 0), g2 = texelFetch(g2Tex, p, 0), g3 = texelFetch(g3Tex, p, 0);
    const vec3 y = g0.xyz, n = g1.xyz, wo = normalize(cameraPos - y);
    const ivec2 tile = min(p / subSize, pattern - 1);
    const ivec2 range = ranges[tile.y * pattern.x + tile.x];
    // Diffuse receivers and diffuse VPLs (the common case) have constant BSDFs: their albedo / pi
    // is taken out of the loop (receiver) or premultiplied into the power on the CPU (VPL,
    // incident.w == 0), which more than halves the loop's cost on llvmpipe.
    const bool glossyY = max(g3.r, max(g3.g, g3.b)) > 0.0;
    vec3 sum = vec3(0.0);
    for (int i = range.x; i < range.x + range.y; ++i) {
        // Fields read one by one, as they are needed: a diffuse VPL (the common case) costs three
        // of its six vec4s, which matters to llvmpipe's memory traffic.
        const vec4 pos = vpls[i].positionIndex;
        const vec3 d = pos.xyz - y;
        const float d2 = dot(d, d);
        const vec3 wi = d * inversesqrt(d2);
        const vec4 nx = vpls[i].normalAlpha;
        const float cosY = dot(n, wi), cosX = -dot(nx.xyz, wi);
        if (cosY <= 0.0 || cosX <= 0.0) continue;
        if (visibility != 0) {
            // Normal offset: the low-resolution map's texel spans a range of distances on a
            // surface seen at a grazing angle; looking up from a point lifted off the surface by
            // a texel's footprint (distance times the texel angle, over cos) removes that acne.
            const float dist = sqrt(d2);
            const vec3 lifted = y + n * (dist * texelAngle * min(2.0 / cosY, 8.0));
            const vec3 e = lifted - pos.xyz;
            const float stored = vplShadowDistance(e, int(pos.w));
            if (length(e) * (1.0 - shadowBias) > stored) continue;
        }
        vec3 c = vpls[i].power.rgb * min(cosX * cosY / d2, maxG);
        const vec4 incident = vpls[i].incident;
        if (incident.w != 0.0)
            c *= evalBsdf(nx.xyz, incident.xyz, -wi, vpls[i].albedo.rgb, vpls[i].specular.rgb, nx.w);
        if (glossyY) c *= evalBsdf(n, wo, wi, g2.rgb, g3.rgb, g1.w);
        sum += c;
    }
    if (!glossyY) sum *= g2.rgb * (1.0 / PI);
    const int subsets = pattern.x * pattern.y;
    vec3 area = vec3(0.0);
    for (int i = firstArea + tile.y * pattern.x + tile.x; i < firstArea + areaCount; i += subsets) {
        const Light l = lights[i];
        const vec3 d = l.positionKind.xyz - y;
        const float d2 = dot(d, d);
        const vec3 wi = d * inversesqrt(d2);
        const float cosY = dot(n, wi), cosE = -dot(wi, l.normalShadow.xyz);
        if (cosY <= 0.0 || cosE <= 0.0) continue;
        if (sqrt(d2) * (1.0 - areaShadowBias) > texture(areaShadows, vec4(-wi, l.normalShadow.w)).r) continue;
        area += evalBsdf(n, wo, wi, g2.rgb, g3.rgb, g1.w) * l.intensityCosFalloff.rgb * (cosY * cosE / d2);
    }
    result = vec4(sum + area * float(subsets), 1.0);
}
