package org.skinlab.desktop.bench;

import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.skinlab.animation.AnimationHelper;
import org.skinlab.animation.DualQuaternion;
import org.skinlab.skinning.JointPalette;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinningMethod;

/**
 * The skinning loop as the thesis wrote it, kept only as a speed baseline for
 * {@code skinlab bench skinning --baseline thesis}: objects per vertex (JOML matrices and vectors,
 * a {@link DualQuaternion} per influence) and, for DQS, every influence's joint matrix converted
 * to a dual quaternion per vertex ({@link AnimationHelper#toDualQuaternion}: a polar decomposition
 * each time) instead of once per joint per frame, with the antipodality sign as a branch. It
 * computes the same deformation as the kernels (checked by the benchmark's checksum), only slowly.
 */
public final class ThesisSkinningBaseline {
    private final SkinnedGeometry geometry;
    private final SkinningMethod method;

    public ThesisSkinningBaseline(SkinnedGeometry geometry, SkinningMethod method) {
        this.geometry = geometry;
        this.method = method;
    }

    /** Deforms all points; normals by the blended transform (as the C++ reference). */
    public void skinAll(JointPalette palette, float[] outPositions, float[] outNormals) {
        float[] pos = geometry.positionArray();
        float[] nrm = geometry.normalArray();
        int[] joints = geometry.jointArray();
        float[] weights = geometry.weightArray();
        int width = geometry.influencesPerPoint();
        for (int i = 0; i < geometry.pointCount(); i++) {
            Vector3f p = new Vector3f(pos[3 * i], pos[3 * i + 1], pos[3 * i + 2]);
            Vector3f n = new Vector3f(nrm[3 * i], nrm[3 * i + 1], nrm[3 * i + 2]);
            if (method == SkinningMethod.DQS) {
                DualQuaternion blended = new DualQuaternion().scale(0f);
                DualQuaternion pivot = null;
                for (int k = 0; k < width; k++) {
                    Matrix4f m = palette.getMatrix(joints[width * i + k], new Matrix4f());
                    DualQuaternion q = AnimationHelper.toDualQuaternion(m, new DualQuaternion());
                    float w = weights[width * i + k];
                    if (pivot == null) {
                        pivot = q;
                    } else if (pivot.realDot(q) < 0) {
                        w = -w;
                    }
                    blended.addScaled(w, q);
                }
                blended.normalize();
                blended.transformPosition(p);
                blended.transformDirection(n);
            } else {
                Matrix4f blended = new Matrix4f().zero().m33(1f);
                for (int k = 0; k < width; k++) {
                    Matrix4f m = palette.getMatrix(joints[width * i + k], new Matrix4f());
                    blended.fma4x3(m, weights[width * i + k]);
                }
                blended.transformPosition(p);
                blended.transformDirection(n);
            }
            outPositions[3 * i] = p.x;
            outPositions[3 * i + 1] = p.y;
            outPositions[3 * i + 2] = p.z;
            outNormals[3 * i] = n.x;
            outNormals[3 * i + 1] = n.y;
            outNormals[3 * i + 2] = n.z;
        }
    }
}
