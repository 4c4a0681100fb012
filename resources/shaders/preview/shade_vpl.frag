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
layout(binding = 0) uniform sampler2D g0Tex;
layout(binding = 1) uniform sampler2D g1Tex;
layout(binding = 2) uniform sampler2D g2Tex;
layout(binding = 3) uniform sampler2D g3Tex;
layout(binding = 4) uniform samplerCubeArray vplShadows;
layout(location = 0) out vec4 result;

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
        const Vpl v = vpls[i];
        const vec3 d = v.positionIndex.xyz - y;
        const float d2 = dot(d, d);
        const vec3 wi = d * inversesqrt(d2);
        const float cosY = dot(n, wi), cosX = -dot(v.normalAlpha.xyz, wi);
        if (cosY <= 0.0 || cosX <= 0.0) continue;
        if (visibility != 0) {
            const float stored = texture(vplShadows, vec4(-wi, v.positionIndex.w)).r;
            if (sqrt(d2) * (1.0 - shadowBias) > stored) continue;
        }
        vec3 c = v.power.rgb * min(cosX * cosY / d2, maxG);
        if (v.incident.w != 0.0)
            c *= evalBsdf(v.normalAlpha.xyz, v.incident.xyz, -wi, v.albedo.rgb, v.specular.rgb, v.normalAlpha.w);
        if (glossyY) c *= evalBsdf(n, wo, wi, g2.rgb, g3.rgb, g1.w);
        sum += c;
    }
    if (!glossyY) sum *= g2.rgb * (1.0 / PI);
    result = vec4(sum, 1.0);
}
