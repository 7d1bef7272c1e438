package org.skinlab.skinning;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.joml.Quaternionf;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;
import org.skinlab.skinning.reference.IndependentStbs;

/**
 * The scalar stretchable-and-twistable-bones kernels against {@link IndependentStbs} (double
 * precision, from the formulas) on {@link StbsChain}, and against the formulas' closed forms
 * where a pose has one.
 */
class StbsSkinningTest {
    /** Float kernels against the double reference on a 3-unit chain: a few float roundings of unit-sized terms. */
    private static final double POSITION_TOLERANCE = 2e-5;
    private static final double NORMAL_TOLERANCE = 2e-4;
    private static final double TWIST_TOLERANCE = 2e-5;

    static IndependentStbs reference(SkinnedGeometry g) {
        Bones bones = g.bones();
        int n = g.jointCount();
        double[][] heads = new double[n][3];
        double[][] tails = new double[n][3];
        int[] parents = new int[n];
        for (int j = 0; j < n; j++) {
            for (int a = 0; a < 3; a++) {
                heads[j][a] = bones.head(j, a);
                tails[j][a] = bones.tail(j, a);
            }
            parents[j] = bones.parent(j);
        }
        return new IndependentStbs(g.bindMatrixArray(), heads, tails, parents);
    }

    /** Largest position and normal differences of the kernel from the reference, over all points. */
    static double[] compare(SkinnedGeometry g, JointPalette palette, SkinningMethod method, IndependentStbs ref) {
        int n = g.pointCount();
        float[] p = new float[3 * n];
        float[] nn = new float[3 * n];
        Skinners.scalar(method, g, NormalTransform.INVERSE_TRANSPOSE, PositionSharing.NEVER).skinAll(palette, p, nn);
        ref.pose(palette.matrices());
        int width = g.influencesPerPoint();
        double worstP = 0;
        double worstN = 0;
        for (int i = 0; i < n; i++) {
            int[] js = new int[width];
            double[] ws = new double[width];
            for (int k = 0; k < width; k++) {
                js[k] = g.jointArray()[width * i + k];
                ws[k] = g.weightArray()[width * i + k];
            }
            double[] rest = {g.positionArray()[3 * i], g.positionArray()[3 * i + 1], g.positionArray()[3 * i + 2]};
            double[] normal = {g.normalArray()[3 * i], g.normalArray()[3 * i + 1], g.normalArray()[3 * i + 2]};
            double[] e = ref.skin(rest, normal, js, ws, method == SkinningMethod.STBS_DQS);
            for (int a = 0; a < 3; a++) {
                worstP = Math.max(worstP, Math.abs(e[a] - p[3 * i + a]));
                worstN = Math.max(worstN, Math.abs(e[3 + a] - nn[3 * i + a]));
            }
        }
        return new double[] {worstP, worstN};
    }

    @Test
    void bothBlendsAgreeWithTheReferenceOnRandomPosesWithAndWithoutScale() {
        SkinnedGeometry g = StbsChain.geometry();
        JointPalette palette = g.newPalette();
        IndependentStbs ref = reference(g);
        Random random = new Random(21);
        for (int pose = 0; pose < 20; pose++) {
            StbsChain.randomPose(palette, random, 1.4f, pose % 2 == 1);
            for (SkinningMethod m : new SkinningMethod[] {SkinningMethod.STBS_LBS, SkinningMethod.STBS_DQS}) {
                double[] d = compare(g, palette, m, ref);
                assertTrue(d[0] < POSITION_TOLERANCE, m + " pose " + pose + ": position off by " + d[0]);
                assertTrue(d[1] < NORMAL_TOLERANCE, m + " pose " + pose + ": normal off by " + d[1]);
            }
        }
    }

