package org.skinlab.skinning;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;

import org.joml.Matrix3f;
import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;

/**
 * {@link NormalTransform#INVERSE_TRANSPOSE} in the scalar kernels (directly and through
 * {@link Skinner#skinDeformations} and {@link DeformationExpansion}) against JOML's own
 * {@code invert().transpose()} of the joint matrix (an independent computation), on a single joint
 * that rotates and scales non-uniformly, so that the inverse-transpose, the inverse and the matrix
 * itself all move a normal differently. Tolerance 1e-5: a handful of float operations on unit
 * vectors.
 */
class InverseTransposeNormalsTest {
    private static final float[] NORMALS = {1, 0, 0, 0, 1, 0, 0, 0, 1, 0.6f, 0, 0.8f, 0, -0.28f, 0.96f};

    private static SkinnedGeometry oneJoint() {
        int n = NORMALS.length / 3;
        float[] positions = new float[3 * n];
        int[] joints = new int[n];
        float[] weights = new float[n];
        java.util.Arrays.fill(weights, 1f);
        return SkinnedGeometry.fromArrays(positions, NORMALS.clone(), 1, joints, weights,
                new Matrix4f().get(new float[16])).withCentresOfRotation();
    }

    private static void assertInverseTranspose(Matrix4f m, float[] out) {
        Matrix3f it = new Matrix3f();
        m.get3x3(it).invert().transpose();
        for (int i = 0; i < NORMALS.length / 3; i++) {
            Vector3f e = it.transform(new Vector3f(NORMALS[3 * i], NORMALS[3 * i + 1], NORMALS[3 * i + 2])).normalize();
            assertEquals(e.x, out[3 * i], 1e-5f, "x of normal " + i);
            assertEquals(e.y, out[3 * i + 1], 1e-5f, "y of normal " + i);
            assertEquals(e.z, out[3 * i + 2], 1e-5f, "z of normal " + i);
        }
    }

    @Test
    void lbsMovesNormalsByTheInverseTransposeOfARotatedScaledJoint() {
        Matrix4f m = new Matrix4f().rotateXYZ(0.7f, -0.4f, 1.1f).scale(2f, 1f, 0.5f).setTranslation(0.1f, 0.2f, 0.3f);
        SkinnedGeometry g = oneJoint();
        JointPalette palette = g.newPalette();
        palette.setMatrix(0, m);
        float[] p = new float[NORMALS.length];
        float[] n = new float[NORMALS.length];
        new ScalarLbsSkinner(g, NormalTransform.INVERSE_TRANSPOSE).skinAll(palette, p, n);
        assertInverseTranspose(m, n);
    }

    @Test
    void lbsRotatesNormalsWithARigidJoint() {
        // For a rotation the inverse-transpose is the rotation itself (not its inverse).
        Matrix4f m = new Matrix4f().rotateXYZ(0.3f, 1.2f, -0.5f).setTranslation(1f, 2f, 3f);
        SkinnedGeometry g = oneJoint();
        JointPalette palette = g.newPalette();
        palette.setMatrix(0, m);
        float[] p = new float[NORMALS.length];
        float[] n = new float[NORMALS.length];
        new ScalarLbsSkinner(g, NormalTransform.INVERSE_TRANSPOSE).skinAll(palette, p, n);
        for (int i = 0; i < NORMALS.length / 3; i++) {
            Vector3f e = m.transformDirection(new Vector3f(NORMALS[3 * i], NORMALS[3 * i + 1], NORMALS[3 * i + 2]));
            assertEquals(e.x, n[3 * i], 1e-5f);
            assertEquals(e.y, n[3 * i + 1], 1e-5f);
            assertEquals(e.z, n[3 * i + 2], 1e-5f);
        }
    }

