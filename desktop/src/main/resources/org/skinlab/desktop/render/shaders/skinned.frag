#version 330 core
// The material's surface (core's material.glsl) lit by Lambert with a camera-side key light, a
// fill from below and a little specular, plus its emission; or a colour map for the weight and
// difference views; or one flat colour (wireframe overlay).

in vec3 vWorld;
in vec3 vNormal;
in vec2 vUv;
in vec4 vColor;
in float vScalar;

uniform int uViewMode;        // 0 shaded, 1 weights, 2 difference
uniform vec3 uEye;
uniform float uScalarFull;    // the scalar shown as the top of the colour map
uniform bool uFlat;
uniform vec4 uFlatColor;

out vec4 fragColor;

// Blue, cyan, green, yellow, red: readable without a legend's fine print.
vec3 ramp(float x) {
    x = clamp(x, 0.0, 1.0);
    vec3 c0 = vec3(0.10, 0.20, 0.75);
    vec3 c1 = vec3(0.10, 0.75, 0.85);
    vec3 c2 = vec3(0.20, 0.80, 0.20);
    vec3 c3 = vec3(0.95, 0.85, 0.15);
    vec3 c4 = vec3(0.90, 0.15, 0.10);
    float s = x * 4.0;
    if (s < 1.0) return mix(c0, c1, s);
    if (s < 2.0) return mix(c1, c2, s - 1.0);
    if (s < 3.0) return mix(c2, c3, s - 2.0);
    return mix(c3, c4, s - 3.0);
}

#include "material.glsl"

void main() {
    if (uFlat) {
        fragColor = uFlatColor;
        return;
    }
    vec3 v = normalize(uEye - vWorld);
    vec3 n = vNormal;
    if (dot(n, n) < 1e-12) {
        // A mesh without normals: the face normal from the screen-space derivatives.
        n = cross(dFdx(vWorld), dFdy(vWorld));
    }
    n = normalize(n);
    // Lit from the side that faces the camera, whatever the file's winding.
    if (dot(n, v) < 0.0) {
        n = -n;
    }
    bool colourMap = uViewMode == 1 || uViewMode == 2;
    vec4 c = colourMap ? vec4(ramp(vScalar / uScalarFull), 1.0) : surfaceBase(vUv, vColor);
    if (!colourMap && uUnlit) {
        fragColor = c;
        return;
    }
    vec3 base = c.rgb;
    vec3 key = normalize(v + vec3(0.3, 0.6, 0.2));
    vec3 fill = normalize(vec3(-0.4, -0.5, -0.3));
    float diffuse = max(dot(n, key), 0.0) * 0.75 + max(dot(n, fill), 0.0) * 0.15;
    float ambient = 0.25 + 0.1 * n.y;
    vec3 h = normalize(key + v);
    float specular = uViewMode == 0 ? pow(max(dot(n, h), 0.0), 32.0) * 0.15 : 0.0;
    vec3 emission = colourMap ? vec3(0.0) : surfaceEmission(vUv);
    fragColor = vec4(base * (ambient + diffuse) + vec3(specular) + emission, c.a);
}
