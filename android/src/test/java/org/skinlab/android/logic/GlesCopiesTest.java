package org.skinlab.android.logic;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.lwjgl.opengles.GLES30.*;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.FloatBuffer;
import java.nio.IntBuffer;
import java.nio.ShortBuffer;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.joml.Matrix4f;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.skinlab.importer.ModelImporter;
import org.skinlab.model.Model;
import org.skinlab.scene.ModelFraming;
import org.skinlab.simulation.AnimationConfig;
import org.skinlab.simulation.Frame;
import org.skinlab.simulation.SkeletalAnimatedMesh;
import org.skinlab.skinning.InfluenceView;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinningGlsl;
import org.skinlab.skinning.SkinningMethod;

/**
 * The measurement's copies as the GL thread draws them (CopiesDrawer: one set of vertex buffers,
 * each copy's palette uploaded into the one palette texture before its draw, its model-view from
 * {@link CopiesLayout}), with the app's shaders on a real OpenGL ES 3.0 (Mesa under Xvfb): with 1,
 * 4, 8 and 12 copies of the walking character, in a portrait and a landscape view, every copy is
 * seen, whole (none touches the picture's border), each in its own pose. Each copy is drawn unlit
 * in a colour of its own, so its pixels can be counted.
 */
class GlesCopiesTest {
    private static final Path WALKER = Path.of(System.getProperty("skinlab.root", "."), "assets", "characters",
            "humanoid-walk.dae");

    private static GlesContext context;
    private static int program;

    @BeforeAll
    static void open() {
        context = GlesContext.openOrSkip();
        program = GlesPrograms.link(GlesShaders.skinnedVertex(), GlesShaders.skinnedFragment());
    }

    @AfterAll
    static void close() {
        if (context != null) {
            glDeleteProgram(program);
            context.close();
        }
    }

    @Test
    void everyCopyIsSeenWholeInPortraitAndLandscape() throws Exception {
        Model model = ModelImporter.read(WALKER);
        for (int[] size : new int[][] {{160, 320}, {360, 180}}) {
            for (int copies : MeasureProtocol.COPIES) {
                int[] pixels = render(model, copies, size[0], size[1], SkinningMethod.DQS);
                for (int i = 0; i < copies; i++) {
                    int[] box = box(pixels, size[0], size[1], colour(i));
                    String where = copies + " copies in " + size[0] + "x" + size[1] + ", copy " + i;
                    assertTrue(box[4] >= 15, where + ": " + box[4] + " pixels seen");
                    assertTrue(box[0] > 0 && box[1] > 0 && box[2] < size[0] - 1 && box[3] < size[1] - 1,
                            where + " touches the border: " + java.util.Arrays.toString(box));
                }
            }
        }
    }

    @Test
    void eachCopyIsDrawnInItsOwnPose() throws Exception {
        // Two copies in one frame, the second at another clip time than the first, then at the
        // same: only the second copy's pixels change, so each draw used the palette uploaded for
        // its own copy, not the one before.
        Model model = ModelImporter.read(WALKER);
        int[] apart = render(model, 2, 240, 160, SkinningMethod.LBS, new double[] {0, 0.37});
        int[] alike = render(model, 2, 240, 160, SkinningMethod.LBS, new double[] {0, 0});
        assertEquals(0, changed(apart, alike, colour(0)), "the first copy is drawn alike both times");
        assertTrue(changed(apart, alike, colour(1)) > 30, "the second copy's own pose moved its silhouette by "
                + changed(apart, alike, colour(1)) + " pixels");
    }

    private static int changed(int[] a, int[] b, int colour) {
        int n = 0;
        for (int p = 0; p < a.length; p++) {
            n += (a[p] == colour) != (b[p] == colour) ? 1 : 0;
        }
        return n;
    }

    /** {@code copies} copies, copy i playing from 0.37 i s as the app's copies do. */
    private static int[] render(Model model, int copies, int width, int height, SkinningMethod method) {
        double[] times = new double[copies];
        for (int i = 0; i < copies; i++) {
            times[i] = 0.37 * i;
        }
        return render(model, copies, width, height, method, times);
    }