    @Test
    void theBoneRowsTwistIsTheReferencesGeometricTwist() {
        SkinnedGeometry g = StbsChain.geometry();
        JointPalette palette = g.newPalette();
        IndependentStbs ref = reference(g);
        Random random = new Random(5);
        for (int pose = 0; pose < 20; pose++) {
            StbsChain.randomPose(palette, random, 1.4f, pose % 2 == 1);
            ref.pose(palette.matrices());
            for (int j = 0; j < 3; j++) {
                assertEquals(ref.twist(j), palette.boneRows()[JointPalette.BONE_FLOATS * j + 3], TWIST_TOLERANCE,
                        "pose " + pose + " joint " + j);
            }
        }
    }

    /** Joint 1 turned by 120 degrees about its own axis: a point at fraction e of bone 1 (weight 1 there) turns by e 120. */
    @Test
    void aTwistSpreadsLinearlyAlongTheBone() {
        SkinnedGeometry g = StbsChain.geometry();
        JointPalette palette = g.newPalette();
        float angle = (float) Math.toRadians(120);
        StbsChain.pose(palette, new Quaternionf[] {new Quaternionf(), new Quaternionf().rotateY(angle), new Quaternionf()},
                new Vector3f[] {new Vector3f(1), new Vector3f(1), new Vector3f(1)}, new Vector3f());
        for (SkinningMethod m : new SkinningMethod[] {SkinningMethod.STBS_LBS, SkinningMethod.STBS_DQS}) {
            float[] p = skin(g, palette, m);
            // Rings 26..34 (y 1.3 .. 1.7) have weight 1 on joint 1; point 0 of a ring starts at +X.
            for (int ring = 26; ring <= 34; ring++) {
                int i = ring * StbsChain.AROUND;
                double e = StbsChain.ringY(ring) - 1;
                double expected = e * angle;
                // rotateY turns +X towards -Z.
                double turned = Math.atan2(-p[3 * i + 2], p[3 * i]);
                assertEquals(expected, turned, 1e-5, m + " ring " + ring);
                assertEquals(StbsChain.RADIUS, Math.hypot(p[3 * i], p[3 * i + 2]), 1e-6, m + " radius");
                assertEquals(StbsChain.ringY(ring), p[3 * i + 1], 1e-6, m + " height");
            }
        }
    }

    /**
     * Joint 1 stretched 1.5x along its axis, joint 2 scaled back (so it is rigid, moved up by 0.5):
     * points of bone 1 (weight 1) stretch evenly, points beyond its tail move up by 0.5 for every
     * influence, whatever their weights, and no ring changes its radius.
     */
    @Test
    void aStretchIsEvenAlongTheBoneAndRigidBeyondItsTail() {
        SkinnedGeometry g = StbsChain.geometry();
        JointPalette palette = g.newPalette();
        StbsChain.pose(palette, new Quaternionf[] {new Quaternionf(), new Quaternionf(), new Quaternionf()},
                new Vector3f[] {new Vector3f(1), new Vector3f(1, 1.5f, 1), new Vector3f(1, 1 / 1.5f, 1)}, new Vector3f());
        for (SkinningMethod m : new SkinningMethod[] {SkinningMethod.STBS_LBS, SkinningMethod.STBS_DQS}) {
            float[] p = skin(g, palette, m);
            for (int ring = 0; ring < StbsChain.RINGS; ring++) {
                int i = ring * StbsChain.AROUND;
                float y = StbsChain.ringY(ring);
                assertEquals(StbsChain.RADIUS, Math.hypot(p[3 * i], p[3 * i + 2]), 1e-6, m + " ring " + ring);
                if (y >= 1.25f && y <= 1.75f) {
                    assertEquals(1 + 1.5 * (y - 1), p[3 * i + 1], 1e-5, m + " ring " + ring);
                } else if (y >= 2f) {
                    assertEquals(y + 0.5, p[3 * i + 1], 1e-5, m + " ring " + ring);
                }
            }
        }
    }

    private static float[] skin(SkinnedGeometry g, JointPalette palette, SkinningMethod m) {
        float[] p = new float[3 * g.pointCount()];
        float[] n = new float[3 * g.pointCount()];
        Skinners.scalar(m, g, NormalTransform.INVERSE_TRANSPOSE, PositionSharing.NEVER).skinAll(palette, p, n);
        return p;
    }
}
