package org.skinlab.simulation;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.util.function.BooleanSupplier;

import org.joml.Matrix4f;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.skinlab.collada.ColladaImporter;
import org.skinlab.model.Mesh;
import org.skinlab.model.MeshInstance;
import org.skinlab.model.Model;
import org.skinlab.model.Skin;
import org.skinlab.skinning.JointPalette;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinningGlsl;
import org.skinlab.skinning.SkinningMethod;
import org.skinlab.testing.TestPaths;

/**
 * The joint palette a frame carries for GPU skinning: it belongs to the frame's step, it is there
 * whatever the method, palette-only frames (CPU skinning off) carry it and refuse their mesh, the
 * mode switches from another thread while the simulation runs, and a skinner written from
 * nothing but {@link Frame}'s documented layouts reproduces the CPU-skinned mesh (LBS, and DQS
 * with bone scale).
 */
@Timeout(value = 30, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class PaletteFrameTest {
    /** The methods this test is about (CoR has its own tests: CorSkinningTest). */
    private static final SkinningMethod[] LBS_AND_DQS = {SkinningMethod.LBS, SkinningMethod.DQS};

    private static final Model RIBBON = TwistRibbon.model();
    /**
     * The layout skinner below works in double precision from the frame's floats, the kernels in
     * float: they differ by float rounding, about 2e-7 of the model's bounding box diagonal for
     * positions and 2e-7 for unit normals on both assets. Ten times that is allowed; a misread
     * layout (a transposed matrix, w first, the scale parts ignored) is off by 1e-3 or more.
     */
    private static final double POSITION_TOLERANCE = 2e-6;
    private static final double NORMAL_TOLERANCE = 2e-6;

    private static SkeletalAnimatedMesh ribbon(AnimationConfig config) {
        return new SkeletalAnimatedMesh(RIBBON, RIBBON.clips().get(0), config);
    }

    @Test
    void aPaletteOnlyFrameCarriesThePaletteOfItsClipTimeAndRefusesItsMesh() {
        AnimationConfig config = new AnimationConfig();
        FrameChecker checker = FrameChecker.ribbon(RIBBON);
        try (SkeletalAnimatedMesh mesh = ribbon(config)) {
            mesh.step(0.5);
            config.setCpuSkinning(false);
            mesh.step(0.75);
            try (Frame f = mesh.acquire()) {
                assertFalse(f.hasSkinnedMesh());
                assertEquals(1.25f, f.clipTime(), 1e-6f);
                assertEquals(2, f.palette(0).jointCount());
                // The palette is the skeleton's at 1.25 s, and Root's translation is the clip time.
                assertNull(checker.problem(f));
                // The buffer still holds an earlier step's mesh: handing it out would be a silent lie.
                IllegalStateException e = assertThrows(IllegalStateException.class, () -> f.positions(0));
                assertTrue(e.getMessage().contains("palette only") && e.getMessage().contains("frame " + f.sequence()),
                        e.getMessage());
                assertThrows(IllegalStateException.class, () -> f.normals(0));
                assertTrue(f.toString().contains("palette only"), f.toString());
                // Posing and the palette took time; no kernel deformed a mesh.
                assertEquals(0, f.meshSkinningNanos());
                assertTrue(f.skinningNanos() > 0);
            }
            // Stopped mesh updates publish nothing in palette mode either.
            config.stopMeshUpdates();
            long before = mesh.latestSequence();
            mesh.step(0.5);
            assertEquals(before, mesh.latestSequence());
            // Back to CPU skinning: the next frame has its mesh again, of its own step.
            config.startMeshUpdates();
            config.setCpuSkinning(true);
            mesh.step(0.25);
            try (Frame f = mesh.acquire()) {
                assertTrue(f.hasSkinnedMesh());
                assertEquals(2.0f, f.clipTime(), 1e-6f);
                assertNull(checker.problem(f));
                // The kernels' time is part of the step's, which also posed the skeleton.
                assertTrue(f.meshSkinningNanos() > 0 && f.meshSkinningNanos() < f.skinningNanos(),
                        f.meshSkinningNanos() + " of " + f.skinningNanos() + " ns");
            }
        }
    }

    @Test
    void aMethodWithoutShaderCodeIsSkinnedOnTheCpuEvenInPaletteOnlyMode() {
        // Renderers can only draw such a method from a mesh: the step makes one whatever the switch says.
        AnimationConfig config = new AnimationConfig(AnimationConfig.Settings.DEFAULT.withCpuSkinning(false));
        FrameChecker checker = FrameChecker.ribbon(RIBBON);
        int cpuOnly = 0;
        try (SkeletalAnimatedMesh mesh = ribbon(config)) {
            for (SkinningMethod m : SkinningMethod.values()) {
                config.setMethod(m);
                mesh.step(0.25);
                try (Frame f = mesh.acquire()) {
                    assertEquals(m, f.method());
                    assertEquals(!SkinningGlsl.hasCode(m), f.hasSkinnedMesh(), m.key());
                    assertEquals(!SkinningGlsl.hasCode(m), f.meshSkinningNanos() > 0, m.key());
                    assertNull(checker.problem(f), m.key());
                }
                cpuOnly += SkinningGlsl.hasCode(m) ? 0 : 1;
            }
        }
        assumeTrue(cpuOnly > 0, "every method has shader code: no CPU fallback to see");
    }

    @Test
    void framesCarryDualQuaternionsWhateverTheMethod() {
        // An LBS step never needs the dual quaternions itself; a split view drawing DQS from the
        // same frame does. Root turns 90 degrees about x per second, and moves 1 along x.
        try (SkeletalAnimatedMesh mesh = ribbon(new AnimationConfig())) {
            mesh.step(1.0);
            try (Frame f = mesh.acquire()) {
                assertEquals(SkinningMethod.LBS, f.method());
                assertNull(FrameChecker.ribbon(RIBBON).problem(f));
                float[] q = f.palette(0).dualQuaternions();
                // Root at 1 s: rotation 90 degrees about x, r = (sin 45, 0, 0, cos 45), up to sign.
                double s = Math.signum(q[3]);
                assertEquals(Math.sqrt(0.5), s * q[0], 1e-6);
                assertEquals(0.0, q[1], 1e-6);
                assertEquals(0.0, q[2], 1e-6);
                assertEquals(Math.sqrt(0.5), s * q[3], 1e-6);
                // No joint of the ribbon scales: every scale part is the identity.
                assertFalse(f.palette(0).hasScale());
                float[] identity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
                for (int j = 0; j < f.palette(0).jointCount(); j++) {
                    for (int i = 0; i < 12; i++) {
                        assertEquals(identity[i], f.palette(0).scales()[12 * j + i], "joint " + j + " scale " + i);
                    }
                }
            }
        }
    }

    @Test
    void theFrameSaysWhetherItsPaletteMirrors() {
        // A shader's normals need the sign rule of the CPU kernels: the frame carries the palette's flags.
        float[] identities = new float[32];
        for (int i = 0; i < 32; i += 5) {
            identities[i] = 1f;
        }
        identities[16] = identities[21] = identities[26] = identities[31] = 1f;
        SkinnedGeometry geometry = SkinnedGeometry.fromArrays(new float[3], new float[] {0, 1, 0}, 1, new int[1],
                new float[] {1}, identities, new int[] {-1, 0});
        JointPalette palette = geometry.newPalette();
        Frame f = new Frame(java.util.List.of(geometry), new boolean[1]);
        palette.prepareAll();
        f.copyPalette(0, palette);
        assertFalse(f.palette(0).mirrorsMatrices());
        assertFalse(f.palette(0).mirrorsScales());
        // A reflection is no rigid motion: DQS's split moves it into the joint's scale part.
        palette.setMatrix(1, new Matrix4f().scaling(-1, 1, 1));
        palette.prepareAll();
        f.copyPalette(0, palette);
        assertEquals(palette.boneRows()[JointPalette.BONE_FLOATS + 23], f.palette(0).boneRows()[JointPalette.BONE_FLOATS + 23],
                "the bone rows come along: joint 1's parent");
        assertTrue(f.palette(0).mirrorsMatrices());
        assertTrue(f.palette(0).hasScale());
        assertTrue(f.palette(0).mirrorsScales());
    }

    @Test
    void switchingToPaletteOnlyFromAnotherThreadShowsWithinTwoSteps() throws Exception {
        AnimationConfig config = new AnimationConfig();
        FrameChecker checker = FrameChecker.ribbon(RIBBON);
        try (SkeletalAnimatedMesh mesh = ribbon(config)) {
            mesh.setStepRate(500);
            mesh.start();
            for (int round = 0; round < 4; round++) {
                boolean cpu = round % 2 == 1;
                config.setCpuSkinning(cpu);
                // A step that read the settings before the switch may still publish the old kind;
                // every later one publishes the new kind.
                long switched = mesh.latestSequence();
                await("a frame two steps after the switch", () -> mesh.latestSequence() >= switched + 2);
                try (Frame f = mesh.acquire()) {
                    assertTrue(f.sequence() >= switched + 2);
                    assertEquals(cpu, f.hasSkinnedMesh(),
                            () -> "frame " + f + " after switching CPU skinning to " + cpu);
                    assertNull(checker.problem(f));
                }
            }
            assertNull(mesh.failure());
            assertTrue(mesh.isRunning());
        }
    }

    @Test
    void aSkinnerWrittenFromTheFrameLayoutsReproducesTheHumanoid() throws Exception {
        reproducesTheCpuMesh("characters/humanoid-walk.dae", false);
    }

    @Test
    void aSkinnerWrittenFromTheFrameLayoutsReproducesTheScaledTentacle() throws Exception {
        reproducesTheCpuMesh("creatures/tentacle-wave.dae", true);
    }

    /**
     * Steps an asset by hand through its clip with LBS and with DQS and, at each step, skins the
     * frame's bind-shape mesh from the frame's own palette with {@link #layoutSkin} (influences
     * read from the model's {@link Skin}, not from the runtime geometry) and compares with the
     * CPU-skinned positions and normals of the same frame.
     */
    private static void reproducesTheCpuMesh(String asset, boolean expectScale) throws Exception {
        Model model = ColladaImporter.read(TestPaths.asset(asset));
        boolean sawScale = false;
        for (SkinningMethod method : LBS_AND_DQS) {
            AnimationConfig config = new AnimationConfig();
            config.setMethod(method);
            try (SkeletalAnimatedMesh mesh = SkeletalAnimatedMesh.of(model, model.clips().get(0).name(), config)) {
                for (int step = 0; step < 6; step++) {
                    mesh.step(0.37);
                    try (Frame f = mesh.acquire()) {
                        for (int g = 0; g < f.geometryCount(); g++) {
                            sawScale |= f.palette(g).hasScale();
                            compare(asset, f, g, mesh.geometries().get(g));
                        }
                    }
                }
            }
        }
        if (expectScale) {
            assertTrue(sawScale, asset + ": no frame had a scaled joint, so the scale layout went untested");
        }
    }

    private static void compare(String asset, Frame f, int g, SkinnedGeometry geometry) {
        MeshInstance instance = geometry.instance();
        assertTrue(instance.isSkinned(), asset + ": expected skinned meshes only");
        Mesh mesh = instance.mesh();
        double size = diagonal(mesh.positions());
        double[] out = new double[6];
        float[] positions = f.positions(g);
        float[] normals = f.normals(g);
        float[] meshNormals = mesh.normals();
        for (int v = 0; v < mesh.vertexCount(); v++) {
            int p = mesh.vertexPosition(v);
            double[] n = mesh.hasNormals()
                    ? new double[] {meshNormals[3 * v], meshNormals[3 * v + 1], meshNormals[3 * v + 2]}
                    : new double[3];
            layoutSkin(f, g, instance.skin(), p, mesh.positions(), n, out);
            int point = geometry.pointOfPosition(p);
            for (int c = 0; c < 3; c++) {
                double error = Math.abs(out[c] - positions[3 * point + c]);
                if (error > POSITION_TOLERANCE * size) {
                    fail(asset + " " + f + ": position " + p + " component " + c + " is " + positions[3 * point + c]
                            + ", the layout skinner gives " + out[c]);
                }
                // Vertex v is point v (SkinnedGeometry: render vertices first, in order).
                if (mesh.hasNormals() && Math.abs(out[3 + c] - normals[3 * v + c]) > NORMAL_TOLERANCE) {
                    fail(asset + " " + f + ": normal of vertex " + v + " component " + c + " is "
                            + normals[3 * v + c] + ", the layout skinner gives " + out[3 + c]);
                }
            }
        }
    }

    /**
     * Skins one position as a shader author would from {@link Frame}'s class comment alone: LBS
     * from the row-major 3x4 matrices; DQS from the blended scale parts (when the frame has
     * scale) and the dual quaternions (real x y z w, dual x y z w), sign-aligned with the
     * dominant influence. Writes the position and the normal (inverse transpose, unit) to out.
     */
    private static void layoutSkin(Frame f, int g, Skin skin, int p, float[] bindPositions, double[] n,
            double[] out) {
        int start = skin.influenceStart(p);
        int count = skin.influenceCount(p);
        double sum = 0;
        for (int k = 0; k < count; k++) {
            sum += skin.influenceWeight(start + k);
        }
        int[] joints;
        double[] weights;
        if (count == 0 || Math.abs(sum) <= 1e-12) {
            joints = new int[] {skin.jointCount()}; // the bind-shape pseudo-joint
            weights = new double[] {1};
        } else {
            joints = new int[count];
            weights = new double[count];
            for (int k = 0; k < count; k++) {
                int j = skin.influenceJoint(start + k);
                joints[k] = j < 0 ? skin.jointCount() : j;
                weights[k] = skin.influenceWeight(start + k) / sum;
            }
        }
        double px = bindPositions[3 * p];
        double py = bindPositions[3 * p + 1];
        double pz = bindPositions[3 * p + 2];
        if (f.method() == SkinningMethod.LBS) {
            double[] m = blend(f.palette(g).matrices(), joints, weights);
            apply(m, px, py, pz, n, out);
            return;
        }
        double[] p1 = {px, py, pz, n[0], n[1], n[2]};
        if (f.palette(g).hasScale()) {
            apply(blend(f.palette(g).scales(), joints, weights), px, py, pz, n, p1);
        }
        float[] dq = f.palette(g).dualQuaternions();
        int pivot = 0;
        for (int k = 1; k < joints.length; k++) {
            if (weights[k] > weights[pivot]) {
                pivot = k;
            }
        }
        double[] b = new double[8];
        int o0 = 8 * joints[pivot];
        for (int k = 0; k < joints.length; k++) {
            int o = 8 * joints[k];
            double dot = dq[o0] * dq[o] + dq[o0 + 1] * dq[o + 1] + dq[o0 + 2] * dq[o + 2] + dq[o0 + 3] * dq[o + 3];
            double w = dot < 0 ? -weights[k] : weights[k];
            for (int i = 0; i < 8; i++) {
                b[i] += w * dq[o + i];
            }
        }
        double len = Math.sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2] + b[3] * b[3]);
        double rx = b[0] / len, ry = b[1] / len, rz = b[2] / len, rw = b[3] / len;
        double dx = b[4] / len, dy = b[5] / len, dz = b[6] / len, dw = b[7] / len;
        // t = 2 (r.w d.xyz - d.w r.xyz + r.xyz x d.xyz)
        double tx = 2 * (rw * dx - dw * rx + (ry * dz - rz * dy));
        double ty = 2 * (rw * dy - dw * ry + (rz * dx - rx * dz));
        double tz = 2 * (rw * dz - dw * rz + (rx * dy - ry * dx));
        rotate(rx, ry, rz, rw, p1[0], p1[1], p1[2], out, 0);
        out[0] += tx;
        out[1] += ty;
        out[2] += tz;
        rotate(rx, ry, rz, rw, p1[3], p1[4], p1[5], out, 3);
    }

    /** The weighted sum of 3x4 row-major matrices. */
    private static double[] blend(float[] matrices, int[] joints, double[] weights) {
        double[] m = new double[12];
        for (int k = 0; k < joints.length; k++) {
            for (int i = 0; i < 12; i++) {
                m[i] += weights[k] * matrices[12 * joints[k] + i];
            }
        }
        return m;
    }

    /** out[0..3) = m (p, 1); out[3..6) = the unit inverse transpose of m's 3x3 part times n. */
    private static void apply(double[] m, double px, double py, double pz, double[] n, double[] out) {
        out[0] = m[0] * px + m[1] * py + m[2] * pz + m[3];
        out[1] = m[4] * px + m[5] * py + m[6] * pz + m[7];
        out[2] = m[8] * px + m[9] * py + m[10] * pz + m[11];
        // The cofactor matrix: det(A) times the inverse transpose, the scale normalised away (and,
        // as in the kernels, a reflection's sign kept, so normals follow the triangles' winding).
        double a = m[0], b = m[1], c = m[2], d = m[4], e = m[5], f = m[6], g = m[8], h = m[9], i = m[10];
        double nx = (e * i - f * h) * n[0] + (f * g - d * i) * n[1] + (d * h - e * g) * n[2];
        double ny = (c * h - b * i) * n[0] + (a * i - c * g) * n[1] + (b * g - a * h) * n[2];
        double nz = (b * f - c * e) * n[0] + (c * d - a * f) * n[1] + (a * e - b * d) * n[2];
        double length = Math.sqrt(nx * nx + ny * ny + nz * nz);
        double inv = length > 0 ? 1 / length : 0;
        out[3] = nx * inv;
        out[4] = ny * inv;
        out[5] = nz * inv;
    }

    /** v' = v + 2 r.xyz x (r.xyz x v + r.w v), written to out at offset o. */
    private static void rotate(double rx, double ry, double rz, double rw, double vx, double vy, double vz,
            double[] out, int o) {
        double cx = ry * vz - rz * vy + rw * vx;
        double cy = rz * vx - rx * vz + rw * vy;
        double cz = rx * vy - ry * vx + rw * vz;
        out[o] = vx + 2 * (ry * cz - rz * cy);
        out[o + 1] = vy + 2 * (rz * cx - rx * cz);
        out[o + 2] = vz + 2 * (rx * cy - ry * cx);
    }

    private static double diagonal(float[] positions) {
        double[] lo = {Double.MAX_VALUE, Double.MAX_VALUE, Double.MAX_VALUE};
        double[] hi = {-Double.MAX_VALUE, -Double.MAX_VALUE, -Double.MAX_VALUE};
        for (int i = 0; i < positions.length; i++) {
            lo[i % 3] = Math.min(lo[i % 3], positions[i]);
            hi[i % 3] = Math.max(hi[i % 3], positions[i]);
        }
        return Math.sqrt(Math.pow(hi[0] - lo[0], 2) + Math.pow(hi[1] - lo[1], 2) + Math.pow(hi[2] - lo[2], 2));
    }

    private static void await(String what, BooleanSupplier condition) throws InterruptedException {
        long deadline = System.nanoTime() + 10_000_000_000L;
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() - deadline > 0) {
                fail("timed out after 10 s waiting for " + what);
            }
            Thread.sleep(1);
        }
    }
}
