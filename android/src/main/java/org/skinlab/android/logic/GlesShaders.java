package org.skinlab.android.logic;

/**
 * The AR app's OpenGL ES 3.00 shaders: the camera image (an external OES texture) as background,
 * and the model skinned in the vertex shader by LBS, DQS or CoR from the palette texture of
 * {@link PaletteTexture} (the desktop's {@code skinned.vert} formulas, with a 2-D float texture
 * instead of texture buffers, which ES 3.0 lacks; 4 influences per vertex).
 */
public final class GlesShaders {
    private GlesShaders() {
    }

    public static final String BACKGROUND_VERTEX = """
            #version 300 es
            layout(location = 0) in vec2 aCorner;   // corner of the sensor's image, in its NDC (y up)
            uniform mat4 uImageToViewport;          // ArCamera.imageToViewport
            uniform mat4 uSensorToNatural;          // PreviewOrientation.sensorToNatural
            uniform mat4 uTexture;                  // SurfaceTexture's transform
            out vec2 vUv;
            void main() {
                vec2 uv = aCorner * 0.5 + 0.5;
                vUv = (uTexture * uSensorToNatural * vec4(uv, 0.0, 1.0)).xy;
                gl_Position = uImageToViewport * vec4(aCorner, 0.0, 1.0);
            }
            """;

    public static final String BACKGROUND_FRAGMENT = """
            #version 300 es
            #extension GL_OES_EGL_image_external_essl3 : require
            precision mediump float;
            uniform samplerExternalOES uCamera;
            in vec2 vUv;
            out vec4 color;
            void main() {
                color = texture(uCamera, vUv);
            }
            """;

    public static final String SKINNED_VERTEX = """
            #version 300 es
            precision highp float;
            precision highp int;
            layout(location = 0) in vec3 aPosition;
            layout(location = 1) in vec3 aNormal;
            layout(location = 2) in uvec4 aJoints;
            layout(location = 3) in vec4 aWeights;
            layout(location = 4) in vec3 aCentre;
            uniform highp sampler2D uPalette;   // 8 texels per joint row (PaletteTexture)
            uniform int uMethod;                // 1 LBS, 2 DQS, 3 CoR
            uniform bool uHasScale;
            uniform mat4 uModelView;
            uniform mat4 uProjection;
            out vec3 vNormal;
            out vec3 vEye;
            vec4 texel(uint joint, int k) { return texelFetch(uPalette, ivec2(k, int(joint)), 0); }
            void blendRows(int first, out vec4 r0, out vec4 r1, out vec4 r2) {
                r0 = vec4(0.0); r1 = vec4(0.0); r2 = vec4(0.0);
                for (int i = 0; i < 4; i++) {
                    float w = aWeights[i];
                    uint j = aJoints[i];
                    r0 += w * texel(j, first); r1 += w * texel(j, first + 1); r2 += w * texel(j, first + 2);
                }
            }
            vec3 applyRows(vec4 r0, vec4 r1, vec4 r2, vec3 p) {
                vec4 h = vec4(p, 1.0);
                return vec3(dot(r0, h), dot(r1, h), dot(r2, h));
            }
            vec3 cofactorTimes(vec4 r0, vec4 r1, vec4 r2, vec3 n) {
                return vec3(dot(cross(r1.xyz, r2.xyz), n), dot(cross(r2.xyz, r0.xyz), n), dot(cross(r0.xyz, r1.xyz), n));
            }
            vec3 rotate(vec4 q, vec3 v) { return v + 2.0 * cross(q.xyz, cross(q.xyz, v) + q.w * v); }
            void main() {
                vec3 p = aPosition;
                vec3 n = aNormal;
                vec3 c = aCentre;
                vec3 outP;
                vec3 outN;
                if (uMethod == 1) {
                    vec4 r0, r1, r2;
                    blendRows(0, r0, r1, r2);
                    outP = applyRows(r0, r1, r2, p);
                    outN = cofactorTimes(r0, r1, r2, n);
                } else {
                    if (uHasScale) {
                        vec4 s0, s1, s2;
                        blendRows(5, s0, s1, s2);
                        n = cofactorTimes(s0, s1, s2, n);
                        p = applyRows(s0, s1, s2, p);
                        c = applyRows(s0, s1, s2, c);
                    }
                    vec4 pivot = texel(aJoints.x, 3);
                    vec4 br = vec4(0.0);
                    vec4 bd = vec4(0.0);
                    vec3 t = vec3(0.0);
                    for (int i = 0; i < 4; i++) {
                        uint j = aJoints[i];
                        vec4 r = texel(j, 3);
                        vec4 d = texel(j, 4);
                        float w = dot(pivot, r) < 0.0 ? -aWeights[i] : aWeights[i];
                        br += w * r;
                        bd += w * d;
                        t += aWeights[i] * (rotate(r, c) + 2.0 * (r.w * d.xyz - d.w * r.xyz + cross(r.xyz, d.xyz)));
                    }
                    float len = length(br);
                    br /= len;
                    bd /= len;
                    if (uMethod == 2) {
                        outP = rotate(br, p) + 2.0 * (br.w * bd.xyz - bd.w * br.xyz + cross(br.xyz, bd.xyz));
                    } else {
                        // CoR: the rotation blended as in DQS, the translation LBS's of the rigid parts at c.
                        outP = rotate(br, p - c) + t;
                    }
                    outN = rotate(br, n);
                }
                vec4 eye = uModelView * vec4(outP, 1.0);
                vEye = eye.xyz;
                vNormal = mat3(uModelView) * outN;
                gl_Position = uProjection * eye;
            }
            """;

    public static final String SKINNED_FRAGMENT = """
            #version 300 es
            precision mediump float;
            uniform vec4 uColor;
            in vec3 vNormal;
            in vec3 vEye;
            out vec4 color;
            void main() {
                vec3 n = normalize(vNormal);
                if (dot(n, vEye) > 0.0) n = -n;       // two-sided
                vec3 l = normalize(vec3(0.3, 0.8, 0.6));
                float diffuse = max(dot(n, l), 0.0);
                color = vec4(uColor.rgb * (0.35 + 0.65 * diffuse), uColor.a);
            }
            """;
}