    /**
     * {@code copies} copies of {@code model}, copy i at clip time {@code times[i]}, in a
     * {@code width} x {@code height} framebuffer; RGB per pixel, top row first.
     */
    private static int[] render(Model model, int copies, int width, int height, SkinningMethod method,
            double[] times) {
        AnimationConfig config = new AnimationConfig(AnimationConfig.Settings.DEFAULT.withCpuSkinning(false)
                .withMethod(method));
        List<SkeletalAnimatedMesh> meshes = new ArrayList<>();
        for (int i = 0; i < copies; i++) {
            SkeletalAnimatedMesh m = new SkeletalAnimatedMesh(model, model.clips().get(0), config);
            m.seek(times[i]);
            m.step(0);
            meshes.add(m);
        }
        ModelFraming framing;
        try (Frame f = meshes.get(0).acquire()) {
            framing = ModelFraming.of(model.asset(), meshes.get(0).geometries(), f);
        }
        int colour = glGenTextures();
        glBindTexture(GL_TEXTURE_2D, colour);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, (ByteBuffer) null);
        int depth = glGenRenderbuffers();
        glBindRenderbuffer(GL_RENDERBUFFER, depth);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
        int fbo = glGenFramebuffers();
        glBindFramebuffer(GL_FRAMEBUFFER, fbo);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour, 0);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
        assertEquals(GL_FRAMEBUFFER_COMPLETE, glCheckFramebufferStatus(GL_FRAMEBUFFER));
        glViewport(0, 0, width, height);
        glClearColor(0f, 0f, 0f, 1f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glEnable(GL_DEPTH_TEST);
        try (Geometry g = new Geometry(meshes.get(0).geometries().get(0))) {
            Matrix4f view = new Matrix4f();
            Matrix4f projection = new Matrix4f();
            Matrix4f placed = new Matrix4f();
            CopiesLayout.camera(framing, copies, width, height, view, projection);
            glUseProgram(program);
            glUniformMatrix4fv(glGetUniformLocation(program, "uProjection"), false, projection.get(new float[16]));
            glUniform1i(glGetUniformLocation(program, "uMethod"), SkinningGlsl.methodCode(method));
            glUniform1i(glGetUniformLocation(program, "uPalette"), GlesShaders.PALETTE_UNIT);
            glUniform1i(glGetUniformLocation(program, "uUnlit"), 1);
            glUniform1i(glGetUniformLocation(program, "uAlphaMode"), 0);
            glUniformMatrix3fv(glGetUniformLocation(program, "uBaseTransform"), false, new float[] {1, 0, 0, 0, 1, 0,
                0, 0, 1});
            glVertexAttrib4f(GlesShaders.COLOR, 1f, 1f, 1f, 1f);
            for (int i = 0; i < copies; i++) {
                try (Frame f = meshes.get(i).acquire()) {
                    CopiesLayout.model(framing, i, copies, placed);
                    glUniformMatrix4fv(glGetUniformLocation(program, "uModelView"), false,
                            new Matrix4f(view).mul(placed).get(new float[16]));
                    int c = colour(i);
                    glUniform4f(glGetUniformLocation(program, "uBaseColor"), (c >> 16 & 0xFF) / 255f,
                            (c >> 8 & 0xFF) / 255f, (c & 0xFF) / 255f, 1f);
                    g.draw(f);
                }
            }
        }
        ByteBuffer read = ByteBuffer.allocateDirect(4 * width * height).order(ByteOrder.nativeOrder());
        glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, read);
        assertEquals(GL_NO_ERROR, glGetError());
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glDeleteFramebuffers(fbo);
        glDeleteRenderbuffers(depth);
        glDeleteTextures(colour);
        meshes.forEach(SkeletalAnimatedMesh::close);
        int[] rgb = new int[width * height];
        for (int row = 0; row < height; row++) {
            for (int x = 0; x < width; x++) {
                int o = 4 * (row * width + x); // glReadPixels starts at the bottom row
                rgb[(height - 1 - row) * width + x] = (read.get(o) & 0xFF) << 16 | (read.get(o + 1) & 0xFF) << 8
                        | read.get(o + 2) & 0xFF;
            }
        }
        return rgb;
    }

    /** Copy i's colour: distinct for 12 copies, exact in an 8-bit framebuffer (multiples of 1/255). */
    private static int colour(int i) {
        return (40 + 16 * i) << 16 | (255 - 16 * i) << 8 | (i % 2 == 0 ? 60 : 200);
    }

    /** The pixels of {@code colour}: min x, min y, max x, max y and their count. */
    private static int[] box(int[] rgb, int width, int height, int colour) {
        int[] box = {width, height, -1, -1, 0};
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                if (rgb[y * width + x] == colour) {
                    box[0] = Math.min(box[0], x);
                    box[1] = Math.min(box[1], y);
                    box[2] = Math.max(box[2], x);
                    box[3] = Math.max(box[3], y);
                    box[4]++;
                }
            }
        }
        return box;
    }

    /** One geometry's buffers as ModelGl makes them, and its palette texture refilled before each draw. */
    private static final class Geometry implements AutoCloseable {
        private final int vao = glGenVertexArrays();
        private final int[] buffers = new int[6];
        private final int palette = glGenTextures();
        private final int joints;
        private final int indices;
        private final float[] packed;
        private final FloatBuffer paletteBuffer;

        Geometry(SkinnedGeometry g) {
            int n = g.vertexCount();
            int k = GlesShaders.INFLUENCES;
            InfluenceView view = InfluenceView.of(g, k);
            glGenBuffers(buffers);
            glBindVertexArray(vao);
            floats(buffers[0], g.positionArray(), 3 * n, GlesShaders.POSITION, 3);
            floats(buffers[1], g.normalArray(), 3 * n, GlesShaders.NORMAL, 3);
            ShortBuffer j = ByteBuffer.allocateDirect(2 * k * n).order(ByteOrder.nativeOrder()).asShortBuffer();
            view.putJointIndices(j, n);
            j.flip();
            glBindBuffer(GL_ARRAY_BUFFER, buffers[2]);
            glBufferData(GL_ARRAY_BUFFER, j, GL_STATIC_DRAW);
            glEnableVertexAttribArray(GlesShaders.JOINTS);
            glVertexAttribIPointer(GlesShaders.JOINTS, k, GL_UNSIGNED_SHORT, 2 * k, 0);
            FloatBuffer w = ByteBuffer.allocateDirect(4 * k * n).order(ByteOrder.nativeOrder()).asFloatBuffer();
            view.putWeights(w, n);
            w.flip();
            glBindBuffer(GL_ARRAY_BUFFER, buffers[3]);
            glBufferData(GL_ARRAY_BUFFER, w, GL_STATIC_DRAW);
            glEnableVertexAttribArray(GlesShaders.WEIGHTS);
            glVertexAttribPointer(GlesShaders.WEIGHTS, k, GL_FLOAT, false, 4 * k, 0);
            floats(buffers[4], g.centresOfRotation(), 3 * n, GlesShaders.CENTRE, 3);
            int[] triangles = g.mesh().triangles();
            IntBuffer idx = ByteBuffer.allocateDirect(4 * triangles.length).order(ByteOrder.nativeOrder()).asIntBuffer();
            idx.put(triangles).flip();
            glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers[5]);
            glBufferData(GL_ELEMENT_ARRAY_BUFFER, idx, GL_STATIC_DRAW);
            glBindVertexArray(0);
            indices = triangles.length;
            joints = g.jointCount();
            packed = new float[PaletteTexture.floats(joints)];
            paletteBuffer = ByteBuffer.allocateDirect(4 * packed.length).order(ByteOrder.nativeOrder()).asFloatBuffer();
            glBindTexture(GL_TEXTURE_2D, palette);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
            glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, PaletteTexture.TEXELS_PER_JOINT, joints, 0, GL_RGBA, GL_FLOAT,
                    (FloatBuffer) null);
        }

        private static void floats(int buffer, float[] data, int count, int attribute, int size) {
            FloatBuffer fb = ByteBuffer.allocateDirect(4 * count).order(ByteOrder.nativeOrder()).asFloatBuffer();
            fb.put(data, 0, count).flip();
            glBindBuffer(GL_ARRAY_BUFFER, buffer);
            glBufferData(GL_ARRAY_BUFFER, fb, GL_STATIC_DRAW);
            glEnableVertexAttribArray(attribute);
            glVertexAttribPointer(attribute, size, GL_FLOAT, false, 4 * size, 0);
        }

        /** The frame's palette into the one texture (as ModelGl.palette), then every triangle. */
        void draw(Frame frame) {
            PaletteTexture.pack(frame, 0, packed);
            paletteBuffer.clear();
            paletteBuffer.put(packed).flip();
            glActiveTexture(GL_TEXTURE0 + GlesShaders.PALETTE_UNIT);
            glBindTexture(GL_TEXTURE_2D, palette);
            glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, PaletteTexture.TEXELS_PER_JOINT, joints, GL_RGBA, GL_FLOAT,
                    paletteBuffer);
            glActiveTexture(GL_TEXTURE0);
            glUniform1i(glGetUniformLocation(program, "uHasScale"), frame.palette(0).hasScale() ? 1 : 0);
            glUniform1i(glGetUniformLocation(program, "uMatricesMirror"), frame.palette(0).mirrorsMatrices() ? 1 : 0);
            glUniform1i(glGetUniformLocation(program, "uScalesMirror"), frame.palette(0).mirrorsScales() ? 1 : 0);
            glBindVertexArray(vao);
            glDrawElements(GL_TRIANGLES, indices, GL_UNSIGNED_INT, 0);
            glBindVertexArray(0);
        }

        @Override
        public void close() {
            glDeleteBuffers(buffers);
            glDeleteVertexArrays(vao);
            glDeleteTextures(palette);
        }
    }
}
