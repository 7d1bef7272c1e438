package org.skinlab.skinning;

import java.nio.FloatBuffer;
import java.nio.ShortBuffer;

/**
 * A geometry's influences cut to a fixed number per point and packed for a GPU vertex attribute:
 * what a shader that skins with {@code k} joints per vertex reads. Built once from a
 * {@link SkinnedGeometry}; immutable.
 *
 * <p><b>Which influences.</b> Per point the {@code k} heaviest of the geometry's influences,
 * heaviest first (the DQS pivot stays in slot 0). Equal weights keep the geometry's order, which
 * for an imported skin is the file's order: the result never depends on anything but the input.
 * When a point loses an influence of non-zero weight, its kept weights are divided by their sum
 * so they add up to one again (the point keeps its rigid motion when all its joints move
 * together). A point that loses nothing keeps its weights bit for bit, as the geometry has them
 * ({@link SkinnedGeometry#of} has already divided them by their sum; {@code fromArrays} rows are
 * used as given, as the geometry's own kernels use them): so a cap at or above the geometry's
 * influence count deforms exactly as the geometry does.
 *
 * <p><b>Padding.</b> A slot with weight 0 (a point with fewer influences than {@code k}, a
 * {@code k} above the geometry's width, a weight the file wrote as 0) holds the joint of slot 0,
 * so it costs a shader nothing but a multiplication by zero.
 *
 * <p><b>Layout for OpenGL / OpenGL ES 3.</b> Points in the geometry's order: its render
 * vertices first ({@link #vertexCount()}), then positions no triangle uses, which a renderer
 * leaves out. Per point {@code k} joint indices as <em>unsigned 16-bit</em> integers in a
 * {@code short[]} (Java has no unsigned short; values above 32767 read negative in Java, which
 * the GPU does not see), so any palette of up to 65536 joints fits one format; and {@code k}
 * floats of weight. With the view's two arrays in two buffers (tightly packed, as
 * {@link #putJointIndices} and {@link #putWeights} write them), a vertex shader with
 * {@code in uvec4 joints0; in vec4 weights0;} (and {@code joints1}/{@code weights1} for slots 4
 * to 7) is fed, for attribute {@code a = 0, 1, ...}, with
 * <pre>
 * glVertexAttribIPointer(jointsLocation + a, min(4, k - 4a), GL_UNSIGNED_SHORT, 2 * k, 8 * a);
 * glVertexAttribPointer(weightsLocation + a, min(4, k - 4a), GL_FLOAT, false, 4 * k, 16 * a);
 * </pre>
 * ({@code glVertexAttribIPointer}, not {@code glVertexAttribPointer}, so the indices reach the
 * shader as integers, not as floats.)
 */
public final class InfluenceView {
    /** The most joints an unsigned 16-bit index can address. */
    public static final int MAX_JOINTS = 1 << 16;

    private final int influences;
    private final int pointCount;
    private final int vertexCount;
    private final int jointCount;
    private final int sourceInfluences;
    private final short[] joints;
    private final float[] weights;
    private final float[] dropped;
    private final int cappedPoints;

    private InfluenceView(int influences, int pointCount, int vertexCount, int jointCount, int sourceInfluences,
            short[] joints, float[] weights, float[] dropped, int cappedPoints) {
        this.influences = influences;
        this.pointCount = pointCount;
        this.vertexCount = vertexCount;
        this.jointCount = jointCount;
        this.sourceInfluences = sourceInfluences;
        this.joints = joints;
        this.weights = weights;
        this.dropped = dropped;
        this.cappedPoints = cappedPoints;
    }

