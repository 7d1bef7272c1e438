#version 330 core
uniform sampler2D uImage;   // one 8-bit channel: the camera's luminance
in vec2 vUv;
out vec4 color;

void main() {
    float v = texture(uImage, vUv).r;
    color = vec4(v, v, v, 1.0);
}
