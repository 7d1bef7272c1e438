package org.skinlab.simd;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import com.sun.management.ThreadMXBean;

import java.lang.management.ManagementFactory;
import java.util.Arrays;
import java.util.Random;

import org.joml.Matrix4f;
import org.joml.Quaternionf;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.api.Test;
import org.skinlab.skinning.JointPalette;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.PositionSharing;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.Skinner;
import org.skinlab.skinning.Skinners;
import org.skinlab.skinning.SkinningMethod;

/**
 * The Vector API stretchable-bones kernels against core's scalar ones on random chains (every
 * joint the child of the one before, so bones have tails, twists and stretch offsets), with and
 * without scale. Tolerance as in {@link VectorSkinnerTest}, 2e-5 relative to max(1, |scalar|):
 * besides fused multiply-adds the vector kernels take sin and cos from polynomials good to 6e-8
 * (checked below) where the scalar ones call Math.sin and Math.cos.
 */
class VectorStbsSkinnerTest {
    private static final float TOLERANCE = 2e-5f;

    /** {@code points} random points near a chain of {@code joints} joints along Y, one unit apart. */
    private static SkinnedGeometry chain(long seed, int points, int width, int joints) {
        Random r = new Random(seed);
        float[] pos = new float[3 * points];
        float[] nrm = new float[3 * points];
        int[] jnt = new int[width * points];
        float[] w = new float[width * points];
        for (int i = 0; i < points; i++) {
            float y = joints * r.nextFloat();
            pos[3 * i] = r.nextFloat() - 0.5f;
            pos[3 * i + 1] = y;
            pos[3 * i + 2] = r.nextFloat() - 0.5f;
            float len = (float) Math.hypot(pos[3 * i], pos[3 * i + 2]);
            nrm[3 * i] = pos[3 * i] / len;
            nrm[3 * i + 2] = pos[3 * i + 2] / len;
            int near = Math.min(joints - 1, (int) y);
            float sum = 0;
            for (int k = 0; k < width; k++) {
                jnt[width * i + k] = Math.max(0, Math.min(joints - 1, near + (k + 1) / 2 * (k % 2 == 0 ? 1 : -1)));
                // The last slot is padding (weight 0) for every point of every other block and
                // for every third point elsewhere: blocks skip it only where no lane needs it.
                boolean padding = k > 0 && k == width - 1 && ((i / 8) % 2 == 0 || i % 3 == 0);
                w[width * i + k] = padding ? 0f : k == 0 ? 2f : 0.05f + r.nextFloat();
                sum += w[width * i + k];
            }
            for (int k = 0; k < width; k++) {
                w[width * i + k] /= sum;
            }
        }
        float[] bind = new float[16 * joints];
        int[] parents = new int[joints];
        for (int j = 0; j < joints; j++) {
            new Matrix4f().translation(0, -j, 0).get(bind, 16 * j);
            parents[j] = j - 1;
        }
        return SkinnedGeometry.fromArrays(pos, nrm, width, jnt, w, bind, parents);
    }

    /** Local rotations up to 2.5 rad (twists up to pi occur), scales 0.6..1.6 when {@code scaled}. */
    private static JointPalette pose(SkinnedGeometry g, long seed, boolean scaled) {
        Random r = new Random(seed);
        JointPalette palette = g.newPalette();
        Matrix4f world = new Matrix4f();
        for (int j = 0; j < palette.jointCount(); j++) {
            Quaternionf q = new Quaternionf().rotateAxis(2.5f * r.nextFloat(), r.nextFloat() - 0.5f, r.nextFloat() - 0.5f,
                    r.nextFloat() - 0.5f);
            world.translate(0, j == 0 ? 0 : 1, 0).rotate(q);
            if (scaled) {
                world.scale(0.6f + r.nextFloat(), 0.6f + r.nextFloat(), 0.6f + r.nextFloat());
            }
            palette.setMatrix(j, new Matrix4f(world).translate(0, -j, 0));
        }
        palette.prepareAll();
        return palette;
    }

