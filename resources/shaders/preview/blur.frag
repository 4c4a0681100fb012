#version 450 core
// Gathers the VPL shading pass's split layout back to the image and blurs it horizontally: the
// first half of the separable n x m box blur over continuous regions (the vertical half is in
// direct.frag). Image pixel (x, y) lives in tile (x mod n, y mod m) at (x / n, y / m); each texel
// carries its discontinuity bits in alpha (found by split.frag, passed on by shade_vpl.frag).
// From the centre, walk each way up to the box's reach and stop at the first discontinuity
// (DESIGN.md: blur only across continuous regions), so that every pixel averages one sample of
// each VPL subset where the surface is continuous. boxWidth 1: a plain gather. The output keeps
// the centre's bits for the vertical half.
uniform ivec2 pattern;
uniform ivec2 subSize;
uniform int boxWidth;   // n, or 1
layout(binding = 0) uniform sampler2D splitTex;
layout(location = 0) out vec4 result;

vec4 gathered(ivec2 image) { return texelFetch(splitTex, (image % pattern) * subSize + image / pattern, 0); }

void main() {
    const ivec2 p = ivec2(gl_FragCoord.xy);
    const vec4 centre = gathered(p);
    const int before = (boxWidth - 1) / 2, after = boxWidth - 1 - before;
    vec3 sum = centre.rgb;
    float count = 1.0;
    int bits = int(centre.a);
    for (int i = 1; i <= after && (bits & 1) == 0; ++i) {  // forward: stop where q and q + 1 are apart
        const vec4 q = gathered(p + ivec2(i, 0));
        sum += q.rgb;
        count += 1.0;
        bits = int(q.a);
    }
    for (int i = 1; i <= before && p.x - i >= 0; ++i) {    // backward: the edge is stored on the earlier pixel
        const vec4 q = gathered(p - ivec2(i, 0));
        if ((int(q.a) & 1) != 0) break;
        sum += q.rgb;
        count += 1.0;
    }
    result = vec4(sum / count, centre.a);
}
