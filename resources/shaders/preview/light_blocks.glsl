// The delta lights each block of the image shades in full (render/preview/light_blocks.h):
// block b's are blockLights[b * lightsPerBlock ..] (indices into the lights from firstBlockLight;
// -1: none). Blocks are lightBlockSize pixels of the image, the grid shifted by lightBlockOffset.
//
// Every delta light is also dealt to the sub-buffers (or a random subset of them is), and the blur
// averaged its dealt share into the indirect light. A block's own lights are shaded in full here,
// so their dealt share comes back out: light j, dealt as light firstDealt + dealtAt[j], lit one
// sub-buffer, that is one pixel q of p's blur box, and entered p's blurred value as
// subsets L_j(q) / (rows x the columns of q's row) (box_blur.glsl's walk, blur.frag's bits). The
// same evaluation at q subtracted leaves exactly the other lights' share: no light is counted
// twice, and the blur runs across the blocks' edges as before.
layout(std430, binding = 6) readonly buffer BlockLights { int blockLights[]; };
layout(std430, binding = 4) readonly buffer DealtAt { int dealtAt[]; };
uniform int lightBlockSize;
uniform ivec2 lightBlockOffset;
uniform int lightBlocksX;
uniform int lightsPerBlock;
uniform int firstBlockLight;
uniform int firstDealt;
uniform ivec2 dealPattern;  // n, m

int lightBlockOf(ivec2 imagePixel) {
    const ivec2 b = (imagePixel + lightBlockOffset) / lightBlockSize;
    return b.y * lightBlocksX + b.x;
}

// The first coordinate in [from, to] whose residue modulo n is r, or to + 1.
int firstWithResidue(int from, int to, int n, int r) {
    const int v = from + ((r - from % n) % n + n) % n;
    return v <= to ? v : to + 1;
}

// Dealt light `dealt`'s share in the blurred indirect light at p, whose vertical walk went `up`
// rows up and `down` down; `horizontal` holds blur.frag's output (each row's walk in alpha).
vec3 dealtShareInBlur(int dealt, ivec2 p, int up, int down, sampler2D horizontal, sampler2D g0Tex, usampler2D g1Tex,
                      vec3 eye) {
    const int subsets = dealPattern.x * dealPattern.y, k = dealt % subsets;
    const int y = firstWithResidue(p.y - up, p.y + down, dealPattern.y, k / dealPattern.x);
    if (y > p.y + down) return vec3(0.0);
    const int walk = int(texelFetch(horizontal, ivec2(p.x, y), 0).a);
    const int left = (walk >> 2) & 255, right = (walk >> 10) & 255;
    const int x = firstWithResidue(p.x - left, p.x + right, dealPattern.x, k % dealPattern.x);
    if (x > p.x + right) return vec3(0.0);
    const ivec2 q = ivec2(x, y);
    const vec4 g0 = texelFetch(g0Tex, q, 0);
    if (surfaceKind(g0) != 1) return vec3(0.0);
    const Surface sq = decodeSurface(g0, texelFetch(g1Tex, q, 0));
    const float columns = float(left + right + 1), rows = float(up + down + 1);
    return lightContribution(firstDealt + dealt, sq, normalize(eye - sq.position)) * (float(subsets) / (rows * columns));
}
