package org.skinlab.skinning;

import java.nio.file.Path;
import java.util.Arrays;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.stream.IntStream;

/**
 * The per-point centres of rotation of skinning with optimized centers of rotation (Le and Hodgins,
 * "Real-time Skeletal Skinning with Optimized Centers of Rotation", SIGGRAPH 2016, section 4):
 * for a point with weights w_i at rest, the centre is the area-weighted mean of the surface,
 * weighted by how similar the weights there are to the point's:
 *
 * <pre>
 * p*_i = sum_t s(w_i, w_t) c_t a_t / sum_t s(w_i, w_t) a_t
 * s(w_p, w_v) = sum_{j != k} w_pj w_pk w_vj w_vk exp(-(w_pj w_vk - w_pk w_vj)^2 / sigma^2)
 * </pre>
 *
 * over the triangles t of the rest mesh subdivided until the weights of every edge's ends are at
 * most epsilon apart (the paper's numerical integration, {@link SimilarityTriangles}), with c_t,
 * a_t a (sub-)triangle's centroid and area and w_t the mean of its corners' weights. Two weight
 * vectors are similar only where both weight the same two joints, so a point with one influence
 * (rigid) or none has no similar triangle: its centre is undefined, and it is set to the point
 * itself, which makes the run-time formula reduce to LBS there (the point moves with its one
 * joint, rigidly).
 *
 * <p><b>Cost.</b> Per point, the triangles sharing two of its joints, each cut into n^2
 * sub-triangles, k^2 similarity terms each: O(P T_j n^2 k^2) for P points and T_j triangles
 * around a joint pair, far below the paper's every-point-against-every-triangle. Computed per
 * mesh position, not per render vertex (vertices sharing a position share its weights), in
 * parallel over positions. The paper's further acceleration (clustering similar weight vectors)
 * is not needed at our sizes: docs/skinning.md has the timings ({@code skinlab centres}).
 */
public final class CentresOfRotation {
    /**
     * The precomputation's two parameters: the width of the similarity kernel and the largest
     * weight distance along an edge of the integration mesh (both the paper's defaults: 0.1).
     * Epsilon may be infinite (no subdivision, the triangles as they are); below
     * {@link #MIN_WEIGHT_EPSILON} the subdivision would grow without bound and is refused.
     *
     * @param sigma         the similarity kernel's width sigma, in weight units; finite and above 0
     * @param weightEpsilon the largest difference of weight vectors (Euclidean) between the ends of an
     *                      edge of the integration mesh; at least {@link #MIN_WEIGHT_EPSILON}, or
     *                      infinite for no subdivision
     */
    public record Parameters(double sigma, double weightEpsilon) {
        /** The paper's parameters, sigma 0.1, epsilon 0.1: those of {@link SkinnedGeometry#withCentresOfRotation()}. */
        public static final Parameters DEFAULT = new Parameters(0.1, 0.1);

        /**
         * Checks the parameters.
         *
         * @param sigma         the similarity kernel's width, finite and above 0
         * @param weightEpsilon the largest weight distance along an integration edge, at least
         *                      {@link #MIN_WEIGHT_EPSILON} (infinity for no subdivision)
         * @throws IllegalArgumentException when sigma is not finite and above 0, or epsilon is below
         *                                  {@link #MIN_WEIGHT_EPSILON} or NaN
         */
        public Parameters {
            if (!(sigma > 0) || Double.isInfinite(sigma)) {
                throw new IllegalArgumentException("sigma " + sigma + " (need a finite width > 0)");
            }
            if (!(weightEpsilon >= MIN_WEIGHT_EPSILON)) {
                throw new IllegalArgumentException("weight epsilon " + weightEpsilon + " (need at least "
                        + MIN_WEIGHT_EPSILON + ", or infinity for no subdivision)");
            }
        }
    }

    /** The smallest weight epsilon: an edge from one joint to another (distance sqrt 2) in 142 segments. */
    public static final double MIN_WEIGHT_EPSILON = 0.01;

    /** Told how far a computation is: positions done of all; called from worker threads. */
    @FunctionalInterface
    public interface Progress {
        /**
         * Reports progress; calls may come from several threads at once and out of order.
         *
         * @param done  positions done so far
         * @param total positions in all (1 of 1 when the centres came from the cache)
         */
        void update(int done, int total);

