package org.skinlab.android.logic;

import org.skinlab.ar.LensGlsl;
import org.skinlab.internal.scene.MaterialGlsl;
import org.skinlab.skinning.PaletteTexels;
import org.skinlab.skinning.SkinningGlsl;

/**
 * The AR app's OpenGL ES 3.00 shaders: the camera image (an external OES texture) as background,
 * undistorted through the camera's lens ({@link #backgroundFragment()}), and the model skinned in the vertex shader by the methods with shader code ({@link SkinningGlsl#hasCode}) from the palette texture of
 * {@link PaletteTexture}, with the formulas the desktop's shader shares ({@link SkinningGlsl}: a 2-D
 * float texture instead of the desktop's texture buffers, which ES 3.0 lacks; {@value #INFLUENCES}
 * influences per vertex). The skinned model's vertex attributes sit at the locations below
 * (what the app's buffers and the tests bind).
 */
public final class GlesShaders {
    /** Vertex attribute locations of {@link #skinnedVertex()}: bind-space position and normal (3 floats each). */
    public static final int POSITION = 0;
    public static final int NORMAL = 1;
    /** {@value #INFLUENCES} joint indices per vertex, unsigned 16-bit integers ({@code glVertexAttribIPointer}). */
    public static final int JOINTS = 2;
    /** {@value #INFLUENCES} weights per vertex, floats. */
    public static final int WEIGHTS = 3;
    /** CoR's centre of rotation per vertex, 3 floats ({@code SkinnedGeometry.centresOfRotation()}). */
    public static final int CENTRE = 4;
    /** The texture coordinates the materials sample by (2 floats; the model's v-up convention). */
    public static final int UV = 5;
    /** The vertex colour, RGBA floats (a constant white when the mesh has none). */
    public static final int COLOR = 6;
    /** Texture units: the palette (ModelGl), the material's base and emission textures. */
    public static final int PALETTE_UNIT = 1;
    public static final int BASE_TEXTURE_UNIT = 0;
    public static final int EMISSION_TEXTURE_UNIT = 2;
    /** Influences per vertex the shader reads: the app skins an {@code InfluenceView} of this many. */
    public static final int INFLUENCES = 4;

    private GlesShaders() {
    }

    /**
     * The camera background's vertex shader: the sensor's image across the viewport
     * ({@code ArCamera.imageToViewport}); the fragment shader finds what to sample.
     */
    public static final String BACKGROUND_VERTEX = """
            #version 300 es
            layout(location = 0) in vec2 aCorner;   // corner of the sensor's image, in its NDC (y up)
            uniform mat4 uImageToViewport;          // ArCamera.imageToViewport
            out vec2 vSensor;                       // where in the sensor's image: 0..1, y up
            void main() {
                vSensor = aCorner * 0.5 + 0.5;
                gl_Position = uImageToViewport * vec4(aCorner, 0.0, 1.0);
            }
            """;

    private static final String BACKGROUND_FRAGMENT = """
            #version 300 es
            #extension GL_OES_EGL_image_external_essl3 : require
            precision highp float;                  // pixel coordinates: mediump's 11 bits are too few
            uniform samplerExternalOES uCamera;
            uniform mat4 uSensorToNatural;          // PreviewOrientation.sensorToNatural
            uniform mat4 uTexture;                  // SurfaceTexture's transform
            uniform vec2 uSize;                     // LensGlsl.uniforms: the sensor image's size,
            uniform vec4 uPinhole;                  // fx, fy, cx, cy,
            uniform vec3 uRadial;                   // k1, k2, k3,
            uniform vec2 uTangential;               // p1, p2
            in vec2 vSensor;
            out vec4 color;

            #include "lens.glsl"

            void main() {
                // lens.glsl counts rows from the image's top; the sensor's NDC has y up.
                vec2 st = lensSourceCoord(vec2(vSensor.x, 1.0 - vSensor.y), uSize, uPinhole, uRadial, uTangential);
                if (any(lessThan(st, vec2(0.0))) || any(greaterThan(st, vec2(1.0)))) {
                    color = vec4(0.0, 0.0, 0.0, 1.0);
                    return;
                }
                vec2 uv = (uTexture * uSensorToNatural * vec4(st.x, 1.0 - st.y, 0.0, 1.0)).xy;
                color = texture(uCamera, uv);
            }
            """;

    /**
     * The camera background's fragment shader: the ideal pinhole image the model is projected into,
     * each fragment sampling the camera's external texture where the lens put its ray (core's
     * {@code lens.glsl}, {@link LensGlsl}, shared with the desktop), black beyond the image.
     *
     * @throws IllegalStateException when the formulas cannot be read (an APK without them)
     */
    public static String backgroundFragment() {
        return LensGlsl.expand(BACKGROUND_FRAGMENT);
    }

    /**
     * The skinned model's vertex shader: this app's header and main around the formulas both apps
     * share ({@link SkinningGlsl}), read from core's resource on each call (once per GL context).
     *
     * @throws IllegalStateException when the formulas cannot be read (an APK without them)
     */
    public static String skinnedVertex() {
        return SkinningGlsl.expand(SKINNED_VERTEX_HEADER + SKINNED_VERTEX_BODY);
    }

