package org.skinlab.desktop.bench;

import org.skinlab.skinning.JointPalette;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinningMethod;

/**
 * The synthetic skinning input of the shared side-by-side benchmark ({@code ../shared/perf/}:
 * {@code skin_ref.cpp} and its Java twin), bit-identical to it: splitmix64 with seed 42 drawn in
 * the same order, 64 joints with random rigid transforms (a normalised random quaternion and a
 * translation in [-1,1)^3), and per point a position in [-1,1)^3, a unit normal, 4 distinct
 * random joints and 4 positive weights normalised to sum 1. Every float is computed with the same
 * operations in the same order as the C++ (Java float arithmetic is IEEE single precision without
 * contraction, as g++ -O3 without -ffast-math on x86-64), so the inputs are equal bit for bit.
 */
public final class SyntheticSkinData {
    public static final int JOINTS = 64;
    /** Influences per point of the reference's data. */
    public static final int INFLUENCES = 4;
    public static final long SEED = 42L;

    private final int points;
    private final int influences;
    /** Per joint a row-major 3x4 affine matrix (r00 r01 r02 tx, r10 ..). */
    private final float[] matrices = new float[12 * JOINTS];
    /** Per joint a unit dual quaternion, real (x y z w) then dual (x y z w). */
    private final float[] dualQuaternions = new float[8 * JOINTS];
    private final float[] positions;
    private final float[] normals;
    private final int[] joints;
    private final float[] weights;

    /** The data of {@code points} points with the reference's seed. */
    public SyntheticSkinData(int points) {
        this(points, SEED);
    }

    public SyntheticSkinData(int points, long seed) {
        this(points, seed, INFLUENCES);
    }

    /**
     * Data with {@code influences} distinct joints per point (1 to {@link #JOINTS}), drawn the same
     * way; with {@link #INFLUENCES} it is the reference's, bit for bit. Other counts measure how the
     * cost grows with influences, on the same joints and positions.
     */
    public SyntheticSkinData(int points, long seed, int influences) {
        if (points < 0) {
            throw new IllegalArgumentException("points must not be negative, was " + points);
        }
        if (influences < 1 || influences > JOINTS) {
            throw new IllegalArgumentException("influences must be 1 to " + JOINTS + ", was " + influences);
        }
        this.points = points;
        this.influences = influences;
        SplitMix64 r = new SplitMix64(seed);
        for (int j = 0; j < JOINTS; j++) {
            drawJoint(r, j);
        }
        positions = new float[3 * points];
        normals = new float[3 * points];
        joints = new int[influences * points];
        weights = new float[influences * points];
        int[] ids = new int[influences];
        float[] ws = new float[influences];
        for (int i = 0; i < points; i++) {
            drawPoint(r, i, ids, ws);
        }
    }

    /** Joint {@code j}: a random rotation (a normalised random quaternion) and translation, as a matrix and a dual quaternion. */
    private void drawJoint(SplitMix64 r, int j) {
        float x = r.nextSigned();
        float y = r.nextSigned();
        float z = r.nextSigned();
        float w = r.nextSigned();
        float n = (float) Math.sqrt(x * x + y * y + z * z + w * w);
        x /= n;
        y /= n;
        z /= n;
        w /= n;
        float tx = r.nextSigned();
        float ty = r.nextSigned();
        float tz = r.nextSigned();
        float[] m = matrices;
        int o = 12 * j;
        m[o] = 1 - 2 * (y * y + z * z);
        m[o + 1] = 2 * (x * y - w * z);
        m[o + 2] = 2 * (x * z + w * y);
        m[o + 3] = tx;
        m[o + 4] = 2 * (x * y + w * z);
        m[o + 5] = 1 - 2 * (x * x + z * z);
        m[o + 6] = 2 * (y * z - w * x);
        m[o + 7] = ty;
        m[o + 8] = 2 * (x * z - w * y);
        m[o + 9] = 2 * (y * z + w * x);
        m[o + 10] = 1 - 2 * (x * x + y * y);
        m[o + 11] = tz;
        // d = (t, 0) r / 2 (Kavan et al. 2008)
        float[] q = dualQuaternions;
        int p = 8 * j;
        q[p] = x;
        q[p + 1] = y;
        q[p + 2] = z;
        q[p + 3] = w;
        q[p + 4] = 0.5f * (tx * w + ty * z - tz * y);
        q[p + 5] = 0.5f * (-tx * z + ty * w + tz * x);
        q[p + 6] = 0.5f * (tx * y - ty * x + tz * w);
        q[p + 7] = -0.5f * (tx * x + ty * y + tz * z);
    }

