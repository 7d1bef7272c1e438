uniform vec4 m_BaseColor;
uniform vec3 m_LightDirection;
uniform vec4 m_LightColor;
uniform vec4 m_AmbientColor;

in vec3 wNormal;
out vec4 fragColor;

void main() {
    vec3 n = normalize(wNormal);
    vec3 toLight = -normalize(m_LightDirection);
    // Lambert for the light; a sky-to-ground ambient so that the side away from the light keeps its shape.
    float diffuse = max(dot(n, toLight), 0.0);
    float sky = 0.5 + 0.5 * n.y;
    vec3 light = m_AmbientColor.rgb * mix(0.6, 1.0, sky) + m_LightColor.rgb * diffuse;
    fragColor = vec4(m_BaseColor.rgb * light, m_BaseColor.a);
}