    /** The numbers the Java side and the shader must agree on, as GLSL macros. */
    private static final String SKINNED_VERTEX_HEADER = "#version 300 es\n"
            + "#define POSITION_LOCATION " + POSITION + "\n"
            + "#define NORMAL_LOCATION " + NORMAL + "\n"
            + "#define JOINTS_LOCATION " + JOINTS + "\n"
            + "#define WEIGHTS_LOCATION " + WEIGHTS + "\n"
            + "#define CENTRE_LOCATION " + CENTRE + "\n"
            + "#define UV_LOCATION " + UV + "\n"
            + "#define COLOR_LOCATION " + COLOR + "\n"
            + "#define INFLUENCES " + INFLUENCES + "\n"
            + "#define MATRIX_TEXEL " + PaletteTexels.MATRIX_TEXEL + "\n"
            + "#define ROTATION_TEXEL " + PaletteTexels.ROTATION_TEXEL + "\n"
            + "#define SCALE_TEXEL " + PaletteTexels.SCALE_TEXEL + "\n"
            + "#define BONE_TEXEL " + PaletteTexels.BONE_TEXEL + "\n";

    private static final String SKINNED_VERTEX_BODY = """
            precision highp float;
            precision highp int;
            layout(location = POSITION_LOCATION) in vec3 aPosition;   // bind space
            layout(location = NORMAL_LOCATION) in vec3 aNormal;
            layout(location = JOINTS_LOCATION) in uvec4 aJoints;      // InfluenceView with INFLUENCES slots
            layout(location = WEIGHTS_LOCATION) in vec4 aWeights;
            layout(location = CENTRE_LOCATION) in vec3 aCentre;       // CoR: the point's centre of rotation
            layout(location = UV_LOCATION) in vec2 aUv;
            layout(location = COLOR_LOCATION) in vec4 aColor;
            uniform highp sampler2D uPalette;   // TEXELS_PER_JOINT texels per joint row (PaletteTexture)
            uniform int uMethod;                // SkinningGlsl.methodCode; 0: the points are CPU-skinned
            uniform mat4 uModelView;
            uniform mat4 uProjection;
            out vec3 vNormal;
            out vec3 vEye;
            out vec2 vUv;
            out vec4 vColor;

            // The palette as skinning.glsl reads it: parts are the first texel of their rows.
            const int MATRIX_ROWS = MATRIX_TEXEL;
            const int SCALE_ROWS = SCALE_TEXEL;
            int influenceCount() { return INFLUENCES; }
            float weightAt(int i) { return aWeights[i]; }
            uint jointAt(int i) { return aJoints[i]; }
            vec4 paletteRow(int part, uint joint, int row) { return texelFetch(uPalette, ivec2(part + row, int(joint)), 0); }
            vec4 paletteRotation(uint joint) { return texelFetch(uPalette, ivec2(ROTATION_TEXEL, int(joint)), 0); }
            vec4 paletteDual(uint joint) { return texelFetch(uPalette, ivec2(ROTATION_TEXEL + 1, int(joint)), 0); }
            vec4 boneRow(uint joint, int row) { return texelFetch(uPalette, ivec2(BONE_TEXEL + row, int(joint)), 0); }

            #include "skinning.glsl"

            void main() {
                vec3 p;
                vec3 n;
                skin(uMethod, aPosition, aNormal, aCentre, p, n);
                vec4 eye = uModelView * vec4(p, 1.0);
                vEye = eye.xyz;
                vNormal = mat3(uModelView) * n;
                vUv = aUv;
                vColor = aColor;
                gl_Position = uProjection * eye;
            }
            """;

    /**
     * The skinned model's fragment shader: the part's material (core's {@code material.glsl},
     * {@link MaterialGlsl}, shared with the desktop) lit by one light from above the camera, both
     * faces lit alike; unlit parts as their base colour; emission added.
     *
     * @throws IllegalStateException when the formulas cannot be read (an APK without them)
     */
    public static String skinnedFragment() {
        return MaterialGlsl.expand(SKINNED_FRAGMENT);
    }

    private static final String SKINNED_FRAGMENT = """
            #version 300 es
            precision mediump float;
            in vec3 vNormal;
            in vec3 vEye;
            in vec2 vUv;
            in vec4 vColor;
            out vec4 color;

            #include "material.glsl"

            void main() {
                vec4 base = surfaceBase(vUv, vColor);
                if (uUnlit) {
                    color = base;
                    return;
                }
                vec3 n = normalize(vNormal);
                if (dot(n, vEye) > 0.0) n = -n;       // lit on the side the camera sees
                vec3 l = normalize(vec3(0.3, 0.8, 0.6));
                float diffuse = max(dot(n, l), 0.0);
                color = vec4(base.rgb * (0.35 + 0.65 * diffuse) + surfaceEmission(vUv), base.a);
            }
            """;
}
