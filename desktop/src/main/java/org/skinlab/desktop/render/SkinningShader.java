package org.skinlab.desktop.render;

import static org.lwjgl.opengl.GL33C.*;

/**
 * The skinning program ({@code shaders/skinned.vert}, {@code skinned.frag}) and its uniform
 * locations, looked up once. It also records {@code vPosed}, the skinned position before the
 * model matrix, for transform feedback (GPU against CPU checks).
 */
public final class SkinningShader implements AutoCloseable {
    /** The transform feedback varying: 3 floats per vertex, the skinned position. */
    public static final String POSED_VARYING = "vPosed";

    /** Texture units of the material's textures (the palette takes PaletteBuffers' units). */
    static final int BASE_TEXTURE_UNIT = 0;
    static final int EMISSION_TEXTURE_UNIT = 4;

    private final ShaderProgram program;
    final int viewProjection;
    final int model;
    final int eye;
    final int skinning;
    final int influences;
    final int hasScale;
    final int matricesMirror;
    final int scalesMirror;
    final int compare;
    final int selectedJoint;
    final int viewMode;
    final int scalarFull;
    final int checkerCell;
    final int columns;
    final int spacing;
    final int firstInstance;
    final int flat;
    final int flatColor;
    final int baseColor;
    final int hasBaseTexture;
    final int baseTransform;
    final int emission;
    final int hasEmissionTexture;
    final int emissionTransform;
    final int alphaMode;
    final int alphaCutoff;
    final int unlit;

    public SkinningShader() {
        program = ShaderProgram.load("skinned", "skinned", POSED_VARYING);
        viewProjection = program.uniform("uViewProjection");
        model = program.uniform("uModel");
        eye = program.uniform("uEye");
        skinning = program.uniform("uSkinning");
        influences = program.uniform("uInfluences");
        hasScale = program.uniform("uHasScale");
        matricesMirror = program.uniform("uMatricesMirror");
        scalesMirror = program.uniform("uScalesMirror");
        compare = program.uniform("uCompare");
        selectedJoint = program.uniform("uSelectedJoint");
        viewMode = program.uniform("uViewMode");
        scalarFull = program.uniform("uScalarFull");
        checkerCell = program.uniform("uCheckerCell");
        columns = program.uniform("uColumns");
        spacing = program.uniform("uSpacing");
        firstInstance = program.uniform("uFirstInstance");
        flat = program.uniform("uFlat");
        flatColor = program.uniform("uFlatColor");
        baseColor = program.uniform("uBaseColor");
        hasBaseTexture = program.uniform("uHasBaseTexture");
        baseTransform = program.uniform("uBaseTransform");
        emission = program.uniform("uEmission");
        hasEmissionTexture = program.uniform("uHasEmissionTexture");
        emissionTransform = program.uniform("uEmissionTransform");
        alphaMode = program.uniform("uAlphaMode");
        alphaCutoff = program.uniform("uAlphaCutoff");
        unlit = program.uniform("uUnlit");
        program.use();
        glUniform1i(program.uniform("uBaseTexture"), BASE_TEXTURE_UNIT);
        glUniform1i(program.uniform("uEmissionTexture"), EMISSION_TEXTURE_UNIT);
        glUniform1i(program.uniform("uMatrices"), PaletteBuffers.MATRIX_UNIT);
        glUniform1i(program.uniform("uDualQuaternions"), PaletteBuffers.DUAL_QUATERNION_UNIT);
        glUniform1i(program.uniform("uScales"), PaletteBuffers.SCALE_UNIT);
        glUniform1i(program.uniform("uBones"), PaletteBuffers.BONE_UNIT);
        glUseProgram(0);
    }

    void use() {
        program.use();
    }

    public int programId() {
        return program.id();
    }

    @Override
    public void close() {
        program.close();
    }
}