    /** Point {@code i}: position, unit normal, {@link #influences} distinct joints and normalised weights. */
    private void drawPoint(SplitMix64 r, int i, int[] ids, float[] ws) {
        for (int k = 0; k < 3; k++) {
            positions[3 * i + k] = r.nextSigned();
        }
        float nx = r.nextSigned();
        float ny = r.nextSigned();
        float nz = r.nextSigned();
        float nn = (float) Math.sqrt(nx * nx + ny * ny + nz * nz);
        if (nn < 1e-6f) {
            nx = 0;
            ny = 0;
            nz = 1;
            nn = 1;
        }
        normals[3 * i] = nx / nn;
        normals[3 * i + 1] = ny / nn;
        normals[3 * i + 2] = nz / nn;
        int got = 0;
        while (got < influences) {
            int c = (int) (r.next() & (JOINTS - 1));
            boolean duplicate = false;
            for (int k = 0; k < got; k++) {
                duplicate |= ids[k] == c;
            }
            if (!duplicate) {
                ids[got++] = c;
            }
        }
        float sum = 0;
        for (int k = 0; k < influences; k++) {
            ws[k] = 0.05f + r.nextFloat();
            sum += ws[k];
        }
        for (int k = 0; k < influences; k++) {
            joints[influences * i + k] = ids[k];
            weights[influences * i + k] = ws[k] / sum;
        }
    }

    public int pointCount() {
        return points;
    }

    public int influences() {
        return influences;
    }

    /** The reference's joint matrices (row-major 3x4 per joint). Read-only. */
    public float[] matrices() {
        return matrices;
    }

    /** The reference's dual quaternions (8 floats per joint). Read-only. */
    public float[] dualQuaternions() {
        return dualQuaternions;
    }

    /**
     * The points as a runtime geometry: influences in the order drawn (the first is the DQS
     * pivot, as in the C++), identity bind matrices.
     */
    public SkinnedGeometry geometry() {
        float[] bind = new float[16 * JOINTS];
        for (int j = 0; j < JOINTS; j++) {
            bind[16 * j] = bind[16 * j + 5] = bind[16 * j + 10] = bind[16 * j + 15] = 1f;
        }
        return SkinnedGeometry.fromArrays(positions, normals, influences, joints, weights, bind);
    }

    /**
     * A palette holding the reference's joint matrices, with its dual quaternions derived by
     * {@link JointPalette#prepare} (equal to {@link #dualQuaternions()} up to
     * sign and float noise; see SyntheticSkinDataTest).
     */
    public JointPalette palette() {
        JointPalette palette = JointPalette.withoutBindFrames(JOINTS);
        System.arraycopy(matrices, 0, palette.writableMatrices(), 0, matrices.length);
        palette.prepare(SkinningMethod.DQS);
        return palette;
    }

    /**
     * The reference's checksum: sum of the output positions plus half the sum of the normals, in
     * double; {@code outNormals} null for positions-only skinning (the sum of the positions, as
     * {@code bench/cpp/skin_positions.cpp} reports it).
     */
    public static double checksum(float[] outPositions, float[] outNormals) {
        double s = 0;
        for (float x : outPositions) {
            s += x;
        }
        if (outNormals != null) {
            for (float x : outNormals) {
                s += 0.5 * x;
            }
        }
        return s;
    }

    /** Steele, Lea and Flood's splitmix64 (2014), as in the reference. */
    private static final class SplitMix64 {
        private long state;

        SplitMix64(long seed) {
            state = seed;
        }

        long next() {
            long z = state += 0x9E3779B97F4A7C15L;
            z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
            z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
            return z ^ (z >>> 31);
        }

        /** [0, 1) from the top 24 bits. */
        float nextFloat() {
            return (float) (next() >>> 40) * (1.0f / 16777216.0f);
        }

        /** [-1, 1). */
        float nextSigned() {
            return nextFloat() * 2.0f - 1.0f;
        }
    }
}
