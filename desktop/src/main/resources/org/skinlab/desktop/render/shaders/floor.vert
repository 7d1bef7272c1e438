#version 330 core
// The floor grid: lines on y = 0 around the model, fading towards the rim.
layout(location = 0) in vec2 aPosition;   // x, z in units of the grid's half extent (-1..1)

uniform mat4 uViewProjection;
uniform float uExtent;
uniform vec3 uCentre;

out vec2 vGrid;

void main() {
    vGrid = aPosition;
    gl_Position = uViewProjection * vec4(uCentre.x + aPosition.x * uExtent, 0.0, uCentre.z + aPosition.y * uExtent, 1.0);
}
