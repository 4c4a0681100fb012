#version 450 core
// The box of what each block of the image sees (render/preview/light_blocks.h), a texel a block:
// the lowest position of its shaded surfaces with their count in alpha, and the highest.
#include_gbuffer
uniform int lightBlockSize;     // pixels
uniform ivec2 lightBlockOffset; // block b covers pixels b * size - offset .. + size
layout(binding = 0) uniform sampler2D g0Tex;
layout(location = 0) out vec4 lowest;
layout(location = 1) out vec4 highest;

void main() {
    const ivec2 origin = ivec2(gl_FragCoord.xy) * lightBlockSize - lightBlockOffset;
    const ivec2 size = textureSize(g0Tex, 0);
    vec3 lo = vec3(3.0e38), hi = vec3(-3.0e38);
    float seen = 0.0;
    for (int y = max(origin.y, 0); y < min(origin.y + lightBlockSize, size.y); ++y)
        for (int x = max(origin.x, 0); x < min(origin.x + lightBlockSize, size.x); ++x) {
            const vec4 g0 = texelFetch(g0Tex, ivec2(x, y), 0);
            if (surfaceKind(g0) != 1) continue;
            lo = min(lo, g0.xyz);
            hi = max(hi, g0.xyz);
            seen += 1.0;
        }
    lowest = vec4(lo, seen);
    highest = vec4(hi, 0.0);
}