    @Test
    void dqsScalePhaseMovesNormalsByTheInverseTransposeToo() {
        // One joint: DQS's split M = D S reproduces M exactly, so the normal must be M^-T n.
        Matrix4f m = new Matrix4f().rotateXYZ(-0.2f, 0.9f, 0.4f).scale(0.5f, 1.5f, 1f).setTranslation(0.4f, 0f, -1f);
        SkinnedGeometry g = oneJoint();
        JointPalette palette = g.newPalette();
        palette.setMatrix(0, m);
        palette.prepareAll();
        float[] p = new float[NORMALS.length];
        float[] n = new float[NORMALS.length];
        new ScalarDqsSkinner(g, NormalTransform.INVERSE_TRANSPOSE).skinAll(palette, p, n);
        assertInverseTranspose(m, n);
    }

    /** Skins with {@code method} directly and through deformations and the scalar expansion; both must agree. */
    private static float[] normalsBothWays(SkinningMethod method, Matrix4f m) {
        SkinnedGeometry g = oneJoint();
        JointPalette palette = g.newPalette();
        palette.setMatrix(0, m);
        palette.prepareAll();
        if (method.usesBones()) {
            palette.prepareAll();
        }
        Skinner k = Skinners.scalar(method, g, NormalTransform.INVERSE_TRANSPOSE);
        float[] p = new float[NORMALS.length];
        float[] n = new float[NORMALS.length];
        k.skinAll(palette, p, n);
        int points = g.pointCount();
        float[] deformations = new float[Skinner.DEFORMATION_FLOATS * points];
        k.skinDeformations(palette, deformations, 0, points);
        int[] identity = new int[points];
        for (int i = 0; i < points; i++) {
            identity[i] = i;
        }
        float[] p2 = new float[NORMALS.length];
        float[] n2 = new float[NORMALS.length];
        DeformationExpansion.scalar(identity, g.normalArray()).expand(deformations, p2, n2, 0, points, true);
        for (int i = 0; i < NORMALS.length; i++) {
            assertEquals(p[i], p2[i], 1e-5f, method + ": position float " + i + " by deformations");
            assertEquals(n[i], n2[i], 1e-5f, method + ": normal float " + i + " by deformations");
        }
        return n;
    }

    /**
     * The methods that move a point of one joint by that joint's whole matrix. STBS keeps of a
     * joint's scale only the stretch along its bone (docs/skinning.md), so a scaled or mirrored
     * joint is not its matrix there; StbsSkinningTest checks its normals.
     */
    private static List<SkinningMethod> wholeMatrixMethods() {
        List<SkinningMethod> methods = new ArrayList<>(List.of(SkinningMethod.values()));
        methods.removeAll(List.of(SkinningMethod.STBS_LBS, SkinningMethod.STBS_DQS));
        return methods;
    }

    @Test
    void mirroringJointsKeepNormalsOutward() {
        // A mirror (det < 0): the cofactor is det times the inverse-transpose and would turn every
        // normal inwards; the inverse-transpose itself is the outward normal of the mirrored surface
        // (a face at x = +1 with normal +x lands at x = -1 facing -x).
        Matrix4f mirror = new Matrix4f().rotateXYZ(0.2f, 0.9f, -0.3f).scale(-1f, 1f, 1f).setTranslation(0.5f, 0f, 0f);
        Matrix4f scaledMirror = new Matrix4f().rotateXYZ(-0.6f, 0.1f, 0.4f).scale(1.5f, -0.5f, 2f);
        for (SkinningMethod method : wholeMatrixMethods()) {
            assertInverseTranspose(mirror, normalsBothWays(method, mirror));
            assertInverseTranspose(scaledMirror, normalsBothWays(method, scaledMirror));
        }
    }

    @Test
    void deformationsCarryTheSameNormalsForOrdinaryJoints() {
        Matrix4f m = new Matrix4f().rotateXYZ(0.7f, -0.4f, 1.1f).scale(2f, 1f, 0.5f).setTranslation(0.1f, 0.2f, 0.3f);
        for (SkinningMethod method : wholeMatrixMethods()) {
            assertInverseTranspose(m, normalsBothWays(method, m));
        }
    }
}
