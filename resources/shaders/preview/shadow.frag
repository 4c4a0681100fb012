#version 450 core
// Stores the distance to the light: lookups compare distances, independent of the face.
// A proxy of the scene (render/preview/shadow_proxy.h) lies within a cell of the true surfaces,
// often just in front of the very surface a VPL sits on: surfaces nearer the centre than that
// are left out, or the VPL would be shadowed by its own surface.
in vec3 fragRelative;
uniform float nearSkip;  // scene units: the proxy's cell, 0 for the scene itself
layout(location = 0) out float distance;
void main() {
    const float d = length(fragRelative);
    if (d < nearSkip) discard;
    distance = d;
}
