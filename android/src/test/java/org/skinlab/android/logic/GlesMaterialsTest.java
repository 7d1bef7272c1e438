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
import java.util.Arrays;

import org.joml.Matrix4f;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.skinlab.importer.ModelImporter;
import org.skinlab.model.Image;
import org.skinlab.model.Model;
import org.skinlab.model.MeshPart;
import org.skinlab.model.Texture;
import org.skinlab.internal.scene.BlendOrder;
import org.skinlab.internal.scene.MaterialGlsl;
import org.skinlab.internal.scene.PartCentres;
import org.skinlab.internal.scene.PartMaterial;
import org.skinlab.simulation.AnimationConfig;
import org.skinlab.simulation.Frame;
import org.skinlab.simulation.SkeletalAnimatedMesh;
import org.skinlab.skinning.InfluenceView;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinningGlsl;
import org.skinlab.skinning.SkinningMethod;

/**
 * The phone's model shaders ({@link GlesShaders#skinnedVertex()}, {@link GlesShaders#skinnedFragment()}:
 * core's material.glsl) draw glTF materials on a real OpenGL ES 3.0 (Mesa under Xvfb): core's
 * {@code gltf/materials.glb} (tools/gltf/make-fixtures.py: unit quads in a 3 x 3 grid, one
 * material feature each), its pictures decoded by {@link ModelTextures} (ImageIO standing in for
 * BitmapFactory) and each geometry fed, textured, culled and ordered as the app's ModelGl and
 * ArRenderer do it, drawn into a 200 x 200 framebuffer through an orthographic camera that shows
 * x in [-2, 2] and y in [-0.75, 3.25]: a quad's centre (X, Y) lands on pixel
 * (50 (X + 2), 200 - 50 (Y + 0.75)), a quarter of a quad is 12.5 pixels.
 *
 * And {@code gltf/skin-textured.glb}, skinned and textured, at rest and with its upper half slid.
 *
 * <p>Lit colours are the base colour times 0.35 + 0.65 n.l = 0.72 here (the app's light, quads
 * facing the camera): checks ask for a dominant channel above 150 and the others below 60.
 */
class GlesMaterialsTest {
    private static final int SIZE = 200;
    /** Pixel columns and rows of the grid's quad centres. */
    private static final int[] COLUMNS = {38, 100, 162};
    private static final int[] ROWS = {38, 100, 162};

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
    void aSkinnedTexturedGlbIsDrawnTexturedWhereItsJointsPutIt() throws Exception {
        // skin-textured.glb: a 1 x 2 strip with the four-colour picture; its upper half follows a
        // joint that slides 0.5 along +X by t = 1 (0.45 at t = 0.9: the clip loops at its end).
        // (0.25, 1.5) shows green at rest, then the red that was at (-0.2, 1.5); (-0.25, 1.5) is
        // then empty; the lower left stays blue.
        Matrix4f view = new Matrix4f().translate(0, 0, -5);
        int[][] rest = render("skin-textured.glb", view, 0.0, 1);
        expect(rest, 112, 88, "upper right at rest", 0, 1, 0);
        expect(rest, 88, 88, "upper left at rest", 1, 0, 0);
        expect(rest, 88, 150, "lower left at rest", 0, 0, 1);
        int[][] slid = render("skin-textured.glb", view, 0.9, 1);
        expect(slid, 112, 88, "upper half slid right: its red", 1, 0, 0);
        expectClear(slid, 88, 88, "where the upper left was");
        expect(slid, 88, 150, "lower left", 0, 0, 1);
    }