    /**
     * The view of a geometry with {@code k} influences per point (any {@code k >= 1}; 4 and 8 are
     * what shaders usually take).
     *
     * @param geometry the geometry whose influences are cut; its arrays are read, not kept
     * @param k        influences per point in the view, at least 1
     * @return a new view
     * @throws IllegalArgumentException if {@code k < 1} or the palette has more than
     *                                  {@value #MAX_JOINTS} joints
     */
    public static InfluenceView of(SkinnedGeometry geometry, int k) {
        if (k < 1) {
            throw new IllegalArgumentException("influences per point must be at least 1, not " + k);
        }
        if (geometry.jointCount() > MAX_JOINTS) {
            throw new IllegalArgumentException(geometry + ": " + geometry.jointCount()
                    + " joints do not fit unsigned 16-bit indices (at most " + MAX_JOINTS + ")");
        }
        int points = geometry.pointCount();
        int width = geometry.influencesPerPoint();
        int[] sourceJoints = geometry.jointArray();
        float[] sourceWeights = geometry.weightArray();
        short[] joints = new short[k * points];
        float[] weights = new float[k * points];
        float[] dropped = new float[points];
        int[] order = new int[width];
        int capped = 0;
        for (int i = 0; i < points; i++) {
            sortByDecreasingWeight(sourceWeights, width * i, width, order);
            if (capRow(sourceJoints, sourceWeights, width, i, order, k, joints, weights, dropped)) {
                capped++;
            }
        }
        return new InfluenceView(k, points, geometry.vertexCount(), geometry.jointCount(), width, joints, weights,
                dropped, capped);
    }

    /**
     * The slots of the row at {@code o} into {@code order}, by decreasing weight: a stable
     * insertion sort, a no-op for the rows {@link SkinnedGeometry#of} sorts already, needed for
     * {@link SkinnedGeometry#fromArrays} rows taken as given.
     */
    private static void sortByDecreasingWeight(float[] sourceWeights, int o, int width, int[] order) {
        for (int a = 0; a < width; a++) {
            int e = a;
            int b = a - 1;
            while (b >= 0 && sourceWeights[o + order[b]] < sourceWeights[o + e]) {
                order[b + 1] = order[b];
                b--;
            }
            order[b + 1] = e;
        }
    }

    /**
     * Writes point {@code i}'s {@code k} heaviest influences (in {@code order}) into {@code joints}
     * and {@code weights}, renormalised when the cap dropped weight, and that weight into
     * {@code dropped}; returns whether it dropped any.
     */
    private static boolean capRow(int[] sourceJoints, float[] sourceWeights, int width, int i, int[] order, int k,
            short[] joints, float[] weights, float[] dropped) {
        int o = width * i;
        int kept = Math.min(k, width);
        double lostWeight = 0;
        boolean lost = false;
        for (int s = kept; s < width; s++) {
            lostWeight += sourceWeights[o + order[s]];
            lost |= sourceWeights[o + order[s]] != 0f;
        }
        dropped[i] = (float) lostWeight;
        double sum = 0;
        for (int s = 0; s < kept; s++) {
            sum += sourceWeights[o + order[s]];
        }
        // A sum of zero or less only comes from fromArrays rows (negative weights): kept as given.
        boolean renormalise = lost && sum > 0;
        int d = k * i;
        int first = sourceJoints[o + order[0]];
        for (int s = 0; s < k; s++) {
            float w = s < kept ? sourceWeights[o + order[s]] : 0f;
            if (renormalise) {
                w = (float) (w / sum);
            }
            weights[d + s] = w;
            joints[d + s] = (short) (w == 0f ? first : sourceJoints[o + order[s]]);
        }
        return lost;
    }

    /**
     * Influences per point in this view ({@code k}).
     *
     * @return k, the stride of {@link #jointIndices()} and {@link #weights()}
     */
    public int influencesPerPoint() {
        return influences;
    }

    /**
     * Influences per point of the geometry it was made from.
     *
     * @return the geometry's {@link SkinnedGeometry#influencesPerPoint()}
     */
    public int sourceInfluencesPerPoint() {
        return sourceInfluences;
    }

    /**
     * Number of points, as in the geometry.
     *
     * @return the geometry's {@link SkinnedGeometry#pointCount()}
     */
    public int pointCount() {
        return pointCount;
    }

    /**
     * Points {@code [0, vertexCount)} are the mesh's render vertices, what a renderer uploads.
     *
     * @return the geometry's {@link SkinnedGeometry#vertexCount()}
     */
    public int vertexCount() {
        return vertexCount;
    }

    /**
     * Palette size of the geometry: every joint index is below it.
     *
     * @return the geometry's {@link SkinnedGeometry#jointCount()}, at most {@value #MAX_JOINTS}
     */
    public int jointCount() {
        return jointCount;
    }

