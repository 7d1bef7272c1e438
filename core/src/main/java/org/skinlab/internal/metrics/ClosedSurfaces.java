package org.skinlab.internal.metrics;

import java.util.Arrays;
import java.util.HashMap;
import java.util.Map;

/**
 * The one rule for when triangles enclose a volume: join the corners that lie at the same point
 * (bit for bit: a surface split along seams, or cut into parts by material, still meets itself
 * there), leave out triangles with two corners at one point (they add nothing to a volume), and
 * require every remaining edge to be walked exactly once in each direction. Then the triangles
 * are closed, consistently wound surfaces, and the divergence theorem's sum
 * ({@link ArtifactMetrics#signedVolume}) is their volume, whatever the origin.
 *
 * <p>Points of several parts can be joined in one instance ({@link #corners}), so that parts that
 * are open alone can be tested together ({@link #closed(int[][])}). Offline work: it allocates.
 */
final class ClosedSurfaces {
    /** A point's coordinates as bits, with -0 taken as +0. */
    private record Point(int x, int y, int z) {
    }

    private final Map<Point, Integer> ids = new HashMap<>();

    /**
     * Per triangle corner, the id of its point: equal for corners at the same point, in this
     * call and every earlier one.
     *
     * @param points    3 floats per point
     * @param triangles 3 point indices per triangle
     */
    int[] corners(float[] points, int[] triangles) {
        int[] idOfPoint = new int[points.length / 3];
        Arrays.fill(idOfPoint, -1);
        int[] corners = new int[triangles.length];
        for (int c = 0; c < triangles.length; c++) {
            int p = triangles[c];
            if (idOfPoint[p] < 0) {
                Point key = new Point(Float.floatToIntBits(points[3 * p] + 0f),
                        Float.floatToIntBits(points[3 * p + 1] + 0f), Float.floatToIntBits(points[3 * p + 2] + 0f));
                Integer id = ids.putIfAbsent(key, ids.size());
                idOfPoint[p] = id == null ? ids.size() - 1 : id;
            }
            corners[c] = idOfPoint[p];
        }
        return corners;
    }

    /** Whether the triangles given by their corners ({@link #corners}) form closed surfaces together. */
    static boolean closed(int[]... cornerSets) {
        int size = 0;
        for (int[] corners : cornerSets) {
            size += corners.length;
        }
        long[] edges = new long[size];
        int n = 0;
        for (int[] corners : cornerSets) {
            for (int t = 0; t < corners.length; t += 3) {
                int a = corners[t];
                int b = corners[t + 1];
                int c = corners[t + 2];
                if (a == b || b == c || c == a) {
                    continue;
                }
                edges[n++] = edge(a, b);
                edges[n++] = edge(b, c);
                edges[n++] = edge(c, a);
            }
        }
        if (n == 0) {
            return false;
        }
        // Sorted, a repeated edge sits beside itself and the reverse of each is found by halving.
        Arrays.sort(edges, 0, n);
        for (int e = 0; e < n; e++) {
            long key = edges[e];
            if (e + 1 < n && edges[e + 1] == key
                    || Arrays.binarySearch(edges, 0, n, edge((int) key, (int) (key >>> 32))) < 0) {
                return false;
            }
        }
        return true;
    }

    /** The directed edge from a to b as one key. */
    private static long edge(int a, int b) {
        return (long) a << 32 | (b & 0xffffffffL);
    }
}
