package org.skinlab.skinning;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.joml.Matrix4f;
import org.junit.jupiter.api.Test;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.collada.ColladaImporter;
import org.skinlab.model.Model;
import org.skinlab.skinning.reference.IndependentSpline;
import org.skinlab.testing.TestPaths;
import org.skinlab.internal.metrics.ArtifactMetrics;

/**
 * The spline kernel against {@link IndependentSpline}, the double-precision evaluation written
 * from the formulas, on a synthetic chain, the bend cylinder and the characters.
 *
 * <p>Tolerances: positions within 2e-6 of the model's size and unit normals within 1e-5 (the
 * float kernel rounds a few times per step: the curve, the slerp through acos and sin, two
 * quaternion products; measured at most 1.5e-7 of the size and 1.2e-6 on these models, so the
 * bounds leave a factor of ten for other JITs' rounding), curve parameters within 1e-6 (float
 * storage of a double search).
 */
class SplineSkinningTest {
    private static final double POSITION_TOLERANCE = 2e-6;
    private static final double NORMAL_TOLERANCE = 1e-5;

    /**
     * Three joints up the Y axis (heads at y = 0, 1, 2, a leaf to y = 3), a tube of radius 0.3
     * around it, 16 points per ring every 0.05, weights ramping over 0.3 either side of each joint.
     */
    static SkinnedGeometry chain() {
        int rings = 61;
        int around = 16;
        int points = rings * around;
        float[] positions = new float[3 * points];
        float[] normals = new float[3 * points];
        int[] joints = new int[2 * points];
        float[] weights = new float[2 * points];
        for (int r = 0; r < rings; r++) {
            float y = 0.05f * r;
            int lower = Math.min(2, (int) Math.floor(y));
            int near = Math.round(y);
            float t = (y - near + 0.3f) / 0.6f;
            for (int s = 0; s < around; s++) {
                int i = r * around + s;
                double angle = 2 * Math.PI * s / around;
                positions[3 * i] = (float) (0.3 * Math.cos(angle));
                positions[3 * i + 1] = y;
                positions[3 * i + 2] = (float) (0.3 * Math.sin(angle));
                normals[3 * i] = (float) Math.cos(angle);
                normals[3 * i + 2] = (float) Math.sin(angle);
                if (near >= 1 && near <= 2 && t > 0f && t < 1f) {
                    joints[2 * i] = near - 1;
                    joints[2 * i + 1] = near;
                    weights[2 * i] = 1f - t;
                    weights[2 * i + 1] = t;
                } else {
                    joints[2 * i] = lower;
                    joints[2 * i + 1] = lower;
                    weights[2 * i] = 1f;
                }
            }
        }
        float[] bind = new float[48];
        for (int j = 0; j < 3; j++) {
            new Matrix4f().translation(0, -j, 0).get(bind, 16 * j);
        }
        return SkinnedGeometry.fromArrays(positions, normals, 2, joints, weights, bind, new int[] {-1, 0, 1});
    }

    /** The chain's pose: joint 1 bent 80 degrees about X at its head, joint 2 twisted 60 degrees and bent 30 about Z. */
    static JointPalette chainPose(SkinnedGeometry g) {
        JointPalette palette = g.newPalette();
        Matrix4f m1 = new Matrix4f().translation(0, 1, 0).rotateX((float) Math.toRadians(80)).translate(0, -1, 0);
        Matrix4f m2 = new Matrix4f(m1).translate(0, 2, 0).rotateZ((float) Math.toRadians(30))
                .rotateY((float) Math.toRadians(60)).translate(0, -2, 0);
        palette.setMatrix(1, m1);
        palette.setMatrix(2, m2);
        palette.prepareAll();
        return palette;
    }