    /**
     * How many points lost an influence of non-zero weight to the cap (0: the view is exact).
     *
     * @return the number of capped points, in {@code [0, pointCount()]}
     */
    public int cappedPointCount() {
        return cappedPoints;
    }

    /**
     * The weight the cap dropped at a point, before the kept weights were renormalised: the sum
     * of the geometry's weights beyond the {@code k} kept (0 when the point lost nothing).
     *
     * @param point a point, {@code [0, pointCount())}
     * @return the dropped weight, not negative for a geometry's normalised weights
     */
    public float droppedWeight(int point) {
        return dropped[point];
    }

    /**
     * Palette joint of slot {@code slot} of point {@code point}.
     *
     * @param point a point, {@code [0, pointCount())}
     * @param slot  a slot, {@code [0, influencesPerPoint())}, heaviest first
     * @return the joint index, in {@code [0, jointCount())}; slot 0's joint for a zero-weight slot
     * @throws IndexOutOfBoundsException for a slot outside the view
     */
    public int joint(int point, int slot) {
        return Short.toUnsignedInt(joints[influences * point + checkSlot(slot)]);
    }

    /**
     * Weight of slot {@code slot} of point {@code point}.
     *
     * @param point a point, {@code [0, pointCount())}
     * @param slot  a slot, {@code [0, influencesPerPoint())}, heaviest first
     * @return the weight, renormalised when the point was capped; 0 for padding
     * @throws IndexOutOfBoundsException for a slot outside the view
     */
    public float weight(int point, int slot) {
        return weights[influences * point + checkSlot(slot)];
    }

    private int checkSlot(int slot) {
        if (slot < 0 || slot >= influences) {
            throw new IndexOutOfBoundsException("slot " + slot + " of " + influences);
        }
        return slot;
    }

    /**
     * A copy of the joint indices, {@code k} per point: unsigned 16-bit values (read them with
     * {@link Short#toUnsignedInt}), for {@code GL_UNSIGNED_SHORT}.
     *
     * @return {@code k * pointCount()} indices, point-major; a new array on each call
     */
    public short[] jointIndices() {
        return joints.clone();
    }

    /**
     * A copy of the weights, {@code k} per point.
     *
     * @return {@code k * pointCount()} weights, point-major and parallel to {@link #jointIndices()}; a new
     *         array on each call
     */
    public float[] weights() {
        return weights.clone();
    }

    /**
     * Joint indices of all points as palette indices in an {@code int[]} ({@code k} per point),
     * e.g. for {@link SkinnedGeometry#fromArrays}.
     *
     * @return {@code k * pointCount()} joint indices, point-major; a new array
     */
    public int[] jointIndicesAsInts() {
        int[] result = new int[joints.length];
        for (int i = 0; i < joints.length; i++) {
            result[i] = Short.toUnsignedInt(joints[i]);
        }
        return result;
    }

    /**
     * Writes the joint indices of points {@code [0, points)} at the buffer's position (relative
     * put: the position advances by {@code k * points}), e.g. into a direct buffer for
     * {@code glBufferData}. Pass {@link #vertexCount()} to upload the render vertices.
     *
     * @param dest   the buffer, with room for {@code k * points} shorts
     * @param points how many points to write, from the first, {@code [0, pointCount()]}
     * @throws IndexOutOfBoundsException when {@code points} is outside {@code [0, pointCount()]}
     */
    public void putJointIndices(ShortBuffer dest, int points) {
        dest.put(joints, 0, influences * checkPoints(points));
    }

    /**
     * As {@link #putJointIndices} for the weights.
     *
     * @param dest   the buffer, with room for {@code k * points} floats
     * @param points how many points to write, from the first, {@code [0, pointCount()]}
     * @throws IndexOutOfBoundsException when {@code points} is outside {@code [0, pointCount()]}
     */
    public void putWeights(FloatBuffer dest, int points) {
        dest.put(weights, 0, influences * checkPoints(points));
    }

    private int checkPoints(int points) {
        if (points < 0 || points > pointCount) {
            throw new IndexOutOfBoundsException(points + " points of " + pointCount);
        }
        return points;
    }

    @Override
    public String toString() {
        return "InfluenceView[" + pointCount + " points, " + influences + " of " + sourceInfluences
                + " influences, " + cappedPoints + " points capped]";
    }
}
