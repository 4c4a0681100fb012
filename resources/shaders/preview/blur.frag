#version 450 core
// One direction of the separable n x m box blur over continuous regions: from the centre, walk
// each way up to the box's reach and stop at the first discontinuity (DESIGN.md: blur only
// across continuous regions). The box is n wide horizontally, m tall vertically, so every pixel
// averages one sample of each VPL subset where the surface is continuous.
uniform ivec2 axis;     // (1, 0) or (0, 1)
uniform int boxWidth;   // n or m
layout(binding = 0) uniform sampler2D source;
layout(binding = 1) uniform sampler2D edgesTex;
layout(location = 0) out vec4 result;

int edgeBits(ivec2 p) { return int(texelFetch(edgesTex, p, 0).r); }

void main() {
    const ivec2 p = ivec2(gl_FragCoord.xy);
    const int bit = axis.x == 1 ? 1 : 2;
    const int before = (boxWidth - 1) / 2, after = boxWidth - 1 - before;
    vec3 sum = texelFetch(source, p, 0).rgb;
    float count = 1.0;
    ivec2 q = p;
    for (int i = 0; i < after; ++i) {     // forward: stop where q and q + axis are apart
        if ((edgeBits(q) & bit) != 0) break;
        q += axis;
        sum += texelFetch(source, q, 0).rgb;
        count += 1.0;
    }
    q = p;
    for (int i = 0; i < before; ++i) {    // backward: the edge is stored on the earlier pixel
        const ivec2 r = q - axis;
        if (any(lessThan(r, ivec2(0))) || (edgeBits(r) & bit) != 0) break;
        q = r;
        sum += texelFetch(source, q, 0).rgb;
        count += 1.0;
    }
    result = vec4(sum / count, 1.0);
}
