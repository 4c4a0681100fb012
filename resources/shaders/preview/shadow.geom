#version 450 core
layout(triangles, invocations = 6) in;
layout(triangle_strip, max_vertices = 3) out;
uniform mat4 faceProj[6];  // the cube map faces' view-projections, the light at the origin
in vec3 relative[];
flat in int cube[];
out vec3 fragRelative;
void main() {
    for (int i = 0; i < 3; ++i) {
        gl_Layer = cube[i] * 6 + gl_InvocationID;
        fragRelative = relative[i];
        gl_Position = faceProj[gl_InvocationID] * vec4(relative[i], 1.0);
        EmitVertex();
    }
    EndPrimitive();
}