        /** Ignores every update. */
        Progress NONE = (done, total) -> {
        };
    }

    /** Where computed centres are kept between runs; null: nowhere (see {@link #setCacheDirectory}). */
    private static volatile Path cacheDirectory;

    private CentresOfRotation() {
    }

    /**
     * Keeps computed centres in {@code directory} (created when needed), one file per geometry
     * named by a hash of everything the centres depend on (bind positions, triangles, influences,
     * parameters), so that loading a file again costs a file read. Null turns the cache off (the
     * default). Set once by an application at start; a cache that cannot be read or written is
     * passed by silently (the centres are then computed).
     *
     * @param directory the cache's folder, or null for no cache
     */
    public static void setCacheDirectory(Path directory) {
        cacheDirectory = directory;
    }

    /**
     * The folder computed centres are kept in ({@link #setCacheDirectory}).
     *
     * @return the folder, or null when there is no cache (the default)
     */
    public static Path cacheDirectory() {
        return cacheDirectory;
    }

    /**
     * The centres from the cache when it holds them for this geometry and these parameters, else
     * computed (and then stored in the cache, if one is set).
     *
     * @param geometry   the geometry, at rest
     * @param parameters the precomputation's parameters
     * @param progress   told how far the computation is ({@link Progress#NONE} for nothing)
     * @return the centres as {@link #compute} returns them; a new array
     */
    public static float[] computeOrLoad(SkinnedGeometry geometry, Parameters parameters, Progress progress) {
        Path dir = cacheDirectory;
        if (dir == null) {
            return compute(geometry, parameters, progress);
        }
        String key = CentresCache.key(geometry, parameters);
        float[] cached = CentresCache.load(dir, key, 3 * geometry.pointCount());
        if (cached != null) {
            progress.update(1, 1);
            return cached;
        }
        float[] centres = compute(geometry, parameters, progress);
        CentresCache.store(dir, key, centres);
        return centres;
    }

    /**
     * The centre of every point of {@code geometry}, 3 floats per point in bind space (the space
     * of {@link SkinnedGeometry#positionArray()}).
     *
     * <p>Bind-time work: in parallel on the common fork-join pool, up to a second for a large
     * character. A geometry without triangles ({@link SkinnedGeometry#fromArrays}) gets every point
     * as its own centre.
     *
     * @param geometry   the geometry, at rest
     * @param parameters the precomputation's parameters
     * @param progress   told how far the computation is ({@link Progress#NONE} for nothing)
     * @return a new array of {@code 3 * pointCount()} floats, the point itself where its centre is undefined
     */
    public static float[] compute(SkinnedGeometry geometry, Parameters parameters, Progress progress) {
        return centres(geometry, triangles(geometry), parameters, progress);
    }

    /**
     * How many triangles the integration runs over after subdivision (for reports and benchmarks).
     *
     * @param geometry   the geometry, at rest
     * @param parameters the parameters; only the weight epsilon matters
     * @return the number of sub-triangles, 0 for a geometry without triangles
     */
    public static long integrationTriangles(SkinnedGeometry geometry, Parameters parameters) {
        return new SimilarityTriangles(geometry, triangles(geometry), parameters.weightEpsilon()).integrationTriangles();
    }

    private static int[] triangles(SkinnedGeometry geometry) {
        return geometry.mesh() == null ? new int[0] : geometry.mesh().triangles();
    }

    /**
     * As {@link #compute(SkinnedGeometry, Parameters, Progress)} over triangles given apart from the
     * geometry: for a geometry made from arrays ({@link SkinnedGeometry#fromArrays}), e.g. an engine's
     * mesh whose index buffer holds its triangles.
     *
     * @param geometry   the geometry, at rest
     * @param triangles  3 indices of the geometry's points per triangle
     * @param parameters the precomputation's parameters
     * @param progress   told how far the computation is ({@link Progress#NONE} for nothing)
     * @return a new array of {@code 3 * pointCount()} floats, the point itself where its centre is undefined
     */
    public static float[] compute(SkinnedGeometry geometry, int[] triangles, Parameters parameters, Progress progress) {
        if (triangles.length % 3 != 0) {
            throw new IllegalArgumentException(triangles.length + " triangle indices: need 3 per triangle");
        }
        for (int i : triangles) {
            if (i < 0 || i >= geometry.pointCount()) {
                throw new IllegalArgumentException("triangle index " + i + " outside the " + geometry.pointCount() + " points");
            }
        }
        return centres(geometry, triangles, parameters, progress);
    }