    static IndependentSpline reference(SkinnedGeometry g, float stiffness) {
        Bones bones = g.bones();
        int joints = g.jointCount();
        int[] parents = new int[joints];
        int[] tailJoints = new int[joints];
        double[] heads = new double[3 * joints];
        double[] tails = new double[3 * joints];
        for (int j = 0; j < joints; j++) {
            parents[j] = bones.parent(j);
            tailJoints[j] = bones.tailJoint(j);
            for (int e = 0; e < 3; e++) {
                heads[3 * j + e] = bones.head(j, e);
                tails[3 * j + e] = bones.tail(j, e);
            }
        }
        float[] w = g.weightArray();
        double[] weights = new double[w.length];
        for (int i = 0; i < w.length; i++) {
            weights[i] = w[i];
        }
        return new IndependentSpline(doubles(g.positionArray()), doubles(g.normalArray()), g.influencesPerPoint(),
                g.jointArray(), weights, parents, tailJoints, heads, tails, g.bindMatrixArray(), stiffness);
    }

    static double[] doubles(float[] a) {
        double[] d = new double[a.length];
        for (int i = 0; i < a.length; i++) {
            d[i] = a[i];
        }
        return d;
    }

    /** Largest position difference over the size, and largest normal difference, of kernel and reference. */
    private static double[] agreement(SkinnedGeometry g, JointPalette palette, IndependentSpline reference) {
        Skinner s = Skinners.scalar(SkinningMethod.SPLINE, g, NormalTransform.INVERSE_TRANSPOSE, PositionSharing.NEVER);
        int n = g.pointCount();
        float[] p = new float[3 * n];
        float[] nn = new float[3 * n];
        s.skinAll(palette, p, nn);
        double[] rp = new double[3 * n];
        double[] rn = new double[3 * n];
        reference.deform(doubles(palette.matrices()), rp, rn);
        double size = ArtifactMetrics.boundsDiagonal(g.positionArray(), g.vertexCount());
        double position = 0;
        double normal = 0;
        for (int i = 0; i < 3 * n; i++) {
            position = Math.max(position, Math.abs(p[i] - rp[i]) / size);
            normal = Math.max(normal, Math.abs(nn[i] - rn[i]));
        }
        return new double[] {position, normal};
    }

    private static void assertAgrees(String what, double[] agreement) {
        System.out.printf("%s: positions %.2e of the size, normals %.2e%n", what, agreement[0], agreement[1]);
        assertTrue(agreement[0] < POSITION_TOLERANCE, what + " positions " + agreement[0]);
        assertTrue(agreement[1] < NORMAL_TOLERANCE, what + " normals " + agreement[1]);
    }

    @Test
    void restPoseKeepsEveryPoint() {
        SkinnedGeometry g = chain();
        JointPalette palette = g.newPalette();
        palette.prepareAll();
        float[] p = new float[3 * g.pointCount()];
        Skinners.scalar(SkinningMethod.SPLINE, g, NormalTransform.INVERSE_TRANSPOSE).skinAll(palette, p,
                new float[p.length]);
        for (int i = 0; i < p.length; i++) {
            assertEquals(g.positionArray()[i], p[i], 1e-6f);
        }
    }

    @Test
    void bindingMatchesTheReferenceSearch() {
        SkinnedGeometry g = chain();
        SplineBinding binding = SplineBinding.of(g);
        IndependentSpline reference = reference(g, SplineBinding.DEFAULT_STIFFNESS);
        int curved = 0;
        for (int i = 0; i < g.pointCount(); i++) {
            for (int k = 0; k < 2; k++) {
                int s = 2 * i + k;
                assertEquals(reference.curveOf(s), binding.curve(i, k), "point " + i);
                assertEquals(reference.parameter(s), binding.x(i, k), 1e-6, "point " + i);
                curved += binding.curve(i, k) >= 0 ? 1 : 0;
            }
        }
        // Points from y = 0.5 to 2.5 (the middles of bones 0 and 2) lie on the curves across joints 1 and 2.
        assertTrue(curved > 2 * 16 * 38, "curved slots " + curved);
        // A point on the joint of a straight chain sits in the middle of its curve (by symmetry).
        int atJoint = 20 * 16;
        assertEquals(1, binding.curve(atJoint, 0) == 1 ? 1 : binding.curve(atJoint, 1));
        assertEquals(0.5f, binding.x(atJoint, 0), 1e-6f);
    }

