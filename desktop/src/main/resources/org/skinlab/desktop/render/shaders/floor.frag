#version 330 core
in vec2 vGrid;
uniform vec4 uColor;
out vec4 fragColor;

void main() {
    // Per fragment: a line's ends both lie on the rim, so a per-vertex fade would be 0 all along.
    float fade = 1.0 - clamp(length(vGrid), 0.0, 1.0);
    fragColor = vec4(uColor.rgb, uColor.a * fade);
}
