#version 450 core
// A directional light's shadow map: an orthographic depth map over the scene's bounding sphere,
// one draw per directional light (there are few), into its own layer.
layout(location = 0) in vec3 position;
uniform mat4 lightViewProj;
void main() { gl_Position = lightViewProj * vec4(position, 1.0); }
