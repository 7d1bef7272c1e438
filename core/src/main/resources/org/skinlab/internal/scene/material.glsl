// A surface's colour from its material (PartMaterial), the same text in the desktop's fragment
// shader (GLSL 330) and the Android app's (GLSL ES 3.00, which declares a float precision before
// the include line), put in by MaterialGlsl.expand for the line
//     #include "material.glsl"
// The includer passes the texture coordinates and the vertex colour (white when the mesh has
// none), lights surfaceBase's colour (unless uUnlit) and adds surfaceEmission.
//
// Texture transforms (KHR_texture_transform, in the model's v-up convention: TextureTransform)
// are mat3s applied to (u, v, 1). Alpha modes (glTF 2.0, 3.9.4 "Alpha coverage"): OPAQUE ignores
// alpha (drawn with alpha 1), MASK drops fragments whose alpha is below the cutoff and draws the
// rest with alpha 1, BLEND keeps alpha for blending.

uniform vec4 uBaseColor;          // factor (RGBA; alpha already limited by the opacity)
uniform bool uHasBaseTexture;
uniform sampler2D uBaseTexture;
uniform mat3 uBaseTransform;
uniform vec3 uEmission;           // added after lighting
uniform bool uHasEmissionTexture;
uniform sampler2D uEmissionTexture;
uniform mat3 uEmissionTransform;
uniform int uAlphaMode;           // MaterialGlsl: 0 OPAQUE, 1 MASK, 2 BLEND
uniform float uAlphaCutoff;
uniform bool uUnlit;

// The base colour of this fragment; discards it when MASK leaves it out.
vec4 surfaceBase(vec2 uv, vec4 vertexColor) {
    vec4 c = uBaseColor * vertexColor;
    if (uHasBaseTexture) {
        c *= texture(uBaseTexture, (uBaseTransform * vec3(uv, 1.0)).xy);
    }
    if (uAlphaMode == 1) {
        if (c.a < uAlphaCutoff) {
            discard;
        }
        c.a = 1.0;
    } else if (uAlphaMode == 0) {
        c.a = 1.0;
    }
    return c;
}

// The emitted colour of this fragment (zero for none).
vec3 surfaceEmission(vec2 uv) {
    vec3 e = uEmission;
    if (uHasEmissionTexture) {
        e *= texture(uEmissionTexture, (uEmissionTransform * vec3(uv, 1.0)).xy).rgb;
    }
    return e;
}
