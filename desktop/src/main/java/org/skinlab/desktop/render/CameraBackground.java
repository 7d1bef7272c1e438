package org.skinlab.desktop.render;

import static org.lwjgl.opengl.GL33C.*;

import java.nio.ByteBuffer;
import java.nio.FloatBuffer;

import org.joml.Matrix4fc;
import org.lwjgl.system.MemoryUtil;
import org.skinlab.ar.CameraIntrinsics;
import org.skinlab.ar.LensGlsl;

/**
 * The camera image behind the AR scene ({@code skinlab ar}): an 8-bit RGB texture refilled from
 * each new colour frame (one reused upload buffer: nothing allocated per frame), drawn as a quad through
 * {@code ArCamera.imageToViewport}, so it lines up with the projection the model is drawn with.
 * Through a distorted camera the quad shows the ideal pinhole image: its fragment shader samples
 * the frame where the lens put each pixel's ray ({@link LensGlsl}), so straight edges are straight
 * again and the model, projected by the pinhole, stands where the marker is.
 */
public final class CameraBackground implements AutoCloseable {
    private final ShaderProgram program;
    private final int imageToViewport;
    private final int imageUnit;
    private final int size;
    private final int pinhole;
    private final int radial;
    private final int tangential;
    private final float[] lens = new float[11];
    private final int vao;
    private final int vbo;
    private final int texture;
    private final FloatBuffer matrix = MemoryUtil.memAllocFloat(16);
    private ByteBuffer upload = MemoryUtil.memAlloc(1);
    private int width;
    private int height;

    public CameraBackground() {
        program = ShaderProgram.load("background", "background");
        imageToViewport = program.uniform("uImageToViewport");
        imageUnit = program.uniform("uImage");
        size = program.uniform("uSize");
        pinhole = program.uniform("uPinhole");
        radial = program.uniform("uRadial");
        tangential = program.uniform("uTangential");
        FloatBuffer corners = MemoryUtil.memAllocFloat(8);
        try {
            corners.put(new float[] {-1, -1, 1, -1, -1, 1, 1, 1}).flip();
            vao = glGenVertexArrays();
            vbo = glGenBuffers();
            glBindVertexArray(vao);
            glBindBuffer(GL_ARRAY_BUFFER, vbo);
            glBufferData(GL_ARRAY_BUFFER, corners, GL_STATIC_DRAW);
            glEnableVertexAttribArray(0);
            glVertexAttribPointer(0, 2, GL_FLOAT, false, 0, 0L);
            glBindVertexArray(0);
            glBindBuffer(GL_ARRAY_BUFFER, 0);
        } finally {
            MemoryUtil.memFree(corners);
        }
        texture = glGenTextures();
        glBindTexture(GL_TEXTURE_2D, texture);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        glBindTexture(GL_TEXTURE_2D, 0);
    }

    /**
     * Uploads a camera frame of {@code w x h} pixels, {@code rgb} holding R, G, B bytes per pixel,
     * rows top first, no padding (its size may change: the texture follows).
     */
    public void upload(int w, int h, byte[] rgb) {
        int bytes = 3 * w * h;
        if (rgb.length < bytes) {
            throw new IllegalArgumentException(w + "x" + h + " RGB needs " + bytes + " bytes, has " + rgb.length);
        }
        if (upload.capacity() < bytes) {
            MemoryUtil.memFree(upload);
            upload = MemoryUtil.memAlloc(bytes);
        }
        upload.clear();
        upload.put(rgb, 0, bytes).flip();
        glBindTexture(GL_TEXTURE_2D, texture);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        if (w != width || h != height) {
            glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, w, h, 0, GL_RGB, GL_UNSIGNED_BYTE, upload);
            width = w;
            height = h;
        } else {
            glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, w, h, GL_RGB, GL_UNSIGNED_BYTE, upload);
        }
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        glBindTexture(GL_TEXTURE_2D, 0);
    }

    /**
     * Draws the last uploaded frame, seen by {@code camera} (of the frame's size or scaled to it),
     * as its ideal pinhole image through {@code imageToViewport}, behind everything (no depth writes).
     */
    public void draw(Matrix4fc imageToViewportMatrix, CameraIntrinsics camera) {
        if (width == 0) {
            return;
        }
        program.use();
        glUniformMatrix4fv(imageToViewport, false, imageToViewportMatrix.get(matrix));
        LensGlsl.uniforms(camera, lens);
        glUniform2f(size, lens[0], lens[1]);
        glUniform4f(pinhole, lens[2], lens[3], lens[4], lens[5]);
        glUniform3f(radial, lens[6], lens[7], lens[8]);
        glUniform2f(tangential, lens[9], lens[10]);
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D, texture);
        glUniform1i(imageUnit, 0);
        glDepthMask(false);
        glDisable(GL_DEPTH_TEST);
        glBindVertexArray(vao);
        glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
        glBindVertexArray(0);
        glDepthMask(true);
        glBindTexture(GL_TEXTURE_2D, 0);
    }

    @Override
    public void close() {
        glDeleteTextures(texture);
        glDeleteVertexArrays(vao);
        glDeleteBuffers(vbo);
        program.close();
        MemoryUtil.memFree(matrix);
        MemoryUtil.memFree(upload);
    }
}
