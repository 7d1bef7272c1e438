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
    final int columns;
    final int spacing;
    final int firstInstance;
    final int flat;
    final int flatColor;
    final int diffuse;
    final int hasTexture;

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
        columns = program.uniform("uColumns");
        spacing = program.uniform("uSpacing");
        firstInstance = program.uniform("uFirstInstance");
        flat = program.uniform("uFlat");
        flatColor = program.uniform("uFlatColor");
        diffuse = program.uniform("uDiffuse");
        hasTexture = program.uniform("uHasTexture");
        program.use();
        glUniform1i(program.uniform("uTexture"), 0);
        glUniform1i(program.uniform("uMatrices"), PaletteBuffers.MATRIX_UNIT);
        glUniform1i(program.uniform("uDualQuaternions"), PaletteBuffers.DUAL_QUATERNION_UNIT);
        glUniform1i(program.uniform("uScales"), PaletteBuffers.SCALE_UNIT);
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
