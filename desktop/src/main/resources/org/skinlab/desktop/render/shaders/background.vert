#version 330 core
// The camera image across the view (skinlab ar): a quad whose corners are the image's, in the
// normalised device coordinates of the unturned image, moved by ArCamera.imageToViewport.
layout(location = 0) in vec2 aCorner;
uniform mat4 uImageToViewport;
out vec2 vUv;

void main() {
    // Image rows are uploaded top first, so GL's t = 0 is the image's top row (ndc y = +1).
    vUv = vec2(aCorner.x * 0.5 + 0.5, 0.5 - aCorner.y * 0.5);
    gl_Position = uImageToViewport * vec4(aCorner, 0.999, 1.0);
}
