package org.skinlab.desktop.eval;

import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.skinlab.animation.AnimationHelper;
import org.skinlab.internal.metrics.ArtifactMetrics;
import org.skinlab.skinning.SkinnedGeometry;

/**
 * How far a joint's ring of vertices has turned about the joint's axis of motion, seen from its
 * parent bone: what shows a method's reading of a rotation past a half turn. A smooth blend of a
 * joint turned by an angle turns the ring midway between the bones by about half of it; a method
 * that takes the shorter way round (dual quaternions past 180 degrees) turns it the other way.
 *
 * <p>The ring is the geometry's points nearest the plane through the joint across the parent's
 * bone ({@link ArtifactMetrics#ringPoints}). A posed point is taken back by the parent's skinning
 * matrix into bind space, where the rest ring is; both, relative to the joint's origin, are
 * projected on the plane across the axis, and the turn is the least-squares rotation angle between
 * them in that plane: atan2(sum a . (r x q), sum r . q) (2-D Procrustes), in (-180, 180] degrees.
 */
final class RingTurn {
    private final int parent;
    private final int[] ring;
    private final float[] restRelative;
    private final Vector3f origin = new Vector3f();
    private final Matrix4f back = new Matrix4f();
    private final Vector3f p = new Vector3f();

    /** The ring of palette joint {@code joint}, whose parent bone is palette joint {@code parent}. */
    RingTurn(SkinnedGeometry geometry, int joint, int parent) {
        this.parent = parent;
        float[] bind = geometry.bindMatrixArray();
        Vector3f base = new Vector3f();
        new Matrix4f().set(bind, 16 * parent).invert().getTranslation(base);
        new Matrix4f().set(bind, 16 * joint).invert().getTranslation(origin);
        Vector3f bone = new Vector3f(origin).sub(base);
        float size = (float) ArtifactMetrics.boundsDiagonal(geometry.positionArray(), geometry.vertexCount());
        ring = bone.lengthSquared() > 0 ? ArtifactMetrics.ringPoints(geometry, origin, bone, 1e-4f * size)
                : new int[0];
        float[] rest = geometry.positionArray();
        restRelative = new float[3 * ring.length];
        for (int r = 0; r < ring.length; r++) {
            for (int c = 0; c < 3; c++) {
                restRelative[3 * r + c] = rest[3 * ring[r] + c] - origin.get(c);
            }
        }
    }

    /** Whether there is a ring to measure. */
    boolean measurable() {
        return ring.length > 0;
    }

    /**
     * The ring's turn in degrees about {@code axis} (a unit vector in bind space) in a pose: the
     * posed points of the geometry and the pose's skinning matrices (12 floats per joint). NaN when
     * the ring collapsed onto the axis (nothing left to turn).
     */
    double degrees(float[] posed, float[] skinningMatrices, double[] axis) {
        AnimationHelper.getRowMajor3x4(skinningMatrices, 12 * parent, back);
        back.invert();
        double cross = 0;
        double dot = 0;
        for (int r = 0; r < ring.length; r++) {
            int i = ring[r];
            back.transformPosition(p.set(posed[3 * i], posed[3 * i + 1], posed[3 * i + 2])).sub(origin);
            double[] q = across(p.x, p.y, p.z, axis);
            double[] s = across(restRelative[3 * r], restRelative[3 * r + 1], restRelative[3 * r + 2], axis);
            double cx = s[1] * q[2] - s[2] * q[1];
            double cy = s[2] * q[0] - s[0] * q[2];
            double cz = s[0] * q[1] - s[1] * q[0];
            cross += axis[0] * cx + axis[1] * cy + axis[2] * cz;
            dot += s[0] * q[0] + s[1] * q[1] + s[2] * q[2];
        }
        if (Math.abs(cross) + Math.abs(dot) < 1e-12) {
            return Double.NaN;
        }
        return Math.toDegrees(Math.atan2(cross, dot));
    }

    /** v's part across the unit axis a: v - (v . a) a. */
    private static double[] across(double x, double y, double z, double[] a) {
        double along = x * a[0] + y * a[1] + z * a[2];
        return new double[] {x - along * a[0], y - along * a[1], z - along * a[2]};
    }
}
