package org.skinlab.animation;

import org.joml.Matrix4f;
import org.joml.Quaternionf;
import org.joml.Vector3f;

/**
 * What tests ask of a dual quaternion and the runtime never does: its rigid matrix, and whether
 * two dual quaternions are the same transform.
 */
public final class DualQuaternions {
    private DualQuaternions() {
    }

    /** The rigid matrix of a dual quaternion (normalised first, so any non-zero one works). */
    public static Matrix4f toMatrix(DualQuaternion dq, Matrix4f dest) {
        DualQuaternion n = new DualQuaternion(dq).normalize();
        Vector3f t = n.getTranslation(new Vector3f());
        AnimationHelper.rotationMatrix(new Quaternionf(n.rx, n.ry, n.rz, n.rw), dest);
        return dest.setTranslation(t);
    }

    /**
     * True when all eight components of {@code a} and {@code b} agree within {@code eps}, after
     * negating {@code b} when the real parts lie in opposite hemispheres (q and -q are the same
     * transform).
     */
    public static boolean sameTransform(DualQuaternion a, DualQuaternion b, float eps) {
        float s = a.realDot(b) < 0 ? -1 : 1;
        return Math.abs(a.rx - s * b.rx) <= eps && Math.abs(a.ry - s * b.ry) <= eps && Math.abs(a.rz - s * b.rz) <= eps
                && Math.abs(a.rw - s * b.rw) <= eps && Math.abs(a.dx - s * b.dx) <= eps
                && Math.abs(a.dy - s * b.dy) <= eps && Math.abs(a.dz - s * b.dz) <= eps
                && Math.abs(a.dw - s * b.dw) <= eps;
    }
}
