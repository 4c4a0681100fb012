#version 450 core
// Gathers the split layout back: pixel (x, y) lives in tile (x mod n, y mod m) at (x / n, y / m).
uniform ivec2 pattern;
uniform ivec2 subSize;
layout(binding = 0) uniform sampler2D splitTex;
layout(location = 0) out vec4 result;
void main() {
    const ivec2 p = ivec2(gl_FragCoord.xy);
    result = texelFetch(splitTex, (p % pattern) * subSize + p / pattern, 0);
}
