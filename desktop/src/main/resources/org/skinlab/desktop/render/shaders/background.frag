#version 330 core
// The camera image as the ideal pinhole image the model is projected into (lens.glsl): each
// fragment samples the camera's frame where the lens put its ray; beyond the frame, black.
uniform sampler2D uImage;   // the camera's colour, 8-bit RGB
uniform vec2 uSize;         // the camera image in pixels
uniform vec4 uPinhole;      // fx, fy, cx, cy
uniform vec3 uRadial;       // k1, k2, k3
uniform vec2 uTangential;   // p1, p2
in vec2 vUv;
out vec4 color;

#include "lens.glsl"

void main() {
    vec2 st = lensSourceCoord(vUv, uSize, uPinhole, uRadial, uTangential);
    if (any(lessThan(st, vec2(0.0))) || any(greaterThan(st, vec2(1.0)))) {
        color = vec4(0.0, 0.0, 0.0, 1.0);
        return;
    }
    color = vec4(texture(uImage, st).rgb, 1.0);
}