    @Test
    void aTexturedGlbIsDrawnWithItsMaterials() throws Exception {
        int[][] p = render(new Matrix4f().translate(0, 0, -5));
        // The four-colour picture the right way up, then turned by KHR_texture_transform.
        expect(p, COLUMNS[0] - 12, ROWS[0] - 12, "quadrants top left", 1, 0, 0);
        expect(p, COLUMNS[0] + 12, ROWS[0] - 12, "quadrants top right", 0, 1, 0);
        expect(p, COLUMNS[0] - 12, ROWS[0] + 12, "quadrants bottom left", 0, 0, 1);
        expect(p, COLUMNS[0] + 12, ROWS[0] + 12, "quadrants bottom right", 1, 1, 0);
        expect(p, COLUMNS[1] - 12, ROWS[0] - 12, "turned top left", 0, 0, 1);
        expect(p, COLUMNS[1] + 12, ROWS[0] - 12, "turned top right", 1, 0, 0);
        expect(p, COLUMNS[1] - 12, ROWS[0] + 12, "turned bottom left", 1, 1, 0);
        expect(p, COLUMNS[1] + 12, ROWS[0] + 12, "turned bottom right", 0, 1, 0);
        // MASK: the left half cut out, the right half drawn.
        expectClear(p, COLUMNS[2] - 12, ROWS[0], "cutout left half");
        expect(p, COLUMNS[2] + 12, ROWS[0], "cutout right half", 0, 1, 0);
        // BLEND, listed first, drawn after the opaque red quad behind it: blue at 0.5 over red.
        int[] glass = p[ROWS[1] * SIZE + COLUMNS[0]];
        assertTrue(glass[0] > 50 && glass[2] > 50 && glass[1] < 20 && Math.abs(glass[0] - glass[2]) < 40,
                "blue at alpha 0.5 over red: " + Arrays.toString(glass));
        expect(p, COLUMNS[1], ROWS[1], "emissive", 0, 1, 0);
        int[] unlit = p[ROWS[1] * SIZE + COLUMNS[2]];
        assertTrue(Math.abs(unlit[0] - 255) <= 2 && Math.abs(unlit[1] - 128) <= 2 && unlit[2] <= 2,
                "unlit (1, 0.5, 0) exactly: " + Arrays.toString(unlit));
        expectClear(p, COLUMNS[0], ROWS[2], "single-sided quad seen from behind");
        expect(p, COLUMNS[1], ROWS[2], "double-sided quad seen from behind", 1, 1, 0);
        expect(p, COLUMNS[2], ROWS[2], "vertex colours", 1, 0, 1);
    }

    @Test
    void fromBehindTheOtherFacesAreCulled() throws Exception {
        int[][] p = render(new Matrix4f().translate(0, 0, -5).rotateY((float) Math.PI));
        // Seen from behind, x is mirrored: column 0 lands where column 2 was.
        expectClear(p, COLUMNS[2], ROWS[0], "quadrants from behind");
        expect(p, COLUMNS[2], ROWS[2], "single-sided quad facing the camera", 0, 1, 1);
        expect(p, COLUMNS[1], ROWS[2], "double-sided quad from its back", 1, 1, 0);
        expectClear(p, COLUMNS[0], ROWS[2], "vertex-coloured quad from behind");
    }

    private static void expect(int[][] p, int x, int y, String what, int r, int g, int b) {
        int[] c = p[y * SIZE + x];
        int[] want = {r, g, b};
        for (int i = 0; i < 3; i++) {
            assertTrue(want[i] == 1 ? c[i] > 150 : c[i] < 60, what + " at (" + x + ", " + y + ") should be "
                    + Arrays.toString(want) + ": " + Arrays.toString(c));
        }
    }

    private static void expectClear(int[][] p, int x, int y, String what) {
        int[] c = p[y * SIZE + x];
        assertTrue(c[0] == 0 && c[1] == 0 && c[2] == 0, what + " at (" + x + ", " + y + ") is not drawn: "
                + Arrays.toString(c));
    }

    /**
     * materials.glb drawn through {@code view} (5 units in front of the camera, which the lighting's
     * facing test needs) and the orthographic camera; RGB per pixel, row 0 at the top.
     */
    private static int[][] render(Matrix4f view) throws Exception {
        return render("materials.glb", view, 0.0, 2);
    }

