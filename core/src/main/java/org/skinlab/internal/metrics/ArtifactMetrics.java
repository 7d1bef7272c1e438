package org.skinlab.internal.metrics;

import org.joml.Vector3f;
import org.joml.Vector3fc;
import org.skinlab.skinning.SkinnedGeometry;

/**
 * Numbers for the artifacts the thesis could only show: the volume a closed mesh encloses, and
 * how far a ring of vertices around a joint stays from the bone (LBS's "candy wrapper" collapses
 * it toward the axis under twist). All sums in double. Volumes relative to a model's rest pose
 * are {@link RestPose}'s.
 */
public final class ArtifactMetrics {
    private ArtifactMetrics() {
    }

    /**
     * The signed volume enclosed by a triangle mesh: the sum over triangles of
     * {@code p0 . (p1 x p2) / 6} (divergence theorem). Positive for a closed mesh whose triangles
     * wind counter-clockwise seen from outside; meaningless for an open one.
     *
     * @param pointPositions 3 floats per point (vertex indices of {@code triangles} index them)
     * @param triangles      3 vertex indices per triangle
     */
    public static double signedVolume(float[] pointPositions, int[] triangles) {
        double sum = 0;
        for (int t = 0; t < triangles.length; t += 3) {
            int a = 3 * triangles[t];
            int b = 3 * triangles[t + 1];
            int c = 3 * triangles[t + 2];
            double ax = pointPositions[a], ay = pointPositions[a + 1], az = pointPositions[a + 2];
            double bx = pointPositions[b], by = pointPositions[b + 1], bz = pointPositions[b + 2];
            double cx = pointPositions[c], cy = pointPositions[c + 1], cz = pointPositions[c + 2];
            sum += ax * (by * cz - bz * cy) + ay * (bz * cx - bx * cz) + az * (bx * cy - by * cx);
        }
        return sum / 6;
    }

    /** The diagonal of the bounding box of the first {@code count} points (3 floats each); 0 for none. */
    public static double boundsDiagonal(float[] points, int count) {
        if (count <= 0) {
            return 0;
        }
        double minX = Double.MAX_VALUE, minY = Double.MAX_VALUE, minZ = Double.MAX_VALUE;
        double maxX = -Double.MAX_VALUE, maxY = -Double.MAX_VALUE, maxZ = -Double.MAX_VALUE;
        for (int i = 0; i < count; i++) {
            minX = Math.min(minX, points[3 * i]);
            maxX = Math.max(maxX, points[3 * i]);
            minY = Math.min(minY, points[3 * i + 1]);
            maxY = Math.max(maxY, points[3 * i + 1]);
            minZ = Math.min(minZ, points[3 * i + 2]);
            maxZ = Math.max(maxZ, points[3 * i + 2]);
        }
        double dx = maxX - minX;
        double dy = maxY - minY;
        double dz = maxZ - minZ;
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }

    /**
     * Whether a geometry's mesh is closed in bind space ({@link ClosedSurfaces}' rule: corners at
     * the same point joined, so UV seams and hard edges do not open it; every edge walked once each
     * way). Only then is {@link #signedVolume} a volume. A model's parts are judged in its rest pose
     * instead ({@link RestPose}), where parts can close each other.
     */
    public static boolean isClosed(SkinnedGeometry geometry) {
        if (geometry.mesh() == null) {
            return false;
        }
        int[] corners = new ClosedSurfaces().corners(geometry.positionArray(), geometry.mesh().triangles());
        return ClosedSurfaces.closed(corners);
    }

    /**
     * The points of the joint ring: those whose rest position is nearest to the plane through
     * {@code jointPosition} perpendicular to {@code axis}, i.e. within {@code tolerance} of the
     * smallest plane distance any point has. A joint between two rings of vertices (an odd number
     * of segments) gets both.
     */
    public static int[] ringPoints(SkinnedGeometry geometry, Vector3fc jointPosition, Vector3fc axis,
            float tolerance) {
        Vector3f n = new Vector3f(axis).normalize();
        float[] p = geometry.positionArray();
        int points = geometry.pointCount();
        float[] distance = new float[points];
        float nearest = Float.POSITIVE_INFINITY;
        for (int i = 0; i < points; i++) {
            distance[i] = Math.abs((p[3 * i] - jointPosition.x()) * n.x + (p[3 * i + 1] - jointPosition.y()) * n.y
                    + (p[3 * i + 2] - jointPosition.z()) * n.z);
            nearest = Math.min(nearest, distance[i]);
        }
        int count = 0;
        int[] found = new int[points];
        for (int i = 0; i < points; i++) {
            if (distance[i] <= nearest + tolerance) {
                found[count++] = i;
            }
        }
        return java.util.Arrays.copyOf(found, count);
    }

    /**
     * Mean distance of the given points from the line through {@code origin} along {@code axis}:
     * the ring radius. Compare a deformed ring's with its rest value.
     */
    public static double meanDistanceFromAxis(float[] pointPositions, int[] points, Vector3fc origin,
            Vector3fc axis) {
        if (points.length == 0) {
            throw new IllegalArgumentException("no ring points");
        }
        double len = Math.sqrt(axis.lengthSquared());
        double ux = axis.x() / len, uy = axis.y() / len, uz = axis.z() / len;
        double sum = 0;
        for (int i : points) {
            double dx = pointPositions[3 * i] - origin.x();
            double dy = pointPositions[3 * i + 1] - origin.y();
            double dz = pointPositions[3 * i + 2] - origin.z();
            double along = dx * ux + dy * uy + dz * uz;
            dx -= along * ux;
            dy -= along * uy;
            dz -= along * uz;
            sum += Math.sqrt(dx * dx + dy * dy + dz * dz);
        }
        return sum / points.length;
    }
}
