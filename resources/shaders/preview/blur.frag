#version 450 core
// Gathers the VPL shading pass's split layout back to the image and blurs it horizontally: the
// first half of the box blur over continuous regions (box_blur.glsl; the vertical half is in
// direct.frag). The discontinuity bits ride in alpha (found by split.frag, passed on by
// shade_vpl.frag) and the output keeps the centre's for the vertical half, with how far the walk
// went back and forward (8 bits each, from bit 2 and bit 10) for the direct pass's block lights
// (light_blocks.glsl). boxWidth 1: a plain gather.
#include_box_blur
uniform ivec2 pattern;
uniform ivec2 subSize;
uniform int boxWidth;   // n, or 1
uniform int boxFlip;    // box_blur.glsl
layout(binding = 0) uniform sampler2D splitTex;
layout(location = 0) out vec4 result;

void main() {
    int back, forward;
    result = boxBlurWalk(splitTex, ivec2(gl_FragCoord.xy), ivec2(1, 0), boxWidth, pattern, subSize, boxFlip != 0, back,
                         forward);
    result.a = float((int(result.a) & 3) + 4 * back + 1024 * forward);
}
