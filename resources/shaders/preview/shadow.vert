#version 450 core
// Cube shadow maps for many lights at once: instance i renders light i's six faces (the
// geometry shader picks the layer), positions relative to the light.
layout(location = 0) in vec3 position;
layout(std430, binding = 0) readonly buffer Centres { vec4 centres[]; };  // xyz, layer base (cube index)
out vec3 relative;
flat out int cube;
void main() {
    const vec4 c = centres[gl_InstanceID];
    relative = position - c.xyz;
    cube = int(c.w);
}
