#version 330 core
// ColourRampShaderTest: the colour map as the viewer's fragment shader includes it, unlit.

in float vFraction;

out vec4 fragColor;

#include "colour-ramp.glsl"

void main() {
    fragColor = vec4(colourRamp(vFraction), 1.0);
}