    @Test
    void chainAgreesWithTheReference() {
        SkinnedGeometry g = chain();
        for (float a : new float[] {1f, 2f, SplineBinding.DEFAULT_STIFFNESS}) {
            JointPalette palette = chainPose(g);
            Skinner s = new ScalarSplineSkinner(g, NormalTransform.INVERSE_TRANSPOSE, SplineBinding.of(g, a));
            int n = g.pointCount();
            float[] p = new float[3 * n];
            float[] nn = new float[3 * n];
            s.skinAll(palette, p, nn);
            double[] rp = new double[3 * n];
            double[] rn = new double[3 * n];
            reference(g, a).deform(doubles(palette.matrices()), rp, rn);
            double worst = 0;
            double worstNormal = 0;
            for (int i = 0; i < 3 * n; i++) {
                worst = Math.max(worst, Math.abs(p[i] - rp[i]));
                worstNormal = Math.max(worstNormal, Math.abs(nn[i] - rn[i]));
            }
            System.out.printf("chain, stiffness %.0f: positions %.2e, normals %.2e%n", a, worst, worstNormal);
            assertTrue(worst < POSITION_TOLERANCE * 3, // the chain is 3 units tall
                    "stiffness " + a + ": " + worst);
            assertTrue(worstNormal < NORMAL_TOLERANCE, "stiffness " + a + ": " + worstNormal);
        }
    }

    @Test
    void bendCylinderAgreesWithTheReference() throws Exception {
        assertModelAgrees("cylinders/cylinder-bend.dae", new float[] {1f, 2f, 4f});
    }

    @Test
    void charactersAgreeWithTheReference() throws Exception {
        assertModelAgrees("characters/humanoid-walk.dae", new float[] {0.25f, 0.6f});
        assertModelAgrees("creatures/tentacle-wave.dae", new float[] {0.5f, 1.25f});
    }

    /**
     * Skinning each shared position once and expanding gives the points' own results, with unit
     * normals (a spline deformation's normal matrix blends rotations, so the expansion must renormalise).
     */
    @Test
    void sharedPositionsGiveThePointsOwnResults() throws Exception {
        SkinnedModel skinned = SkinnedModel.of(ColladaImporter.read(TestPaths.asset("cylinders/cylinder-bend.dae")));
        SkinnedGeometry g = skinned.geometries().get(0);
        assertTrue(g.sharedPositions() != null, "the cylinder's cap rims share positions");
        Skinner shared = Skinners.scalar(SkinningMethod.SPLINE, g, NormalTransform.INVERSE_TRANSPOSE,
                PositionSharing.ALWAYS);
        Skinner direct = Skinners.scalar(SkinningMethod.SPLINE, g, NormalTransform.INVERSE_TRANSPOSE,
                PositionSharing.NEVER);
        assertTrue(Skinners.sharesPositions(shared));
        skinned.pose(3f, RotationInterpolation.SLERP);
        JointPalette palette = skinned.palette(0).prepareAll();
        int n = g.pointCount();
        float[] sp = new float[3 * n], sn = new float[3 * n], dp = new float[3 * n], dn = new float[3 * n];
        shared.skinAll(palette, sp, sn);
        direct.skinAll(palette, dp, dn);
        for (int i = 0; i < n; i++) {
            for (int e = 0; e < 3; e++) {
                assertEquals(dp[3 * i + e], sp[3 * i + e], 1e-6f, "point " + i);
                assertEquals(dn[3 * i + e], sn[3 * i + e], 1e-5f, "normal " + i);
            }
            double len = Math.sqrt(sn[3 * i] * sn[3 * i] + sn[3 * i + 1] * sn[3 * i + 1] + sn[3 * i + 2] * sn[3 * i + 2]);
            assertEquals(1.0, len, 1e-5, "normal " + i + " is unit");
        }
    }

    private static void assertModelAgrees(String asset, float[] times) throws Exception {
        Model model = ColladaImporter.read(TestPaths.asset(asset));
        SkinnedModel skinned = SkinnedModel.of(model);
        for (int g = 0; g < skinned.geometries().size(); g++) {
            SkinnedGeometry geometry = skinned.geometries().get(g);
            IndependentSpline reference = reference(geometry, SplineBinding.DEFAULT_STIFFNESS);
            for (float t : times) {
                skinned.pose(t, RotationInterpolation.SLERP);
                assertAgrees(asset + " geometry " + g + " at " + t + " s",
                        agreement(geometry, skinned.palette(g).prepareAll(), reference));
            }
        }
    }
}
