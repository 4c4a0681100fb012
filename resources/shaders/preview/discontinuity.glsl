// The discontinuity buffer's bits for the box blur (box_blur.glsl), found where the G-buffer is
// read in image layout: bit 0 set when G-buffer texel s and its right neighbour lie on different
// surfaces (depth or normal differ too much, or either is not a shaded surface, or the neighbour
// is off the image), bit 1 the same for the neighbour below. Needs gbuffer.glsl.
const float EDGE_DEPTH_TOLERANCE = 0.05;   // relative
const float EDGE_NORMAL_TOLERANCE = 0.9;   // minimum cosine between normals

// Branch-free (both neighbours are always read, off-image ones clamped and then rejected):
// llvmpipe runs a SIMD vector of fragments through every branch any of them takes, and early
// returns cost it masks; in the shading pass the branching form cost 5 ms
// (docs/benchmarks-history.md, issue 5, "Session 6").
bool continuousWith(sampler2D g0Tex, usampler2D g1Tex, ivec2 size, vec3 eye, vec4 a0, vec3 na, ivec2 b) {
    const ivec2 c = min(b, size - 1);
    const vec4 b0 = texelFetch(g0Tex, c, 0);
    const vec3 nb = decodeNormal(texelFetch(g1Tex, c, 0));
    const float da = distance(a0.xyz, eye), db = distance(b0.xyz, eye);
    return b == c && surfaceKind(b0) == 1 && abs(da - db) <= EDGE_DEPTH_TOLERANCE * min(da, db) &&
           dot(na, nb) >= EDGE_NORMAL_TOLERANCE;
}

// g0 and n: texel s's own position/kind and normal, already read.
uint edgeBits(sampler2D g0Tex, usampler2D g1Tex, ivec2 size, vec3 eye, ivec2 s, vec4 g0, vec3 n) {
    const bool surface = surfaceKind(g0) == 1;
    const bool right = continuousWith(g0Tex, g1Tex, size, eye, g0, n, s + ivec2(1, 0));
    const bool below = continuousWith(g0Tex, g1Tex, size, eye, g0, n, s + ivec2(0, 1));
    return (surface && right ? 0u : 1u) + (surface && below ? 0u : 2u);
}
