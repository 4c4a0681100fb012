#version 450 core
// Depth only: the depth attachment is the shadow map.
void main() {}