    /** As {@link #render(Matrix4f)} for core's fixture {@code file} at clip time {@code seconds}. */
    private static int[][] render(String file, Matrix4f view, double seconds, int pictureCount) throws Exception {
        Path glb = Path.of(System.getProperty("skinlab.root", ".."), "core/src/test/resources/gltf", file);
        Model model = ModelImporter.read(glb);
        ModelTextures pictures = ModelTextures.decode(model, new ImageIoDecoder());
        assertEquals(pictureCount, pictures.count(), "every picture decodes: " + pictures.problems());
        AnimationConfig config = new AnimationConfig(AnimationConfig.Settings.DEFAULT.withCpuSkinning(false));
        Matrix4f projection = new Matrix4f().ortho(-2f, 2f, -0.75f, 3.25f, -10f, 10f);
        int target = glGenTextures();
        glBindTexture(GL_TEXTURE_2D, target);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, SIZE, SIZE, 0, GL_RGBA, GL_UNSIGNED_BYTE, (ByteBuffer) null);
        int depth = glGenRenderbuffers();
        glBindRenderbuffer(GL_RENDERBUFFER, depth);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, SIZE, SIZE);
        int fbo = glGenFramebuffers();
        glBindFramebuffer(GL_FRAMEBUFFER, fbo);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target, 0);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
        assertEquals(GL_FRAMEBUFFER_COMPLETE, glCheckFramebufferStatus(GL_FRAMEBUFFER));
        glViewport(0, 0, SIZE, SIZE);
        glClearColor(0f, 0f, 0f, 1f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        try (SkeletalAnimatedMesh mesh = SkeletalAnimatedMesh.of(model, config)) {
            mesh.seek(seconds);
            mesh.step(0.0);
            try (Frame frame = mesh.acquire()) {
                AppDraw draw = new AppDraw(mesh, pictures);
                draw.draw(frame, view, projection);
                draw.close();
            }
        }
        ByteBuffer read = ByteBuffer.allocateDirect(4 * SIZE * SIZE).order(ByteOrder.nativeOrder());
        glReadPixels(0, 0, SIZE, SIZE, GL_RGBA, GL_UNSIGNED_BYTE, read);
        assertEquals(GL_NO_ERROR, glGetError());
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glDeleteFramebuffers(fbo);
        glDeleteRenderbuffers(depth);
        glDeleteTextures(target);
        int[][] out = new int[SIZE * SIZE][];
        for (int row = 0; row < SIZE; row++) {
            for (int x = 0; x < SIZE; x++) {
                int o = 4 * (row * SIZE + x); // glReadPixels starts at the bottom row
                out[(SIZE - 1 - row) * SIZE + x] = new int[] {read.get(o) & 0xFF, read.get(o + 1) & 0xFF,
                        read.get(o + 2) & 0xFF};
            }
        }
        return out;
    }

    /**
     * The app's draw of a model (ModelGl and ArRenderer, through LWJGL's GLES instead of
     * android.opengl): buffers at GlesShaders' locations, palette texture, pictures uploaded as
     * RGBA8 bottom row first, opaque parts, then blended parts ordered by {@link BlendOrder},
     * back faces culled for single-sided parts.
     */
    private static final class AppDraw {
        private final SkeletalAnimatedMesh mesh;
        private final int[] vaos;
        private final int[] palettes;
        private final java.util.List<Integer> names = new java.util.ArrayList<>();
        private final java.util.Map<Image, Integer> textures = new java.util.IdentityHashMap<>();
        private final ModelTextures pictures;

        AppDraw(SkeletalAnimatedMesh mesh, ModelTextures pictures) {
            this.mesh = mesh;
            this.pictures = pictures;
            int n = mesh.geometries().size();
            vaos = new int[n];
            palettes = new int[n];
            for (int g = 0; g < n; g++) {
                vaos[g] = vertexArray(mesh.geometries().get(g));
                palettes[g] = glGenTextures();
                glBindTexture(GL_TEXTURE_2D, palettes[g]);
                glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
                glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
            }
        }

        private int vertexArray(SkinnedGeometry g) {
            int vn = g.vertexCount();
            int vao = glGenVertexArrays();
            glBindVertexArray(vao);
            floats(g.positionArray(), 3 * vn, GlesShaders.POSITION, 3);
            floats(g.normalArray(), 3 * vn, GlesShaders.NORMAL, 3);
            InfluenceView view = InfluenceView.of(g, GlesShaders.INFLUENCES);
            int k = GlesShaders.INFLUENCES;
            ShortBuffer j = ByteBuffer.allocateDirect(2 * k * vn).order(ByteOrder.nativeOrder()).asShortBuffer();
            view.putJointIndices(j, vn);
            j.flip();
            int jb = buffer();
            glBufferData(GL_ARRAY_BUFFER, j, GL_STATIC_DRAW);
            glEnableVertexAttribArray(GlesShaders.JOINTS);
            glVertexAttribIPointer(GlesShaders.JOINTS, k, GL_UNSIGNED_SHORT, 2 * k, 0);
            FloatBuffer w = ByteBuffer.allocateDirect(4 * k * vn).order(ByteOrder.nativeOrder()).asFloatBuffer();
            view.putWeights(w, vn);
            w.flip();
            buffer();
            glBufferData(GL_ARRAY_BUFFER, w, GL_STATIC_DRAW);
            glEnableVertexAttribArray(GlesShaders.WEIGHTS);
            glVertexAttribPointer(GlesShaders.WEIGHTS, k, GL_FLOAT, false, 4 * k, 0);
            floats(g.centresOfRotation(), 3 * vn, GlesShaders.CENTRE, 3);
            floats(PartMaterial.texCoords(g.mesh(), g.instance()), 2 * vn, GlesShaders.UV, 2);
            if (g.mesh().hasColors()) {
                floats(g.mesh().colors(), 4 * vn, GlesShaders.COLOR, 4);
            }
            IntBuffer idx = ByteBuffer.allocateDirect(4 * g.mesh().triangles().length).order(ByteOrder.nativeOrder())
                    .asIntBuffer();
            idx.put(g.mesh().triangles()).flip();
            int eb = glGenBuffers();
            names.add(eb);
            glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, eb);
            glBufferData(GL_ELEMENT_ARRAY_BUFFER, idx, GL_STATIC_DRAW);
            glBindVertexArray(0);
            return vao;
        }

        private int buffer() {
            int b = glGenBuffers();
            names.add(b);
            glBindBuffer(GL_ARRAY_BUFFER, b);
            return b;
        }

        private void floats(float[] data, int count, int attribute, int size) {
            FloatBuffer fb = ByteBuffer.allocateDirect(4 * count).order(ByteOrder.nativeOrder()).asFloatBuffer();
            fb.put(data, 0, count).flip();
            buffer();
            glBufferData(GL_ARRAY_BUFFER, fb, GL_STATIC_DRAW);
            glEnableVertexAttribArray(attribute);
            glVertexAttribPointer(attribute, size, GL_FLOAT, false, 4 * size, 0);
        }

        private int texture(Texture t) {
            if (t == null) {
                return 0;
            }
            return textures.computeIfAbsent(t.image(), image -> {
                TexturePixels p = pictures.of(image);
                int id = glGenTextures();
                glActiveTexture(GL_TEXTURE0 + GlesShaders.BASE_TEXTURE_UNIT);
                glBindTexture(GL_TEXTURE_2D, id);
                glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, p.width(), p.height(), 0, GL_RGBA, GL_UNSIGNED_BYTE,
                        p.rgba().duplicate());
                glGenerateMipmap(GL_TEXTURE_2D);
                glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
                glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
                return id;
            });
        }

        void draw(Frame frame, Matrix4f view, Matrix4f projection) {
            glEnable(GL_DEPTH_TEST);
            glEnable(GL_BLEND);
            glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
            glUseProgram(program);
            glUniformMatrix4fv(glGetUniformLocation(program, "uProjection"), false, projection.get(new float[16]));
            glUniformMatrix4fv(glGetUniformLocation(program, "uModelView"), false, view.get(new float[16]));
            glUniform1i(glGetUniformLocation(program, "uMethod"), SkinningGlsl.methodCode(SkinningMethod.LBS));
            glUniform1i(glGetUniformLocation(program, "uPalette"), GlesShaders.PALETTE_UNIT);
            glUniform1i(glGetUniformLocation(program, "uBaseTexture"), GlesShaders.BASE_TEXTURE_UNIT);
            glUniform1i(glGetUniformLocation(program, "uEmissionTexture"), GlesShaders.EMISSION_TEXTURE_UNIT);
            glVertexAttrib4f(GlesShaders.COLOR, 1f, 1f, 1f, 1f);
            Matrix4f clip = new Matrix4f(projection).mul(view);
            int n = mesh.geometries().size();
            BlendOrder order = new BlendOrder(n);
            float[][] posed = new float[n][];
            for (int g = 0; g < n; g++) {
                SkinnedGeometry geometry = mesh.geometries().get(g);
                PartCentres centres = PartCentres.of(geometry);
                posed[g] = new float[3 * centres.partCount()];
                for (int i = 0; i < centres.partCount(); i++) {
                    centres.posed(i, frame.palette(g).matrices(), posed[g]);
                }
                MeshPart part = geometry.mesh().parts().get(0);
                PartMaterial m = PartMaterial.of(geometry.instance(), part);
                if (m.blended()) {
                    order.add(g, 0, BlendOrder.distance(clip, posed[g], 0));
                } else {
                    drawPart(frame, g, m, part);
                }
            }
            for (int k = 0; k < order.size(); k++) {
                SkinnedGeometry geometry = mesh.geometries().get(order.geometry(k));
                MeshPart part = geometry.mesh().parts().get(order.part(k));
                drawPart(frame, order.geometry(k), PartMaterial.of(geometry.instance(), part), part);
            }
            glDisable(GL_CULL_FACE);
            glDisable(GL_BLEND);
        }

        private void drawPart(Frame frame, int g, PartMaterial m, MeshPart part) {
            float[] packed = new float[PaletteTexture.floats(frame.palette(g).jointCount())];
            PaletteTexture.pack(frame, g, packed);
            FloatBuffer pb = ByteBuffer.allocateDirect(4 * packed.length).order(ByteOrder.nativeOrder()).asFloatBuffer();
            pb.put(packed).flip();
            glActiveTexture(GL_TEXTURE0 + GlesShaders.PALETTE_UNIT);
            glBindTexture(GL_TEXTURE_2D, palettes[g]);
            glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, PaletteTexture.TEXELS_PER_JOINT, frame.palette(g).jointCount(), 0, GL_RGBA,
                    GL_FLOAT, pb);
            if (m.doubleSided()) {
                glDisable(GL_CULL_FACE);
            } else {
                glEnable(GL_CULL_FACE);
                glCullFace(GL_BACK);
                glFrontFace(PartCentres.firstJointMirrors(frame.palette(g).matrices()) ? GL_CW : GL_CCW);
            }
            glUniform4fv(glGetUniformLocation(program, "uBaseColor"), m.baseColor());
            glUniform3fv(glGetUniformLocation(program, "uEmission"), m.emission());
            glUniform1i(glGetUniformLocation(program, "uAlphaMode"), MaterialGlsl.alphaMode(m));
            glUniform1f(glGetUniformLocation(program, "uAlphaCutoff"), m.alphaCutoff());
            glUniform1i(glGetUniformLocation(program, "uUnlit"), m.unlit() ? 1 : 0);
            int base = texture(m.baseTexture());
            int emission = texture(m.emissionTexture());
            glUniform1i(glGetUniformLocation(program, "uHasBaseTexture"), base != 0 ? 1 : 0);
            glUniformMatrix3fv(glGetUniformLocation(program, "uBaseTransform"), false,
                    PartMaterial.uvMatrix(m.baseTexture()));
            glUniform1i(glGetUniformLocation(program, "uHasEmissionTexture"), emission != 0 ? 1 : 0);
            glUniformMatrix3fv(glGetUniformLocation(program, "uEmissionTransform"), false,
                    PartMaterial.uvMatrix(m.emissionTexture()));
            glActiveTexture(GL_TEXTURE0 + GlesShaders.EMISSION_TEXTURE_UNIT);
            glBindTexture(GL_TEXTURE_2D, emission);
            glActiveTexture(GL_TEXTURE0 + GlesShaders.BASE_TEXTURE_UNIT);
            glBindTexture(GL_TEXTURE_2D, base);
            glBindVertexArray(vaos[g]);
            glDrawElements(GL_TRIANGLES, 3 * part.triangleCount(), GL_UNSIGNED_INT, 12L * part.firstTriangle());
            glBindVertexArray(0);
        }

        void close() {
            for (int b : names) {
                glDeleteBuffers(b);
            }
            for (int g = 0; g < vaos.length; g++) {
                glDeleteVertexArrays(vaos[g]);
                glDeleteTextures(palettes[g]);
            }
            for (int t : textures.values()) {
                glDeleteTextures(t);
            }
        }
    }
}