    @ParameterizedTest
    @CsvSource({"STBS_LBS, INVERSE_TRANSPOSE, 4, false", "STBS_LBS, BLENDED_MATRIX, 3, true",
        "STBS_LBS, INVERSE_TRANSPOSE, 2, true", "STBS_DQS, INVERSE_TRANSPOSE, 4, true",
        "STBS_DQS, BLENDED_MATRIX, 3, false", "STBS_DQS, INVERSE_TRANSPOSE, 1, false"})
    void agreesWithScalarForEveryRange(SkinningMethod method, NormalTransform normals, int width, boolean scaled) {
        SkinnedGeometry g = chain(width, 203, width, 6);
        Skinner vector = new VectorSkinnerProvider().create(method, g.boundFor(method), normals);
        assertTrue(vector instanceof VectorStbsSkinner, "the provider offers the vector kernel for " + method);
        Skinner scalar = Skinners.scalar(method, g.boundFor(method), normals, PositionSharing.NEVER);
        for (int seed = 0; seed < 5; seed++) {
            JointPalette palette = pose(g, 100 * width + seed, scaled);
            for (int[] range : new int[][] {{0, 203}, {0, 200}, {3, 77}, {8, 16}, {9, 14}}) {
                assertAgrees(vector, scalar, palette, range[0], range[1]);
            }
        }
    }

    /**
     * {@link Skinner#skinDeformations} (the route of position sharing) against the scalar kernel's deformations:
     * the same records (N's columns, p, padding) for every range, nothing written outside it.
     */
    @ParameterizedTest
    @CsvSource({"STBS_LBS, INVERSE_TRANSPOSE, 4, false", "STBS_LBS, BLENDED_MATRIX, 3, true",
        "STBS_LBS, INVERSE_TRANSPOSE, 2, true", "STBS_LBS, BLENDED_MATRIX, 1, false",
        "STBS_DQS, INVERSE_TRANSPOSE, 4, true", "STBS_DQS, BLENDED_MATRIX, 3, false",
        "STBS_DQS, INVERSE_TRANSPOSE, 1, false", "STBS_DQS, BLENDED_MATRIX, 2, true"})
    void deformationsAgreeWithScalarForEveryRange(SkinningMethod method, NormalTransform normals, int width, boolean scaled) {
        SkinnedGeometry g = chain(width + 10, 203, width, 6);
        Skinner vector = new VectorSkinnerProvider().create(method, g.boundFor(method), normals);
        assertTrue(vector instanceof VectorStbsSkinner, "the provider offers the vector kernel for " + method);
        Skinner scalar = Skinners.scalar(method, g.boundFor(method), normals, PositionSharing.NEVER);
        for (int seed = 0; seed < 5; seed++) {
            JointPalette palette = pose(g, 300 * width + seed, scaled);
            for (int[] range : new int[][] {{0, 203}, {0, 200}, {3, 77}, {8, 16}, {9, 14}}) {
                int n = Skinner.DEFORMATION_FLOATS * g.pointCount();
                float[] vf = nan(n), sf = nan(n);
                vector.skinDeformations(palette, vf, range[0], range[1]);
                scalar.skinDeformations(palette, sf, range[0], range[1]);
                for (int i = 0; i < n; i++) {
                    int point = i / Skinner.DEFORMATION_FLOATS;
                    if (point < range[0] || point >= range[1]) {
                        assertTrue(Float.isNaN(vf[i]), "float " + i + " outside the range was written");
                        continue;
                    }
                    check(vector, "deformation", i, vf[i], sf[i]);
                }
            }
        }
    }

    /**
     * The per-frame path allocates nothing: once C2 has compiled every pass (10 x 2 000 warm-up
     * calls of 25 blocks each, repeated up to 5 times for a compiler queue that is slow to get
     * there), 2 000 calls allocate fewer bytes than calls, the smallest object being 16 bytes. A
     * vector boxed at a call C2 did not inline, or a gather left to the Vector API's Java fallback,
     * costs hundreds of bytes per block. From JDK 25 (what the CLI runs): JDK 17's C2 leaves some of
     * the kernel's lane permutations to that fallback (JFR: {@code AbstractShuffle.toArray},
     * {@code Float256Vector.bOp} under the transpose), about 40 KB per call here.
     */
    @ParameterizedTest
    @CsvSource({"STBS_LBS, INVERSE_TRANSPOSE", "STBS_LBS, BLENDED_MATRIX", "STBS_DQS, INVERSE_TRANSPOSE",
        "STBS_DQS, BLENDED_MATRIX"})
    void skinningAllocatesNothingOnceCompiled(SkinningMethod method, NormalTransform normals) {
        assumeTrue(Runtime.version().feature() >= 25, "JDK 17's C2 leaves some lane permutations to Java code");
        int calls = 2_000;
        SkinnedGeometry g = chain(7, 200, 4, 6);
        Skinner vector = new VectorSkinnerProvider().create(method, g.boundFor(method), normals);
        assertTrue(vector instanceof VectorStbsSkinner, "the provider offers the vector kernel for " + method);
        JointPalette palette = pose(g, 7, true);
        float[] p = new float[3 * 200];
        float[] n = new float[3 * 200];
        long bytes = allocatedBytes(() -> vector.skin(palette, p, n, 0, 200), calls);
        assertTrue(bytes < calls, method + " " + normals + ": " + bytes + " bytes allocated in " + calls + " calls");
    }

