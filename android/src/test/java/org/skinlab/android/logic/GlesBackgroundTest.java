package org.skinlab.android.logic;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.lwjgl.opengles.GLES30.*;

import java.nio.ByteBuffer;
import java.nio.FloatBuffer;
import java.util.Locale;

import org.junit.jupiter.api.Test;
import org.lwjgl.system.MemoryUtil;
import org.skinlab.ar.CameraIntrinsics;
import org.skinlab.ar.LensDistortion;
import org.skinlab.ar.LensGlsl;

/**
 * The app's camera-background shader ({@link GlesShaders#backgroundFragment()}, core's lens.glsl
 * inside) draws the ideal pinhole image of a distorted camera on a real OpenGL ES 3.0 (Mesa's
 * llvmpipe): each output pixel is the camera image sampled where {@link LensDistortion#distort}
 * puts that pixel's ray, computed here on the CPU with bilinear sampling as the GPU's. A desktop
 * Mesa cannot feed a camera's external texture, so the shader runs with its
 * {@code samplerExternalOES} read as a {@code sampler2D} (the one word and the extension line
 * swapped; every formula, uniform and coordinate flip as in the app), fed through a
 * SurfaceTexture-like transform that flips t, as a camera's usually does.
 */
class GlesBackgroundTest {
    private static final int W = 160;
    private static final int H = 120;
    /** DistortedTrackingTest's webcam lens at a quarter of its 640x480. */
    private static final CameraIntrinsics WEBCAM = new CameraIntrinsics(640, 480, 520, 521, 322.3, 236.9,
            new LensDistortion(-0.32, 0.12, -0.02, 0.0012, -0.0008)).scaledTo(W, H);
    /**
     * Largest GPU-CPU difference in gray levels: the GPU samples with 8 bits of sub-texel position
     * and rounds to 8 bits; the image's steepest slope is about 40 levels per pixel, so a rounding
     * of 1/256 texel is 0.2 levels. A coordinate off by half a pixel (a wrong pixel convention) or
     * a flipped axis is tens of levels off.
     */
    private static final int TOLERANCE = 2;

    @Test
    void theBackgroundIsThePinholeImageOfTheLens() {
        try (GlesContext context = GlesContext.openOrSkip()) {
            assertTrue(context.capabilities().GLES30, "an OpenGL ES 3.0 context");
            String app = GlesShaders.backgroundFragment();
            String fragment = app.replace("#extension GL_OES_EGL_image_external_essl3 : require\n", "")
                    .replace("samplerExternalOES", "sampler2D");
            assertNotEquals(app, fragment);
            assertTrue(app.contains("lensSourceCoord("), "lens.glsl is included");
            int program = GlesPrograms.link(GlesShaders.BACKGROUND_VERTEX, fragment);
            byte[] image = image();
            for (CameraIntrinsics k : new CameraIntrinsics[] {WEBCAM.withDistortion(LensDistortion.NONE), WEBCAM}) {
                int[] gpu = render(program, image, k);
                int worst = 0;
                double sum = 0;
                for (int y = 0; y < H; y++) {
                    for (int x = 0; x < W; x++) {
                        int d = Math.abs(gpu[y * W + x] - expected(image, k, x, y));
                        worst = Math.max(worst, d);
                        sum += d;
                    }
                }
                System.out.printf(Locale.ROOT, "background %s: largest difference %d gray levels, mean %.3f%n",
                        k.isDistorted() ? "through the webcam lens" : "of an ideal camera", worst, sum / (W * H));
                assertTrue(worst <= TOLERANCE, "GPU vs CPU: " + worst + " gray levels");
            }
            glDeleteProgram(program);
        }
    }

