package org.skinlab.skinning;

/**
 * Bulge-free DQS's precomputation (Kim and Han 2014, as the thesis' section "DQS - Wölbungen"
 * describes it): per point the bone segment it keeps its distance from, and that distance at
 * rest. Immutable.
 *
 * <p><b>Which segment.</b> The candidates are the bones ({@link Bones}: head to tail in bind space,
 * a point-like leaf being its head) of the joints that influence the point with weight above 0:
 * a bone that does not move the point says nothing about where it should be, and the choice can
 * then be redone on the GPU from the vertex's own influences without a new attribute. Of these,
 * the nearest at rest (the thesis: "the nearest bone segment, usually the heaviest"); a candidate
 * replaces an earlier (heavier) one only when it is nearer by more than {@link #TIE} of the
 * distance, so ties (the ring at a joint, which is as far from both bones) go to the heavier
 * influence whatever the rounding, on the CPU and in the shader alike.
 *
 * <p><b>Morphs.</b> The choice is made from the rest positions the geometry holds when this is
 * built; a skinner whose geometry's rest shape morphs refreshes the distances to the same
 * segments per frame ({@link #restDistances}), which is what the shader computes from the
 * uploaded morphed shape.
 */
public final class BulgeFreeBinding {
    /**
     * The excess over the rest distance a pulled point keeps at most, relative to the rest
     * distance and to the spread of its two heaviest influences ({@link #pulledDistance},
     * {@link #spread}). 0 would be the thesis' formula; 0.05 keeps 0.31 of DQS's bulge at 90 and
     * at 170 degrees of bend while the volume stays within 1.2% and 1.9% of rest on the bend
     * cylinder, where the thesis' formula loses 2.2% and 3.5% (BulgeFreeDqsTest). The shader has
     * the same constant (skinning.glsl, {@code bfdqs}).
     */
    public static final float ALLOWANCE = 0.05f;

    /** A later candidate must be nearer than {@code (1 - TIE)} times the best so far. */
    public static final float TIE = 1e-4f;

    private final int[] joints;
    private final float[] restDistances;
    /** Per point its two heaviest influences' joints (the first twice when it has one). */
    private final int[] pairs;

    private BulgeFreeBinding(int[] joints, float[] restDistances, int[] pairs) {
        this.joints = joints;
        this.restDistances = restDistances;
        this.pairs = pairs;
    }

    /**
     * The binding of every point of a geometry, from its current rest positions and its bones.
     *
     * @param geometry the geometry, with its bones ({@link SkinnedGeometry#bones()})
     * @return a new binding; bind-time work, one pass over the points' influences
     */
    public static BulgeFreeBinding of(SkinnedGeometry geometry) {
        Bones bones = geometry.bones();
        float[] p = geometry.positionArray();
        int[] influenceJoints = geometry.jointArray();
        float[] weights = geometry.weightArray();
        int width = geometry.influencesPerPoint();
        int points = geometry.pointCount();
        int[] joints = new int[points];
        float[] distances = new float[points];
        int[] pairs = new int[2 * points];
        for (int i = 0; i < points; i++) {
            pairs[2 * i] = influenceJoints[width * i];
            pairs[2 * i + 1] = width > 1 && weights[width * i + 1] > 0f ? influenceJoints[width * i + 1]
                    : influenceJoints[width * i];
            int best = influenceJoints[width * i];
            float nearest = Float.POSITIVE_INFINITY;
            for (int k = 0; k < width; k++) {
                int j = influenceJoints[width * i + k];
                if (!(weights[width * i + k] > 0f) && k > 0) {
                    continue;
                }
                float d = distanceToBone(bones, j, p[3 * i], p[3 * i + 1], p[3 * i + 2]);
                if (d < (1f - TIE) * nearest) {
                    nearest = d;
                    best = j;
                }
            }
            joints[i] = best;
            distances[i] = nearest;
        }
        return new BulgeFreeBinding(joints, distances, pairs);
    }

