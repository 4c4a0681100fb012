#version 450 core
// The discontinuity buffer: bit 0 set when this pixel and its right neighbour lie on different
// surfaces (depth or normal differ too much, or either is not a shaded surface), bit 1 the same
// for the neighbour below. The blur does not cross these edges.
uniform float depthTolerance;   // relative
uniform float normalTolerance;  // minimum cosine between normals
layout(binding = 0) uniform sampler2D g0Tex;
layout(binding = 1) uniform sampler2D g1Tex;
layout(binding = 2) uniform sampler2D g2Tex;
layout(location = 0) out float edges;

bool continuous(ivec2 a, ivec2 b) {
    const ivec2 size = textureSize(g0Tex, 0);
    if (any(greaterThanEqual(b, size))) return false;
    if (texelFetch(g0Tex, a, 0).w != 1.0 || texelFetch(g0Tex, b, 0).w != 1.0) return false;
    const float da = texelFetch(g2Tex, a, 0).w, db = texelFetch(g2Tex, b, 0).w;
    if (abs(da - db) > depthTolerance * min(da, db)) return false;
    return dot(texelFetch(g1Tex, a, 0).xyz, texelFetch(g1Tex, b, 0).xyz) >= normalTolerance;
}

void main() {
    const ivec2 p = ivec2(gl_FragCoord.xy);
    int bits = 0;
    if (!continuous(p, p + ivec2(1, 0))) bits |= 1;
    if (!continuous(p, p + ivec2(0, 1))) bits |= 2;
    edges = float(bits);
}
