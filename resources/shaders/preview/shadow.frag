#version 450 core
// Stores the distance to the light: lookups compare distances, independent of the face.
in vec3 fragRelative;
layout(location = 0) out float distance;
void main() { distance = length(fragRelative); }
