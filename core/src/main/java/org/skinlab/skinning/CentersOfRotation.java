package org.skinlab.skinning;

import java.nio.file.Path;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.stream.IntStream;

/**
 * The per-point centres of rotation of skinning with optimized centers of rotation (Le and Hodgins,
 * "Real-time Skeletal Skinning with Optimized Centers of Rotation", SIGGRAPH 2016, section 4):
 * for a point with weights w_i at rest, the centre is the area-weighted mean of the triangle
 * centroids, each weighted by how similar the triangle's weights are to the point's:
 *
 * <pre>
 * p*_i = sum_t s(w_i, w_t) c_t a_t / sum_t s(w_i, w_t) a_t
 * s(w_p, w_v) = sum_{j != k} w_pj w_pk w_vj w_vk exp(-(w_pj w_vk - w_pk w_vj)^2 / sigma^2)
 * </pre>
 *
 * with c_t, a_t the rest centroid and area of triangle t and w_t the mean of its corners'
 * weights. Two weight vectors are similar only where both have weight on the same two joints, so
 * a point with one influence (rigid) or none has no similar triangle: its centre is undefined,
 * and it is set to the point itself, which makes the run-time formula reduce to LBS there (the
 * point moves with its one joint, rigidly).
 *
 * <p><b>Cost.</b> Every point against every triangle: O(P T k^2) for P points, T triangles and
 * k influences per point (only joints both share enter the inner sum, so most pairs cost one
 * look-up). Computed per mesh position, not per render vertex (vertices sharing a position share
 * its weights), in parallel over positions. The paper's acceleration (clustering similar weight
 * vectors) is not needed at our sizes: docs/skinning.md has the timings.
 */
public final class CentersOfRotation {
    /** The paper's default width of the similarity kernel. */
    public static final double DEFAULT_SIGMA = 0.1;

    /** Told how far a computation is: positions done of all; called from worker threads. */
    @FunctionalInterface
    public interface Progress {
        void update(int done, int total);

        Progress NONE = (done, total) -> {
        };
    }

    /** Where computed centres are kept between runs; null: nowhere (see {@link #setCacheDirectory}). */
    private static volatile Path cacheDirectory;

    private CentersOfRotation() {
    }

    /**
     * Keeps computed centres in {@code directory} (created when needed), one file per geometry
     * named by a hash of everything the centres depend on (bind positions, triangles, influences,
     * sigma), so that loading a file again costs a file read. Null turns the cache off (the
     * default). Set once by an application at start; a cache that cannot be read or written is
     * passed by silently (the centres are then computed).
     */
    public static void setCacheDirectory(Path directory) {
        cacheDirectory = directory;
    }

    public static Path cacheDirectory() {
        return cacheDirectory;
    }

    /**
     * The centres from the cache when it holds them for this geometry and sigma, else computed
     * (and then stored in the cache, if one is set).
     */
    public static float[] computeOrLoad(SkinnedGeometry geometry, double sigma, Progress progress) {
        Path dir = cacheDirectory;
        if (dir == null) {
            return compute(geometry, sigma, progress);
        }
        String key = CentresCache.key(geometry, sigma);
        float[] cached = CentresCache.load(dir, key, 3 * geometry.pointCount());
        if (cached != null) {
            progress.update(1, 1);
            return cached;
        }
        float[] centres = compute(geometry, sigma, progress);
        CentresCache.store(dir, key, centres);
        return centres;
    }

    /**
     * The centre of every point of {@code geometry}, 3 floats per point in bind space (the space
     * of {@link SkinnedGeometry#positionArray()}).
     */
    public static float[] compute(SkinnedGeometry geometry, double sigma, Progress progress) {
        if (!(sigma > 0) || Double.isInfinite(sigma)) {
            throw new IllegalArgumentException("sigma " + sigma + " (need a finite width > 0)");
        }
        SkinnedGeometry positions = geometry.sharedPositions() != null ? geometry.sharedPositions() : geometry;
        int[] triangles = geometry.mesh() == null ? new int[0] : geometry.mesh().triangles();
        Triangles t = new Triangles(geometry, triangles);
        int n = positions.pointCount();
        float[] centres = new float[3 * n];
        AtomicInteger done = new AtomicInteger();
        int chunk = 64;
        double inverseSigmaSquared = 1.0 / (sigma * sigma);
        IntStream.range(0, (n + chunk - 1) / chunk).parallel().forEach(c -> {
            int from = c * chunk;
            int to = Math.min(n, from + chunk);
            float[] weightOfJoint = new float[positions.jointCount()];
            float[] shared = new float[2 * t.maxSupport];
            for (int p = from; p < to; p++) {
                centre(positions, p, t, inverseSigmaSquared, weightOfJoint, shared, centres);
            }
            progress.update(done.addAndGet(to - from), n);
        });
        if (positions == geometry) {
            return centres;
        }
        int[] frameOfPoint = geometry.frameOfPointArray();
        float[] perPoint = new float[3 * geometry.pointCount()];
        for (int i = 0; i < geometry.pointCount(); i++) {
            System.arraycopy(centres, 3 * frameOfPoint[i], perPoint, 3 * i, 3);
        }
        return perPoint;
    }

