#version 450 core
// Interleaved sampling, the G-buffer split (DESIGN.md). The split layout is n x m tiles of
// subSize each; texel (x, y) of the G-buffer goes to tile (x mod n, y mod m) at (x / n, y / m).
// MODE 0: in one pass, each output texel fetches its source directly (incoherent reads).
// MODE 1: first of two passes: within blocks of (n B) x (m B) texels, gather the block's texels
//         into n x m sub-blocks of B x B (reads stay inside one small block: cache friendly).
// MODE 2: second pass: translate the B x B sub-blocks to their tiles (a coherent block copy).
// Every output is one texelFetch per attachment (gbuffer.glsl: two); texels outside the source
// read as zero (kind 0, nothing).
// The third output is the discontinuity buffer (discontinuity.glsl), found where the G-buffer is
// read in image layout (MODE 0 and 1: the neighbours are next to the source texel, in cache) and
// moved along with it in MODE 2.
#include_gbuffer
#include_discontinuity
uniform int mode;
uniform ivec2 pattern;   // n, m
uniform ivec2 subSize;   // a tile's size, a multiple of B in both directions
uniform int blockSize;   // B
uniform ivec2 sourceSize;
uniform int findEdges;          // 0: the third output is 0
uniform vec3 cameraPos;
layout(binding = 0) uniform sampler2D in0;
layout(binding = 1) uniform usampler2D in1;
layout(binding = 2) uniform usampler2D in2;  // MODE 2: the intermediate's discontinuity buffer
layout(location = 0) out vec4 out0;
layout(location = 1) out uvec4 out1;
layout(location = 2) out uint out2;

ivec2 sourceOf(ivec2 p) {
    if (mode == 0) {
        const ivec2 tile = p / subSize, q = p % subSize;
        return q * pattern + tile;
    }
    const ivec2 B = ivec2(blockSize);
    if (mode == 1) {
        const ivec2 blockDim = pattern * B;
        const ivec2 block = p / blockDim, l = p % blockDim;
        const ivec2 sub = l / B, q = l % B;
        return block * blockDim + q * pattern + sub;
    }
    // mode 2: p lies in tile `tile`, at q; its sub-block is q / B inside the intermediate block.
    const ivec2 tile = p / subSize, q = p % subSize;
    return (q / B) * (pattern * B) + tile * B + q % B;
}

void main() {
    const ivec2 s = sourceOf(ivec2(gl_FragCoord.xy));
    if (any(greaterThanEqual(s, sourceSize))) {
        out0 = vec4(0.0);
        out1 = uvec4(0u);
        out2 = 3u;
        return;
    }
    out0 = texelFetch(in0, s, 0);
    out1 = texelFetch(in1, s, 0);
    if (mode == 2)
        out2 = texelFetch(in2, s, 0).r;
    else
        out2 = findEdges != 0 ? edgeBits(in0, in1, sourceSize, cameraPos, s, out0, decodeNormal(out1)) : 0u;
}
