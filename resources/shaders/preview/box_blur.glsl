// One direction of the separable n x m box blur over continuous regions (DESIGN.md: blur only
// across continuous regions): blur.frag runs it horizontally while gathering, direct.frag
// vertically. `tex` holds light in rgb and the discontinuity bits in alpha (split.frag: bit 0
// set where a pixel and its right neighbour lie on different surfaces or the neighbour is off the
// image, bit 1 the same for the one below), in the split layout of pattern tiles of subSize each:
// image pixel (x, y) in tile (x mod n, y mod m) at (x / n, y / m); pattern 1 x 1 is the image
// layout. From the centre, walk each way up to the box's reach and stop at the first
// discontinuity, so that every pixel averages one sample of each VPL subset where the surface is
// continuous; box 1: the centre alone. Returns the mean and the centre's bits.

vec4 boxTexel(sampler2D tex, ivec2 image, ivec2 pattern, ivec2 subSize) {
    return texelFetch(tex, (image % pattern) * subSize + image / pattern, 0);
}

// The same, with how far the walk went each way (back: toward lower coordinates), which the
// direct pass needs to take a light's dealt share back out of the blur (light_blocks.glsl).
vec4 boxBlurWalk(sampler2D tex, ivec2 p, ivec2 axis, int box, ivec2 pattern, ivec2 subSize, bool flip, out int back,
                 out int forward) {
    const int bit = axis.x != 0 ? 1 : 2;
    const vec4 centre = boxTexel(tex, p, pattern, subSize);
    const int before = flip ? box / 2 : (box - 1) / 2, after = box - 1 - before;
    vec3 sum = centre.rgb;
    float count = 1.0;
    int bits = int(centre.a);
    forward = 0;
    back = 0;
    // Forward: stop where q and the next pixel are apart (the image's last pixel always is).
    for (int i = 1; i <= after && (bits & bit) == 0; ++i) {
        const vec4 q = boxTexel(tex, p + i * axis, pattern, subSize);
        sum += q.rgb;
        count += 1.0;
        bits = int(q.a);
        forward = i;
    }
    // Backward: the edge is stored on the earlier pixel.
    for (int i = 1; i <= before && all(greaterThanEqual(p - i * axis, ivec2(0))); ++i) {
        const vec4 q = boxTexel(tex, p - i * axis, pattern, subSize);
        if ((int(q.a) & bit) != 0) break;
        sum += q.rgb;
        count += 1.0;
        back = i;
    }
    return vec4(sum / count, centre.a);
}

vec4 boxBlur(sampler2D tex, ivec2 p, ivec2 axis, int box, ivec2 pattern, ivec2 subSize, bool flip) {
    int back, forward;
    return boxBlurWalk(tex, p, axis, box, pattern, subSize, flip, back, forward);
}