    /** The centres over the given triangles (indices of the geometry's points). */
    private static float[] centres(SkinnedGeometry geometry, int[] triangles, Parameters parameters, Progress progress) {
        SkinnedGeometry positions = geometry.sharedPositions() != null ? geometry.sharedPositions() : geometry;
        SimilarityTriangles t = new SimilarityTriangles(geometry, triangles, parameters.weightEpsilon());
        int n = positions.pointCount();
        float[] centres = new float[3 * n];
        AtomicInteger done = new AtomicInteger();
        int chunk = 64;
        double inverseSigmaSquared = 1.0 / (parameters.sigma() * parameters.sigma());
        IntStream.range(0, (n + chunk - 1) / chunk).parallel().forEach(c -> {
            int from = c * chunk;
            int to = Math.min(n, from + chunk);
            Scratch scratch = new Scratch(positions, t);
            for (int p = from; p < to; p++) {
                centre(positions, p, t, inverseSigmaSquared, scratch, centres);
            }
            progress.update(done.addAndGet(to - from), n);
        });
        if (positions == geometry) {
            return centres;
        }
        int[] deformationOfPoint = geometry.deformationOfPointArray();
        float[] perPoint = new float[3 * geometry.pointCount()];
        for (int i = 0; i < geometry.pointCount(); i++) {
            System.arraycopy(centres, 3 * deformationOfPoint[i], perPoint, 3 * i, 3);
        }
        return perPoint;
    }

    /** One worker's arrays, reused for its points. */
    private static final class Scratch {
        /** The point's weight on each joint (zero elsewhere between points). */
        final float[] weightOfJoint;
        final int[] pointJoints;
        final byte[] hits;
        final int[] candidates;
        /** Per shared joint: w_p, then the corners' weights wa, wb, wc. */
        final double[] shared;
        /** Per shared joint: the weight at the sub-triangle's centroid. */
        final double[] atCentroid;
        /** The centroid sums x, y, z weighted by similarity times area, and that weight's sum. */
        final double[] sums = new double[4];

        Scratch(SkinnedGeometry g, SimilarityTriangles t) {
            weightOfJoint = new float[g.jointCount()];
            pointJoints = new int[g.influencesPerPoint()];
            hits = new byte[t.count];
            candidates = new int[t.count];
            shared = new double[4 * t.maxSupport];
            atCentroid = new double[t.maxSupport];
        }
    }

    /** One point's centre into {@code out}. */
    private static void centre(SkinnedGeometry g, int p, SimilarityTriangles t, double inverseSigmaSquared,
            Scratch scratch, float[] out) {
        int support = gatherWeights(g, p, scratch);
        double[] sums = scratch.sums;
        Arrays.fill(sums, 0);
        int found = support >= 2 ? t.candidates(scratch.pointJoints, support, scratch.hits, scratch.candidates) : 0;
        for (int c = 0; c < found; c++) {
            int tri = scratch.candidates[c];
            int m = sharedJoints(t, tri, scratch);
            integrate(t, tri, m, inverseSigmaSquared, scratch);
        }
        float[] rest = g.positionArray();
        if (sums[3] > 0) {
            out[3 * p] = (float) (sums[0] / sums[3]);
            out[3 * p + 1] = (float) (sums[1] / sums[3]);
            out[3 * p + 2] = (float) (sums[2] / sums[3]);
        } else {
            out[3 * p] = rest[3 * p];
            out[3 * p + 1] = rest[3 * p + 1];
            out[3 * p + 2] = rest[3 * p + 2];
        }
        for (int a = 0; a < support; a++) {
            scratch.weightOfJoint[scratch.pointJoints[a]] = 0;
        }
    }