    /**
     * The distance from its bone a point at distance {@code d > r} (r its reference distance) is
     * pulled back to: {@code r + e a / sqrt(a^2 + e^2)} with e = d - r and
     * a = ALLOWANCE spread r, a smooth saturation of the excess (slope 1 at e = 0, never above a);
     * r itself when a = 0. DQS's bulge grows with the sine of half the bend angle (spread), and
     * so does what is kept of it.
     *
     * @param d      the point's distance from its posed bone after DQS, in bind-space units
     * @param r      its reference distance (the rest distance, or its scaled image), not negative
     * @param spread the spread of its two heaviest influences ({@link #spread}), in [0, 1]
     * @return the distance to pull the point to, in [r, d]
     */
    public static float pulledDistance(float d, float r, float spread) {
        float a = ALLOWANCE * spread * r;
        float e = d - r;
        // At least the smallest normal float under the root: a = 0 with e rounded to 0 gives r.
        return r + e * a / (float) Math.sqrt(Math.max(a * a + e * e, Float.MIN_NORMAL));
    }

    /** Distance of a point from joint j's rest bone (its head when the bone has no length). */
    static float distanceToBone(Bones bones, int j, float px, float py, float pz) {
        float hx = bones.head(j, 0), hy = bones.head(j, 1), hz = bones.head(j, 2);
        float ex = bones.tail(j, 0) - hx, ey = bones.tail(j, 1) - hy, ez = bones.tail(j, 2) - hz;
        float ax = px - hx, ay = py - hy, az = pz - hz;
        float t = segmentParameter(ax, ay, az, ex, ey, ez);
        float dx = ax - t * ex, dy = ay - t * ey, dz = az - t * ez;
        return (float) Math.sqrt(dx * dx + dy * dy + dz * dz);
    }

    /**
     * Where on a segment (head + t e, t in [0, 1]) the nearest point to head + a lies: the
     * projection's parameter clamped to the segment; 0 for a segment of no length (its head).
     */
    static float segmentParameter(float ax, float ay, float az, float ex, float ey, float ez) {
        float len2 = ex * ex + ey * ey + ez * ez;
        return len2 > 0f ? Math.max(0f, Math.min(1f, (ax * ex + ay * ey + az * ez) / len2)) : 0f;
    }

    /**
     * The joints of all points, copied.
     *
     * @return per point, the palette joint whose rest bone it keeps its distance from
     */
    public int[] jointArray() {
        return joints.clone();
    }

    /**
     * Per point the joints of its two heaviest influences (the first twice when it has one), copied.
     *
     * @return 2 palette joints per point, heaviest first, for {@link #spread}
     */
    public int[] pairArray() {
        return pairs.clone();
    }

    /**
     * sin(theta / 2) for theta the angle between the rotations of two joints whose dual
     * quaternions (real part first, unit) sit at {@code 8 a} and {@code 8 b} in {@code dq}:
     * {@code sqrt(1 - (q_a . q_b)^2)}, whichever sign either has.
     *
     * @param dq the palette's dual quaternions ({@link JointPalette#dualQuaternions()}), 8 floats per joint
     * @param a  one palette joint
     * @param b  another palette joint (or a itself, giving 0)
     * @return the spread, in [0, 1]: 0 for the same rotation, 1 for rotations half a turn apart
     */
    public static float spread(float[] dq, int a, int b) {
        int p = 8 * a;
        int q = 8 * b;
        float dot = dq[p] * dq[q] + dq[p + 1] * dq[q + 1] + dq[p + 2] * dq[q + 2] + dq[p + 3] * dq[q + 3];
        return (float) Math.sqrt(Math.max(0f, 1f - dot * dot));
    }

    /**
     * The rest distances of all points, copied.
     *
     * @return per point, its distance from its bone in the rest positions the binding was made from,
     *         in bind-space units
     */
    public float[] restDistanceArray() {
        return restDistances.clone();
    }

    /**
     * Each point's distance from its own bone in rest positions {@code positions} (a morphed rest
     * shape) into {@code dest}, allocation-free.
     *
     * @param bones     the geometry's bones, as when the binding was made
     * @param positions the rest positions, 3 floats per point, bind space
     * @param dest      receives one distance per point
     */
    public void restDistances(Bones bones, float[] positions, float[] dest) {
        for (int i = 0; i < joints.length; i++) {
            dest[i] = distanceToBone(bones, joints[i], positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]);
        }
    }

    @Override
    public String toString() {
        return "BulgeFreeBinding[" + joints.length + " points]";
    }
}
