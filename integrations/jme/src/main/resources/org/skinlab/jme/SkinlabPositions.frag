in vec3 worldPosition;
out vec4 fragColor;

void main() {
    fragColor = vec4(worldPosition, 1.0);
}