    /**
     * Point p's weight per joint into {@code scratch.weightOfJoint} (summed over repeated joints) and
     * its joints into {@code scratch.pointJoints}; returns how many joints it has.
     */
    private static int gatherWeights(SkinnedGeometry g, int p, Scratch scratch) {
        int k = g.influencesPerPoint();
        int[] joints = g.jointArray();
        float[] weights = g.weightArray();
        float[] weightOfJoint = scratch.weightOfJoint;
        int support = 0;
        for (int a = 0; a < k; a++) {
            float w = weights[k * p + a];
            if (w > 0) {
                int j = joints[k * p + a];
                if (weightOfJoint[j] == 0) {
                    scratch.pointJoints[support++] = j;
                }
                weightOfJoint[j] += w;
            }
        }
        return support;
    }

    /**
     * The joints both the point and triangle {@code tri} weight, into {@code scratch.shared}: per
     * joint w_p and the corners' weights (4 doubles); returns how many.
     */
    private static int sharedJoints(SimilarityTriangles t, int tri, Scratch scratch) {
        double[] shared = scratch.shared;
        int m = 0;
        for (int e = t.start[tri]; e < t.start[tri + 1]; e++) {
            float wp = scratch.weightOfJoint[t.joints[e]];
            if (wp > 0) {
                shared[4 * m] = wp;
                shared[4 * m + 1] = t.cornerWeights[3 * e];
                shared[4 * m + 2] = t.cornerWeights[3 * e + 1];
                shared[4 * m + 3] = t.cornerWeights[3 * e + 2];
                m++;
            }
        }
        return m;
    }

    /**
     * Adds triangle {@code tri}'s n x n grid of sub-triangles by their centroids, at (u, v) n along
     * the edges ab and ac: upward ones at (i + 1/3, j + 1/3), downward ones at (i + 2/3, j + 2/3).
     */
    private static void integrate(SimilarityTriangles t, int tri, int m, double inverseSigmaSquared, Scratch scratch) {
        double[] shared = scratch.shared;
        int n = t.segments[tri];
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n - i; j++) {
                add(t, tri, (i + 1.0 / 3) / n, (j + 1.0 / 3) / n, shared, m, inverseSigmaSquared, scratch);
                if (i + j < n - 1) {
                    add(t, tri, (i + 2.0 / 3) / n, (j + 2.0 / 3) / n, shared, m, inverseSigmaSquared, scratch);
                }
            }
        }
    }

    /**
     * Adds the sub-triangle of triangle {@code tri} centred at (u, v) along its edges ab and ac:
     * its centroid times similarity times area to {@code sums[0..3)}, similarity times area to
     * {@code sums[3]}.
     */
    private static void add(SimilarityTriangles t, int tri, double u, double v, double[] shared, int m,
            double inverseSigmaSquared, Scratch scratch) {
        double sa = t.subArea[tri] * similarity(shared, m, 1 - u - v, u, v, inverseSigmaSquared, scratch.atCentroid);
        double[] x = t.corners;
        int o = 9 * tri;
        double[] sums = scratch.sums;
        for (int d = 0; d < 3; d++) {
            sums[d] += sa * (x[o + d] + u * (x[o + 3 + d] - x[o + d]) + v * (x[o + 6 + d] - x[o + d]));
        }
        sums[3] += sa;
    }

    /**
     * The similarity of the point's weights to those at barycentric (ba, bb, bc) of a triangle,
     * over the shared joints only (the others contribute nothing); each unordered pair once, which
     * halves the paper's sum over ordered pairs, and the factor cancels in the centre's quotient.
     */
    private static double similarity(double[] shared, int m, double ba, double bb, double bc,
            double inverseSigmaSquared, double[] at) {
        for (int q = 0; q < m; q++) {
            at[q] = ba * shared[4 * q + 1] + bb * shared[4 * q + 2] + bc * shared[4 * q + 3];
        }
        double s = 0;
        for (int q = 0; q < m; q++) {
            double pq = shared[4 * q];
            double tq = at[q];
            for (int r = q + 1; r < m; r++) {
                double pr = shared[4 * r];
                double tr = at[r];
                double d = pq * tr - pr * tq;
                s += pq * pr * tq * tr * Math.exp(-d * d * inverseSigmaSquared);
            }
        }
        return s;
    }
}