    /** One point's centre into {@code out}; the scratch arrays are the caller's thread's own. */
    private static void centre(SkinnedGeometry g, int p, Triangles t, double inverseSigmaSquared, float[] weightOfJoint,
            float[] shared, float[] out) {
        int k = g.influencesPerPoint();
        int[] joints = g.jointArray();
        float[] weights = g.weightArray();
        int support = 0;
        for (int a = 0; a < k; a++) {
            float w = weights[k * p + a];
            if (w > 0) {
                weightOfJoint[joints[k * p + a]] += w;
                support++;
            }
        }
        double sx = 0;
        double sy = 0;
        double sz = 0;
        double sum = 0;
        if (support >= 2) {
            for (int tri = 0; tri < t.count; tri++) {
                // The joints both weight vectors have: (w_p, w_t) pairs.
                int m = 0;
                for (int e = t.start[tri]; e < t.start[tri + 1]; e++) {
                    float wp = weightOfJoint[t.joints[e]];
                    if (wp > 0) {
                        shared[2 * m] = wp;
                        shared[2 * m + 1] = t.weights[e];
                        m++;
                    }
                }
                if (m < 2) {
                    continue;
                }
                double s = 0;
                for (int j = 0; j < m; j++) {
                    double pj = shared[2 * j];
                    double tj = shared[2 * j + 1];
                    for (int l = j + 1; l < m; l++) {
                        double pl = shared[2 * l];
                        double tl = shared[2 * l + 1];
                        double d = pj * tl - pl * tj;
                        s += pj * pl * tj * tl * Math.exp(-d * d * inverseSigmaSquared);
                    }
                }
                double sa = s * t.area[tri];
                sx += sa * t.centroid[3 * tri];
                sy += sa * t.centroid[3 * tri + 1];
                sz += sa * t.centroid[3 * tri + 2];
                sum += sa;
            }
        }
        float[] rest = g.positionArray();
        if (sum > 0) {
            out[3 * p] = (float) (sx / sum);
            out[3 * p + 1] = (float) (sy / sum);
            out[3 * p + 2] = (float) (sz / sum);
        } else {
            out[3 * p] = rest[3 * p];
            out[3 * p + 1] = rest[3 * p + 1];
            out[3 * p + 2] = rest[3 * p + 2];
        }
        for (int a = 0; a < k; a++) {
            weightOfJoint[joints[k * p + a]] = 0;
        }
    }

    /** Per triangle: rest centroid, area, and its corners' mean weights as a sparse list. */
    private static final class Triangles {
        final int count;
        final double[] centroid;
        final double[] area;
        final int[] start;
        final int[] joints;
        final float[] weights;
        final int maxSupport;

        Triangles(SkinnedGeometry g, int[] triangles) {
            count = triangles.length / 3;
            centroid = new double[3 * count];
            area = new double[count];
            start = new int[count + 1];
            int k = g.influencesPerPoint();
            int[] gj = g.jointArray();
            float[] gw = g.weightArray();
            float[] rest = g.positionArray();
            int[] scratchJoints = new int[3 * k];
            float[] scratchWeights = new float[3 * k];
            int[] allJoints = new int[3 * k * Math.max(1, count)];
            float[] allWeights = new float[3 * k * Math.max(1, count)];
            int used = 0;
            int most = 0;
            for (int t = 0; t < count; t++) {
                int a = triangles[3 * t];
                int b = triangles[3 * t + 1];
                int c = triangles[3 * t + 2];
                double abx = rest[3 * b] - rest[3 * a];
                double aby = rest[3 * b + 1] - rest[3 * a + 1];
                double abz = rest[3 * b + 2] - rest[3 * a + 2];
                double acx = rest[3 * c] - rest[3 * a];
                double acy = rest[3 * c + 1] - rest[3 * a + 1];
                double acz = rest[3 * c + 2] - rest[3 * a + 2];
                double cx = aby * acz - abz * acy;
                double cy = abz * acx - abx * acz;
                double cz = abx * acy - aby * acx;
                area[t] = 0.5 * Math.sqrt(cx * cx + cy * cy + cz * cz);
                for (int d = 0; d < 3; d++) {
                    centroid[3 * t + d] = (rest[3 * a + d] + rest[3 * b + d] + rest[3 * c + d]) / 3.0;
                }
                // Merge the corners' influences: each distinct joint once, weight the mean.
                int m = 0;
                for (int corner = 0; corner < 3; corner++) {
                    int v = triangles[3 * t + corner];
                    for (int e = 0; e < k; e++) {
                        float w = gw[k * v + e];
                        if (w <= 0) {
                            continue;
                        }
                        int j = gj[k * v + e];
                        int found = -1;
                        for (int q = 0; q < m; q++) {
                            if (scratchJoints[q] == j) {
                                found = q;
                                break;
                            }
                        }
                        if (found < 0) {
                            scratchJoints[m] = j;
                            scratchWeights[m] = w / 3f;
                            m++;
                        } else {
                            scratchWeights[found] += w / 3f;
                        }
                    }
                }
                start[t] = used;
                System.arraycopy(scratchJoints, 0, allJoints, used, m);
                System.arraycopy(scratchWeights, 0, allWeights, used, m);
                used += m;
                most = Math.max(most, m);
            }
            start[count] = used;
            joints = java.util.Arrays.copyOf(allJoints, used);
            weights = java.util.Arrays.copyOf(allWeights, used);
            maxSupport = Math.max(1, most);
        }
    }
}
