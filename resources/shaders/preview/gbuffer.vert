#version 450 core
// World-space triangles, not indexed: gl_PrimitiveID finds each triangle's normal and material.
layout(location = 0) in vec3 position;
uniform mat4 viewProj;
out vec3 worldPos;
void main() {
    worldPos = position;
    gl_Position = viewProj * vec4(position, 1.0);
}
