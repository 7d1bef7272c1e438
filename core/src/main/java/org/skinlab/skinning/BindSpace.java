package org.skinlab.skinning;

import org.joml.Matrix3f;
import org.joml.Matrix4f;
import org.joml.Matrix4fc;
import org.joml.Vector3f;
import org.skinlab.model.MeshInstance;
import org.skinlab.model.Skin;

/**
 * Bind space, where a skinned geometry's points live: the mesh's positions moved by the skin's
 * bind shape matrix once, and by the common mirror of the bind frames when they all mirror, with
 * the palette's bind matrices to match.
 *
 * <p>Bind frames that all mirror (every INV_BIND with a negative determinant, e.g. a rig exported
 * through a mirroring bind shape) make every skinning matrix a reflection, which DQS can only take
 * through its scale phase. The common mirror F = diag(-1 1 1) moves into the points instead
 * (p -> F p, n -> F n, INV_BIND -> INV_BIND F; F F = I, so LBS is unchanged): the skinning
 * matrices become rigid again and DQS blends rigid motions.
 */
final class BindSpace {
    private BindSpace() {
    }

    /**
     * Moves a skin's points into bind space (bind shape matrix, then the common mirror when
     * {@code mirrorBindFrames}); returns whether their winding is then mirrored against the mesh
     * (by one of the two, not both: {@link SkinnedGeometry#windingMirrored()}).
     */
    static boolean movePoints(Skin skin, boolean mirrorBindFrames, float[] positions, float[] normals) {
        boolean mirrored = applyBindShape(skin.bindShapeMatrix(), positions, normals);
        if (mirrorBindFrames) {
            for (int i = 0; i < positions.length; i += 3) {
                positions[i] = -positions[i];
                normals[i] = -normals[i];
            }
            mirrored = !mirrored;
        }
        return mirrored;
    }

    /**
     * Moves the points into bind space once: positions by the bind shape matrix, normals by its
     * inverse-transpose (the cofactor times the sign of its determinant, renormalised). Every
     * joint's skinning matrix would apply it first anyway ({@code world * INV_BIND * BSM}); doing it
     * here keeps it out of the joints, so a bind shape that scales or mirrors (the stormtrooper's
     * mirrors and scales by 1.662) does not make every joint a scaled one for DQS, and a joint's
     * rest frame is {@code inverse(INV_BIND)}, as in Blender's armature deform
     * (docs/references.md).
     */
    private static boolean applyBindShape(Matrix4fc bsm, float[] positions, float[] normals) {
        if (new Matrix4f(bsm).equals(new Matrix4f())) {
            return false;
        }
        Matrix3f cofactor = new Matrix3f();
        bsm.get3x3(cofactor).cofactor();
        if (bsm.determinant3x3() < 0f) {
            cofactor.scale(-1f);
        }
        Vector3f v = new Vector3f();
        for (int i = 0; i < positions.length; i += 3) {
            bsm.transformPosition(v.set(positions[i], positions[i + 1], positions[i + 2]));
            positions[i] = v.x;
            positions[i + 1] = v.y;
            positions[i + 2] = v.z;
            cofactor.transform(v.set(normals[i], normals[i + 1], normals[i + 2]));
            float len2 = v.lengthSquared();
            if (len2 > 0f) {
                v.mul((float) (1.0 / Math.sqrt(len2)));
            }
            normals[i] = v.x;
            normals[i + 1] = v.y;
            normals[i + 2] = v.z;
        }
        return bsm.determinant3x3() < 0f;
    }

    /** Whether every bind frame of the skin mirrors (then the common mirror moves into the points). */
    static boolean mirrorsBindFrames(Skin skin) {
        Matrix4f m = new Matrix4f();
        boolean all = skin.jointCount() > 0;
        for (int j = 0; j < skin.jointCount() && all; j++) {
            all = skin.inverseBindMatrix(j, m).determinant3x3() < 0f;
        }
        return all;
    }

    /**
     * The palette's bind matrices, 16 floats column-major per joint: the skin's INV_BIND (times F
     * when the common mirror is in the points), then, when {@code bindShapeJoint}, the
     * pseudo-joint's, which undoes only F (the points already hold the bind shape).
     */
    static float[] bindMatrices(Skin skin, boolean bindShapeJoint, boolean mirrorBindFrames) {
        int skinJoints = skin.jointCount();
        float[] bind = new float[16 * (skinJoints + (bindShapeJoint ? 1 : 0))];
        Matrix4f m = new Matrix4f();
        for (int j = 0; j < skinJoints; j++) {
            skin.inverseBindMatrix(j, m);
            if (mirrorBindFrames) {
                m.scale(-1f, 1f, 1f);
            }
            m.get(bind, 16 * j);
        }
        if (bindShapeJoint) {
            m.identity().scale(mirrorBindFrames ? -1f : 1f, 1f, 1f).get(bind, 16 * skinJoints);
        }
        return bind;
    }

    /**
     * What takes a mesh position to its point's position in bind space: the bind shape matrix,
     * then the common mirror of the bind frames when there is one (as {@link #movePoints} applies
     * them once); the identity for a static mesh.
     */
    static Matrix4f pointTransform(MeshInstance instance) {
        Matrix4f m = new Matrix4f();
        Skin skin = instance.skin();
        if (skin == null) {
            return m;
        }
        if (mirrorsBindFrames(skin)) {
            m.scale(-1f, 1f, 1f);
        }
        return m.mul(skin.bindShapeMatrix());
    }
}
