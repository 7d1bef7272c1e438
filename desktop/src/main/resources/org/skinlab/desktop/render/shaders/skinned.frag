#version 330 core
// The material's surface (core's material.glsl) lit by Lambert with a camera-side key light, a
// fill from below and a little specular, plus its emission; in the checker view darkened on every
// other square of a 3-D checker fixed to the rest shape; or a colour map for the weight and
// difference views; or one flat colour (wireframe overlay).

in vec3 vWorld;
in vec3 vNormal;
in vec2 vUv;
in vec4 vColor;
in float vScalar;
in vec3 vRest;

uniform int uViewMode;        // DrawSettings.View's order: 0 shaded, 1 weights, 2 difference, 3 checker
uniform vec3 uEye;
uniform float uScalarFull;    // the scalar shown as the top of the colour map
uniform float uCheckerCell;   // checker view: a square's side, in the rest shape's units
uniform bool uFlat;
uniform vec4 uFlatColor;

out vec4 fragColor;

// The dark squares' share of the light ones' brightness.
const float CHECKER_DARK = 0.45;

// A 3-D checker of unit cells: 1 on light cells, 0 on dark ones, box-filtered over the fragment's
// footprint (the integral of each axis' square wave, Quilez's filtered checkerboard) so that small
// or distant squares fade to grey instead of aliasing. A quarter cell off the origin: faces at a
// model's round coordinates (a cylinder's cap at 0) do not lie on a cell's boundary.
float checker(vec3 p) {
    p += 0.25;
    vec3 w = max(fwidth(p), vec3(1e-4));
    vec3 i = 2.0 * (abs(fract((p - 0.5 * w) * 0.5) - 0.5) - abs(fract((p + 0.5 * w) * 0.5) - 0.5)) / w;
    return 0.5 + 0.5 * i.x * i.y * i.z;
}

#include "colour-ramp.glsl"
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
    vec4 c = colourMap ? vec4(colourRamp(vScalar / uScalarFull), 1.0) : surfaceBase(vUv, vColor);
    if (uViewMode == 3) {
        c.rgb *= mix(CHECKER_DARK, 1.0, checker(vRest / uCheckerCell));
    }
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
    float specular = !colourMap ? pow(max(dot(n, h), 0.0), 32.0) * 0.15 : 0.0;
    vec3 emission = colourMap ? vec3(0.0) : surfaceEmission(vUv);
    fragColor = vec4(base * (ambient + diffuse) + vec3(specular) + emission, c.a);
}