    /** {@link Skinner#skinDeformations} allocates nothing either (see {@link #skinningAllocatesNothingOnceCompiled}). */
    @ParameterizedTest
    @CsvSource({"STBS_LBS, INVERSE_TRANSPOSE", "STBS_LBS, BLENDED_MATRIX", "STBS_DQS, INVERSE_TRANSPOSE",
        "STBS_DQS, BLENDED_MATRIX"})
    void deformationsAllocateNothingOnceCompiled(SkinningMethod method, NormalTransform normals) {
        assumeTrue(Runtime.version().feature() >= 25, "JDK 17's C2 leaves some lane permutations to Java code");
        int calls = 2_000;
        SkinnedGeometry g = chain(7, 200, 4, 6);
        Skinner vector = new VectorSkinnerProvider().create(method, g.boundFor(method), normals);
        assertTrue(vector instanceof VectorStbsSkinner, "the provider offers the vector kernel for " + method);
        JointPalette palette = pose(g, 7, true);
        float[] f = new float[Skinner.DEFORMATION_FLOATS * 200];
        long bytes = allocatedBytes(() -> vector.skinDeformations(palette, f, 0, 200), calls);
        assertTrue(bytes < calls, method + " " + normals + ": " + bytes + " bytes allocated in " + calls + " calls");
    }

    /**
     * The fewest bytes this thread allocated in {@code calls} runs of {@code r}, each measurement
     * after 10 {@code calls} more warm-up runs, over up to 5 rounds (the first below {@code calls} ends them).
     */
    private static long allocatedBytes(Runnable r, int calls) {
        ThreadMXBean threads = (ThreadMXBean) ManagementFactory.getThreadMXBean();
        long id = Thread.currentThread().getId();
        long fewest = Long.MAX_VALUE;
        for (int round = 0; round < 5 && fewest >= calls; round++) {
            for (int i = 0; i < 10 * calls; i++) {
                r.run();
            }
            long before = threads.getThreadAllocatedBytes(id);
            for (int i = 0; i < calls; i++) {
                r.run();
            }
            fewest = Math.min(fewest, threads.getThreadAllocatedBytes(id) - before);
        }
        return fewest;
    }

    @Test
    void thePolynomialsMatchSinAndCosOverTheHalfAngleRange() {
        float[] a = new float[8];
        float worst = 0;
        for (int i = 0; i <= 8000; i += 8) {
            for (int l = 0; l < 8; l++) {
                a[l] = (float) (-Math.PI / 2 + Math.PI * (i + l) / 8000.0);
            }
            float[] scratch = Arrays.copyOf(a, 24);
            StbsInfluenceLanes.sinCos(scratch, 0, 8, 16);
            float[] s = Arrays.copyOfRange(scratch, 8, 16);
            float[] c = Arrays.copyOfRange(scratch, 16, 24);
            for (int l = 0; l < 8; l++) {
                worst = Math.max(worst, (float) Math.abs(s[l] - Math.sin(a[l])));
                worst = Math.max(worst, (float) Math.abs(c[l] - Math.cos(a[l])));
            }
        }
        assertTrue(worst < 3e-7f, "polynomial sin/cos off by " + worst);
    }

    private static void assertAgrees(Skinner vector, Skinner scalar, JointPalette palette, int from, int to) {
        int n = vector.geometry().pointCount();
        float[] vp = nan(3 * n), vn = nan(3 * n), sp = nan(3 * n), sn = nan(3 * n);
        vector.skin(palette, vp, vn, from, to);
        scalar.skin(palette, sp, sn, from, to);
        for (int i = 0; i < 3 * n; i++) {
            if (i < 3 * from || i >= 3 * to) {
                assertTrue(Float.isNaN(vp[i]) && Float.isNaN(vn[i]), "float " + i + " outside the range was written");
                continue;
            }
            check(vector, "position", i, vp[i], sp[i]);
            check(vector, "normal", i, vn[i], sn[i]);
        }
    }

    private static void check(Skinner k, String what, int i, float actual, float expected) {
        if (!(Math.abs(actual - expected) <= TOLERANCE * Math.max(1f, Math.abs(expected)))) {
            fail(k.method() + " " + k.normalTransform() + " " + what + " float " + i + ": vector " + actual + ", scalar "
                    + expected);
        }
    }

    private static float[] nan(int n) {
        float[] a = new float[n];
        Arrays.fill(a, Float.NaN);
        return a;
    }
}
