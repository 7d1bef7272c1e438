#version 330 core
// ColourRampShaderTest: the viewport covered by one strip of two triangles made from gl_VertexID
// (no buffers), each column's fraction of the colour map running from uFrom (left) to uTo (right).

uniform float uFrom;
uniform float uTo;

out float vFraction;

void main() {
    vec2 corner = vec2(float(gl_VertexID & 1), float(gl_VertexID >> 1));
    vFraction = mix(uFrom, uTo, corner.x);
    gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
