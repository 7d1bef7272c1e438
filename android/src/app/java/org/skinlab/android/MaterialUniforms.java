package org.skinlab.android;

import static android.opengl.GLES30.*;

import org.skinlab.android.logic.GlesShaders;
import org.skinlab.internal.scene.MaterialGlsl;
import org.skinlab.internal.scene.PartMaterial;

/** The skinned program's material uniforms (core's material.glsl), looked up once per program. */
final class MaterialUniforms {
    private final int baseColor;
    private final int hasBaseTexture;
    private final int baseTransform;
    private final int emission;
    private final int hasEmissionTexture;
    private final int emissionTransform;
    private final int alphaMode;
    private final int alphaCutoff;
    private final int unlit;

    /** For {@code program}, which must be in use: its texture units are set here. */
    MaterialUniforms(int program) {
        baseColor = glGetUniformLocation(program, "uBaseColor");
        hasBaseTexture = glGetUniformLocation(program, "uHasBaseTexture");
        baseTransform = glGetUniformLocation(program, "uBaseTransform");
        emission = glGetUniformLocation(program, "uEmission");
        hasEmissionTexture = glGetUniformLocation(program, "uHasEmissionTexture");
        emissionTransform = glGetUniformLocation(program, "uEmissionTransform");
        alphaMode = glGetUniformLocation(program, "uAlphaMode");
        alphaCutoff = glGetUniformLocation(program, "uAlphaCutoff");
        unlit = glGetUniformLocation(program, "uUnlit");
        glUniform1i(glGetUniformLocation(program, "uBaseTexture"), GlesShaders.BASE_TEXTURE_UNIT);
        glUniform1i(glGetUniformLocation(program, "uEmissionTexture"), GlesShaders.EMISSION_TEXTURE_UNIT);
    }

    /** Sets part {@code p}'s material and binds its textures (0: none). */
    void set(ModelGl.Part p) {
        PartMaterial m = p.material();
        glUniform4fv(baseColor, 1, p.baseColor(), 0);
        glUniform3fv(emission, 1, p.emission(), 0);
        glUniform1i(alphaMode, MaterialGlsl.alphaMode(m));
        glUniform1f(alphaCutoff, m.alphaCutoff());
        glUniform1i(unlit, m.unlit() ? 1 : 0);
        glUniform1i(hasBaseTexture, p.baseTexture() != 0 ? 1 : 0);
        glUniformMatrix3fv(baseTransform, 1, false, p.baseTransform(), 0);
        glUniform1i(hasEmissionTexture, p.emissionTexture() != 0 ? 1 : 0);
        glUniformMatrix3fv(emissionTransform, 1, false, p.emissionTransform(), 0);
        glActiveTexture(GL_TEXTURE0 + GlesShaders.EMISSION_TEXTURE_UNIT);
        glBindTexture(GL_TEXTURE_2D, p.emissionTexture());
        glActiveTexture(GL_TEXTURE0 + GlesShaders.BASE_TEXTURE_UNIT);
        glBindTexture(GL_TEXTURE_2D, p.baseTexture());
    }
}
