// The G-buffer's encoding, two attachments (32 bytes a texel: on llvmpipe every pass that reads
// or moves the G-buffer costs by the attachment; docs/benchmarks-history.md, issue 5,
// "Session 5"):
//   g0 (RGBA32F): position, and w = kind + alpha / 2, kind 0 nothing, 1 diffuse or glossy (alpha
//        its GGX alpha, in [0, 1]), 2 an emitter's front face, 3 mirror or glass (black in the
//        preview);
//   g1 (RGBA32UI): kind 1: x = the normal turned toward the camera (octahedral, 2 x snorm16),
//        y, z, w = albedo and specular reflectance (6 x unorm16: both are fractions);
//        kind 2: xyz = the emitter's radiance as float bits (exact, any magnitude).
// The albedo layer (frame_passes.cpp) decodes g1 the same way on the CPU.

struct Surface { vec3 position; vec3 normal; vec3 albedo; vec3 specular; float alpha; };

int surfaceKind(vec4 g0) { return int(g0.w); }

vec2 octEncode(vec3 n) {
    const vec2 p = n.xy / (abs(n.x) + abs(n.y) + abs(n.z));
    return n.z >= 0.0 ? p : (1.0 - abs(p.yx)) * vec2(p.x >= 0.0 ? 1.0 : -1.0, p.y >= 0.0 ? 1.0 : -1.0);
}

vec3 octDecode(vec2 e) {
    vec3 n = vec3(e, 1.0 - abs(e.x) - abs(e.y));
    const float t = max(-n.z, 0.0);
    n.x += n.x >= 0.0 ? -t : t;
    n.y += n.y >= 0.0 ? -t : t;
    return normalize(n);
}

vec3 decodeNormal(uvec4 g1) { return octDecode(unpackSnorm2x16(g1.x)); }

Surface decodeSurface(vec4 g0, uvec4 g1) {
    Surface s;
    s.position = g0.xyz;
    s.alpha = (g0.w - 1.0) * 2.0;
    s.normal = decodeNormal(g1);
    const vec2 a = unpackUnorm2x16(g1.y), b = unpackUnorm2x16(g1.z), c = unpackUnorm2x16(g1.w);
    s.albedo = vec3(a, b.x);
    s.specular = vec3(b.y, c);
    return s;
}

vec3 emitterRadiance(uvec4 g1) { return uintBitsToFloat(g1.xyz); }
