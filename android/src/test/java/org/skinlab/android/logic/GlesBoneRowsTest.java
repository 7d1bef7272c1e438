package org.skinlab.android.logic;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.lwjgl.opengles.GLES30.*;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.FloatBuffer;
import java.nio.ShortBuffer;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.skinlab.collada.ColladaImporter;
import org.skinlab.model.Model;
import org.skinlab.simulation.AnimationConfig;
import org.skinlab.simulation.Frame;
import org.skinlab.simulation.SkeletalAnimatedMesh;
import org.skinlab.skinning.JointPalette;

/**
 * The app's vertex shader reads a frame's bone rows where the app puts them: the shader's own
 * header ({@link GlesShaders#skinnedVertex()}, its {@code boneRow(joint, row)} accessor and the
 * palette texture of {@link PaletteTexture}) with its main replaced by one that writes the six
 * rows of each vertex's first joint, read back by transform feedback on a real OpenGL ES 3.0
 * context. Texel fetches of an RGBA32F texture copy floats, so the rows must come back exactly;
 * a texel off, a wrong texture width or a row packed in the wrong place changes them.
 */
class GlesBoneRowsTest {
    private static final String[] ROWS = {"vRow0", "vRow1", "vRow2", "vRow3", "vRow4", "vRow5"};

    /** The app's shader with a main that outputs the bone rows of joint {@code jointAt(0)}. */
    private static String boneRowShader() {
        String app = GlesShaders.skinnedVertex();
        assertEquals(1, app.split("void main\\(\\)", -1).length - 1, "one main to replace");
        StringBuilder s = new StringBuilder(app.replace("void main()", "void appMain()"));
        for (String row : ROWS) {
            s.append("out vec4 ").append(row).append(";\n");
        }
        s.append("void main() {\n    uint j = jointAt(0);\n");
        for (int r = 0; r < ROWS.length; r++) {
            s.append("    ").append(ROWS[r]).append(" = boneRow(j, ").append(r).append(");\n");
        }
        return s.append("    gl_Position = vec4(0.0);\n}\n").toString();
    }

    @Test
    void theShaderReadsEachJointsBoneRowsAsTheFramePublishedThem() throws Exception {
        Path root = Path.of(System.getProperty("skinlab.root", ".."));
        Model model = ColladaImporter.read(root.resolve("assets/characters/humanoid-walk.dae"));
        AnimationConfig config = new AnimationConfig(AnimationConfig.Settings.DEFAULT.withCpuSkinning(false));
        config.stopAnimation();
        try (GlesContext context = GlesContext.openOrSkip();
                SkeletalAnimatedMesh mesh = new SkeletalAnimatedMesh(model, model.clips().get(0), config)) {
            assertTrue(context.capabilities().GLES30, "an OpenGL ES 3.0 context");
            mesh.seek(0.3 * mesh.clipDuration());
            mesh.step(0.0);
            int program = GlesPrograms.link(boneRowShader(), GlesShaders.skinnedFragment(), ROWS);
            try (Frame frame = mesh.acquire()) {
                for (int g = 0; g < frame.geometryCount(); g++) {
                    float[] expected = frame.palette(g).boneRows();
                    assertTrue(lengths(expected) > 0, "geometry " + g + " has bones of some length");
                    float[] packed = new float[PaletteTexture.floats(frame.palette(g).jointCount())];
                    PaletteTexture.pack(frame, g, packed);
                    assertArrayEquals(expected, capture(program, packed, frame.palette(g).jointCount()),
                            "geometry " + g + ": bone rows read by the shader");
                }
            } finally {
                glDeleteProgram(program);
            }
        }
    }

    /** The sum of the bones' lengths (row 4's w). */
    private static float lengths(float[] rows) {
        float sum = 0f;
        for (int b = 0; b < rows.length; b += JointPalette.BONE_FLOATS) {
            sum += rows[b + 19];
        }
        return sum;
    }

    /** One point per joint j (its first influence j), each capturing the 24 floats of j's rows. */
    private static float[] capture(int program, float[] packed, int joints) {
        int vao = glGenVertexArrays();
        int[] buffers = new int[2];
        glGenBuffers(buffers);
        int texture = glGenTextures();
        int query = glGenQueries();
        try {
            glBindVertexArray(vao);
            ShortBuffer j = ByteBuffer.allocateDirect(8 * joints).order(ByteOrder.nativeOrder()).asShortBuffer();
            for (int k = 0; k < joints; k++) {
                j.put((short) k).put((short) 0).put((short) 0).put((short) 0);
            }
            j.flip();
            glBindBuffer(GL_ARRAY_BUFFER, buffers[0]);
            glBufferData(GL_ARRAY_BUFFER, j, GL_STATIC_DRAW);
            glEnableVertexAttribArray(GlesShaders.JOINTS);
            glVertexAttribIPointer(GlesShaders.JOINTS, 4, GL_UNSIGNED_SHORT, 8, 0);
            FloatBuffer data = ByteBuffer.allocateDirect(4 * packed.length).order(ByteOrder.nativeOrder()).asFloatBuffer();
            data.put(packed).flip();
            glActiveTexture(GL_TEXTURE0 + GlesShaders.PALETTE_UNIT);
            glBindTexture(GL_TEXTURE_2D, texture);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
            glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, PaletteTexture.TEXELS_PER_JOINT, joints, 0, GL_RGBA, GL_FLOAT,
                    data);
            glActiveTexture(GL_TEXTURE0);
            glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, buffers[1]);
            glBufferData(GL_TRANSFORM_FEEDBACK_BUFFER, 4L * JointPalette.BONE_FLOATS * joints, GL_STREAM_READ);
            glUseProgram(program);
            glUniform1i(glGetUniformLocation(program, "uPalette"), GlesShaders.PALETTE_UNIT);
            glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, buffers[1]);
            glEnable(GL_RASTERIZER_DISCARD);
            glBeginQuery(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN, query);
            glBeginTransformFeedback(GL_POINTS);
            glDrawArrays(GL_POINTS, 0, joints);
            glEndTransformFeedback();
            glEndQuery(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN);
            glDisable(GL_RASTERIZER_DISCARD);
            assertEquals(joints, glGetQueryObjectui(query, GL_QUERY_RESULT), "points captured");
            ByteBuffer mapped = glMapBufferRange(GL_TRANSFORM_FEEDBACK_BUFFER, 0, 4L * JointPalette.BONE_FLOATS * joints,
                    GL_MAP_READ_BIT);
            float[] out = new float[JointPalette.BONE_FLOATS * joints];
            mapped.order(ByteOrder.nativeOrder()).asFloatBuffer().get(out);
            glUnmapBuffer(GL_TRANSFORM_FEEDBACK_BUFFER);
            return out;
        } finally {
            glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, 0);
            glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, 0);
            glBindVertexArray(0);
            glDeleteQueries(query);
            glDeleteTextures(texture);
            glDeleteBuffers(buffers);
            glDeleteVertexArrays(vao);
        }
    }
}
