package org.skinlab.skinning;

import java.util.HashSet;
import java.util.Set;

/**
 * Seams in a deformed surface: the largest jump in normal direction between neighbouring
 * positions. A method that moves neighbours differently (bulge-free DQS pulls neighbouring points
 * towards different bones) folds the surface between them, which shows in shading although the
 * positions stay close.
 *
 * <p><b>Definition.</b> Neighbours are the two ends of a triangle edge, taken between POSITION
 * entries (so the exporter's split vertices are one). A position's normal is derived from the
 * deformed surface, not from a kernel's normals: the sum of the cross products
 * {@code (b - a) x (c - a)} of the triangles around it (area-weighted face normals), normalised.
 * An edge's jump is the angle between its two ends' normals, {@code atan2(|n_a x n_b|, n_a . n_b)}
 * in radians. {@link #largest} is the largest jump over all edges; {@link #largestAdded} the largest
 * increase of an edge's jump over the same edge in a baseline deformation (for bulge-free DQS: DQS),
 * so that the coarseness of the mesh, which both share, does not count. All in double.
 */
final class NormalSeams {
    /** The largest jump: its angle (radians) and the edge's two POSITION entries. */
    public record Jump(double angle, int positionA, int positionB) {
    }

    private final int[] triangles;
    private final int positions;
    /** Per edge its two positions (a < b). */
    private final int[] edges;
    /** Per position the point whose deformed coordinates stand for it. */
    private final int[] pointOfPosition;

    private NormalSeams(int[] triangles, int positions, int[] edges, int[] pointOfPosition) {
        this.triangles = triangles;
        this.positions = positions;
        this.edges = edges;
        this.pointOfPosition = pointOfPosition;
    }

    /** The edges of a geometry's mesh. */
    public static NormalSeams of(SkinnedGeometry geometry) {
        if (geometry.mesh() == null) {
            throw new IllegalArgumentException(geometry + " has no triangles");
        }
        int[] vertexTriangles = geometry.mesh().triangles();
        int[] positionOf = geometry.mesh().vertexPositions();
        int[] triangles = new int[vertexTriangles.length];
        for (int t = 0; t < triangles.length; t++) {
            triangles[t] = positionOf[vertexTriangles[t]];
        }
        int[] pointOf = new int[geometry.positionCount()];
        for (int p = 0; p < pointOf.length; p++) {
            pointOf[p] = geometry.pointOfPosition(p);
        }
        return of(triangles, pointOf);
    }

    /**
     * The edges of triangles over positions ({@code triangles}: 3 position indices each), deformed
     * points read at {@code pointOfPosition[p]}.
     */
    public static NormalSeams of(int[] triangles, int[] pointOfPosition) {
        Set<Long> seen = new HashSet<>();
        int[] edges = new int[2 * triangles.length];
        int n = 0;
        for (int t = 0; t < triangles.length; t += 3) {
            for (int c = 0; c < 3; c++) {
                int a = triangles[t + c];
                int b = triangles[t + (c + 1) % 3];
                if (a != b && seen.add((long) Math.min(a, b) << 32 | Math.max(a, b))) {
                    edges[n++] = Math.min(a, b);
                    edges[n++] = Math.max(a, b);
                }
            }
        }
        return new NormalSeams(triangles.clone(), pointOfPosition.length, java.util.Arrays.copyOf(edges, n),
                pointOfPosition.clone());
    }

    /** Number of distinct edges. */
    public int edgeCount() {
        return edges.length / 2;
    }

    /** The largest jump of normal direction across an edge of the deformed points. */
    public Jump largest(float[] posedPoints) {
        return largestAdded(posedPoints, null);
    }

    /**
     * The largest increase of an edge's jump in {@code posedPoints} over the same edge in
     * {@code baselinePoints} (null: over 0, i.e. {@link #largest}).
     */
    public Jump largestAdded(float[] posedPoints, float[] baselinePoints) {
        double[] normals = normals(posedPoints);
        double[] base = baselinePoints == null ? null : normals(baselinePoints);
        Jump worst = new Jump(0, -1, -1);
        for (int e = 0; e < edges.length; e += 2) {
            double added = angle(normals, edges[e], edges[e + 1])
                    - (base == null ? 0 : angle(base, edges[e], edges[e + 1]));
            if (added > worst.angle()) {
                worst = new Jump(added, edges[e], edges[e + 1]);
            }
        }
        return worst;
    }

    /** Per position the unit area-weighted normal of the deformed surface (0 for an unused one). */
    private double[] normals(float[] p) {
        double[] n = new double[3 * positions];
        for (int t = 0; t < triangles.length; t += 3) {
            int a = 3 * pointOfPosition[triangles[t]];
            int b = 3 * pointOfPosition[triangles[t + 1]];
            int c = 3 * pointOfPosition[triangles[t + 2]];
            double ux = p[b] - p[a], uy = p[b + 1] - p[a + 1], uz = p[b + 2] - p[a + 2];
            double vx = p[c] - p[a], vy = p[c + 1] - p[a + 1], vz = p[c + 2] - p[a + 2];
            double fx = uy * vz - uz * vy, fy = uz * vx - ux * vz, fz = ux * vy - uy * vx;
            for (int k = 0; k < 3; k++) {
                int q = 3 * triangles[t + k];
                n[q] += fx;
                n[q + 1] += fy;
                n[q + 2] += fz;
            }
        }
        for (int q = 0; q < n.length; q += 3) {
            double len = Math.sqrt(n[q] * n[q] + n[q + 1] * n[q + 1] + n[q + 2] * n[q + 2]);
            if (len > 0) {
                n[q] /= len;
                n[q + 1] /= len;
                n[q + 2] /= len;
            }
        }
        return n;
    }

    private static double angle(double[] n, int a, int b) {
        double ax = n[3 * a], ay = n[3 * a + 1], az = n[3 * a + 2];
        double bx = n[3 * b], by = n[3 * b + 1], bz = n[3 * b + 2];
        double cx = ay * bz - az * by, cy = az * bx - ax * bz, cz = ax * by - ay * bx;
        return Math.atan2(Math.sqrt(cx * cx + cy * cy + cz * cz), ax * bx + ay * by + az * bz);
    }
}
