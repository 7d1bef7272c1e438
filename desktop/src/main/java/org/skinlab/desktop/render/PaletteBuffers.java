package org.skinlab.desktop.render;

import static org.lwjgl.opengl.GL33C.*;

import org.skinlab.simulation.Frame;
import org.skinlab.skinning.JointPalette;

/**
 * One geometry's joint palette on the GPU: skinning matrices, dual quaternions, scale parts and
 * bone rows of a {@link Frame}, each in a texture buffer of RGBA32F texels (3, 2, 3 and 6 texels
 * per joint), so any number of joints fits where a uniform array would stop at a few hundred. The
 * frame's arrays go up as they are: their layouts already are the shader's. The bone rows go up
 * only for a draw with a method that reads them ({@link #uploadBones}).
 */
final class PaletteBuffers implements AutoCloseable {
    /** Texture units the skinning shader samples the palette from. */
    static final int MATRIX_UNIT = 1;
    static final int DUAL_QUATERNION_UNIT = 2;
    static final int SCALE_UNIT = 3;
    /** After the material's emission texture (unit 4). */
    static final int BONE_UNIT = 5;
    /** Texels per joint of the bone rows ({@code JointPalette.BONE_FLOATS} / 4). */
    static final int BONE_TEXELS = JointPalette.BONE_FLOATS / 4;

    private final int[] buffers = new int[4];
    private final int[] textures = new int[4];
    private boolean hasScale;
    private boolean matricesMirror;
    private boolean scalesMirror;

    PaletteBuffers(int joints) {
        int[] floatsPerJoint = {12, 8, 12, JointPalette.BONE_FLOATS};
        glGenBuffers(buffers);
        glGenTextures(textures);
        for (int i = 0; i < buffers.length; i++) {
            glBindBuffer(GL_TEXTURE_BUFFER, buffers[i]);
            glBufferData(GL_TEXTURE_BUFFER, 4L * floatsPerJoint[i] * Math.max(1, joints), GL_STREAM_DRAW);
            glBindTexture(GL_TEXTURE_BUFFER, textures[i]);
            glTexBuffer(GL_TEXTURE_BUFFER, GL_RGBA32F, buffers[i]);
        }
        glBindBuffer(GL_TEXTURE_BUFFER, 0);
        glBindTexture(GL_TEXTURE_BUFFER, 0);
    }

    /** Uploads geometry {@code g}'s palette of {@code frame}, all but the bone rows. */
    void upload(Frame frame, int g) {
        glBindBuffer(GL_TEXTURE_BUFFER, buffers[0]);
        glBufferSubData(GL_TEXTURE_BUFFER, 0, frame.palette(g).matrices());
        glBindBuffer(GL_TEXTURE_BUFFER, buffers[1]);
        glBufferSubData(GL_TEXTURE_BUFFER, 0, frame.palette(g).dualQuaternions());
        glBindBuffer(GL_TEXTURE_BUFFER, buffers[2]);
        glBufferSubData(GL_TEXTURE_BUFFER, 0, frame.palette(g).scales());
        glBindBuffer(GL_TEXTURE_BUFFER, 0);
        hasScale = frame.palette(g).hasScale();
        matricesMirror = frame.palette(g).mirrorsMatrices();
        scalesMirror = frame.palette(g).mirrorsScales();
    }

    /** Uploads geometry {@code g}'s bone rows of {@code frame} (for the methods that read bones). */
    void uploadBones(Frame frame, int g) {
        glBindBuffer(GL_TEXTURE_BUFFER, buffers[3]);
        glBufferSubData(GL_TEXTURE_BUFFER, 0, frame.palette(g).boneRows());
        glBindBuffer(GL_TEXTURE_BUFFER, 0);
    }

    void bind() {
        glActiveTexture(GL_TEXTURE0 + MATRIX_UNIT);
        glBindTexture(GL_TEXTURE_BUFFER, textures[0]);
        glActiveTexture(GL_TEXTURE0 + DUAL_QUATERNION_UNIT);
        glBindTexture(GL_TEXTURE_BUFFER, textures[1]);
        glActiveTexture(GL_TEXTURE0 + SCALE_UNIT);
        glBindTexture(GL_TEXTURE_BUFFER, textures[2]);
        glActiveTexture(GL_TEXTURE0 + BONE_UNIT);
        glBindTexture(GL_TEXTURE_BUFFER, textures[3]);
        glActiveTexture(GL_TEXTURE0);
    }

    boolean hasScale() {
        return hasScale;
    }

    boolean matricesMirror() {
        return matricesMirror;
    }

    boolean scalesMirror() {
        return scalesMirror;
    }

    @Override
    public void close() {
        glDeleteTextures(textures);
        glDeleteBuffers(buffers);
    }
}