    /** A smooth pattern with detail in every direction (about 40 levels per pixel at its steepest). */
    private static byte[] image() {
        byte[] g = new byte[W * H];
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                double v = 128 + 70 * Math.sin(0.35 * x + 0.1 * y) * Math.cos(0.27 * y) + 30 * Math.sin(0.05 * x * y / 10);
                g[y * W + x] = (byte) Math.max(0, Math.min(255, Math.round(v)));
            }
        }
        return g;
    }

    /** What the shader should draw at output pixel (x, y) (row 0 at the top): the CPU's reference. */
    private static int expected(byte[] image, CameraIntrinsics k, int x, int y) {
        double[] d = new double[2];
        k.distortion().distort((x - k.cx()) / k.fx(), (y - k.cy()) / k.fy(), d);
        double sx = d[0] * k.fx() + k.cx();
        double sy = d[1] * k.fy() + k.cy();
        if (sx < -0.5 || sy < -0.5 || sx > W - 0.5 || sy > H - 0.5) {
            return 0;
        }
        // GL's bilinear filter with clamped edges: texel centres at integers in these coordinates.
        int ix = (int) Math.floor(sx);
        int iy = (int) Math.floor(sy);
        double fx = sx - ix, fy = sy - iy;
        double top = (1 - fx) * at(image, ix, iy) + fx * at(image, ix + 1, iy);
        double bottom = (1 - fx) * at(image, ix, iy + 1) + fx * at(image, ix + 1, iy + 1);
        return (int) Math.round((1 - fy) * top + fy * bottom);
    }

    private static int at(byte[] image, int x, int y) {
        return image[Math.max(0, Math.min(H - 1, y)) * W + Math.max(0, Math.min(W - 1, x))] & 0xFF;
    }

    /** The background drawn into a W x H framebuffer; its red channel, row 0 at the top. */
    private static int[] render(int program, byte[] image, CameraIntrinsics k) {
        int texture = glGenTextures();
        glBindTexture(GL_TEXTURE_2D, texture);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        ByteBuffer pixels = MemoryUtil.memAlloc(W * H);
        FloatBuffer quad = MemoryUtil.memAllocFloat(8);
        ByteBuffer read = MemoryUtil.memAlloc(W * H * 4);
        try {
            // Rows top first: t = 0 is the image's top row, so the transform below flips t, as a
            // camera's SurfaceTexture transform does.
            pixels.put(image).flip();
            glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, W, H, 0, GL_RED, GL_UNSIGNED_BYTE, pixels);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
            int target = glGenTextures();
            glBindTexture(GL_TEXTURE_2D, target);
            glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, W, H, 0, GL_RGBA, GL_UNSIGNED_BYTE, (ByteBuffer) null);
            int fbo = glGenFramebuffers();
            glBindFramebuffer(GL_FRAMEBUFFER, fbo);
            glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target, 0);
            assertEquals(GL_FRAMEBUFFER_COMPLETE, glCheckFramebufferStatus(GL_FRAMEBUFFER));
            glViewport(0, 0, W, H);

            glUseProgram(program);
            float[] identity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
            float[] flipT = {1, 0, 0, 0, 0, -1, 0, 0, 0, 0, 1, 0, 0, 1, 0, 1};
            glUniformMatrix4fv(glGetUniformLocation(program, "uImageToViewport"), false, identity);
            glUniformMatrix4fv(glGetUniformLocation(program, "uSensorToNatural"), false, identity);
            glUniformMatrix4fv(glGetUniformLocation(program, "uTexture"), false, flipT);
            float[] lens = LensGlsl.uniforms(k, new float[11]);
            glUniform2f(glGetUniformLocation(program, "uSize"), lens[0], lens[1]);
            glUniform4f(glGetUniformLocation(program, "uPinhole"), lens[2], lens[3], lens[4], lens[5]);
            glUniform3f(glGetUniformLocation(program, "uRadial"), lens[6], lens[7], lens[8]);
            glUniform2f(glGetUniformLocation(program, "uTangential"), lens[9], lens[10]);
            glActiveTexture(GL_TEXTURE0);
            glBindTexture(GL_TEXTURE_2D, texture);
            glUniform1i(glGetUniformLocation(program, "uCamera"), 0);

            int vao = glGenVertexArrays();
            int vbo = glGenBuffers();
            glBindVertexArray(vao);
            glBindBuffer(GL_ARRAY_BUFFER, vbo);
            quad.put(new float[] {-1, -1, 1, -1, -1, 1, 1, 1}).flip();
            glBufferData(GL_ARRAY_BUFFER, quad, GL_STATIC_DRAW);
            glEnableVertexAttribArray(0);
            glVertexAttribPointer(0, 2, GL_FLOAT, false, 0, 0L);
            glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
            glPixelStorei(GL_PACK_ALIGNMENT, 1);
            glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, read);
            assertEquals(GL_NO_ERROR, glGetError());
            int[] out = new int[W * H];
            for (int row = 0; row < H; row++) {
                for (int x = 0; x < W; x++) {
                    // glReadPixels starts at the bottom row.
                    out[(H - 1 - row) * W + x] = read.get(4 * (row * W + x)) & 0xFF;
                }
            }
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
            glDeleteFramebuffers(fbo);
            glDeleteTextures(target);
            glDeleteTextures(texture);
            glDeleteBuffers(vbo);
            glDeleteVertexArrays(vao);
            return out;
        } finally {
            MemoryUtil.memFree(pixels);
            MemoryUtil.memFree(quad);
            MemoryUtil.memFree(read);
        }
    }
}
