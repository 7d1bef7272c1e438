package org.skinlab.skinning;

/**
 * Spline-based skinning's precomputation (Forstmann et al. 2007, "Deformation Styles for
 * Spline-based Skeletal Animation"; the thesis, section 3.3.6): which curve each influence of a
 * point follows and where on it the point sits. Immutable; made once per geometry from its rest
 * shape and {@link Bones}.
 *
 * <p><b>The curves.</b> One curve <em>across</em> each joint c whose parent p continues into it
 * ({@code p}'s tail joint is c) and whose two bones have length: the three control points are
 * the middle of p's bone, c's head (the joint) and the middle of c's bone,
 * <pre>
 * f(x)  = p1 + D12 (1 - (1 - x)^a) + D23 x^a,          D12 = p2 - p1, D23 = p3 - p2
 * f'(x) = a D12 (1 - x)^(a-1) + a D23 x^(a-1)
 * </pre>
 * with stiffness a (a = 2 is the quadratic Bezier curve; a = 1 the straight line p1 p3; large a
 * approaches the bent bones themselves). Consecutive curves of a chain meet at the middles of the
 * bones with the bones' directions, so a chain is one smooth curve. The rest curve has the rest
 * segments ({@link Bones}), the posed one the posed segments (the palette's bone rows).
 *
 * <p><b>Which curve an influence follows.</b> Influence (point i, joint j) with the point's rest
 * position projected on j's bone at s (0 at the head, 1 at the tail): below the middle
 * (s &lt; 1/2) the curve across j's head, from the middle on the curve across j's tail joint.
 * Where that curve does not exist (the lower half of a root, the upper half of a leaf, a side
 * branch such as a thigh off the hips, a bone of length 0) the influence is <em>rigid</em>: it
 * moves with j's skinning matrix as in LBS. Both rules meet continuously at the middle of a bone,
 * where a curve's frame is its bone's. Near a joint, the parent's and the child's influences of a
 * point both land on the curve across that joint at the same place, so the weights only blend
 * where a point straddles different curves.
 *
 * <p><b>Where on the curve.</b> The thesis' binary search: starting in the middle of the curve,
 * halve [0, 1] towards the side the point lies on until it lies in the plane through f(x)
 * perpendicular to f'(x) ({@code (p - f(x)) . f'(x) = 0}); a point beyond an end's plane takes
 * that end. Stored per influence: the curve (the joint it crosses, -1 rigid), x and the four
 * powers {@code 1 - (1-x)^a, x^a, a (1-x)^(a-1), a x^(a-1)}, so a kernel evaluates f and f'
 * without a power function. The point's offset from the rest curve is not stored: kernels take
 * it from the current rest shape each frame, so a morphing rest shape is followed (its points
 * keep the x found on the shape this binding was made from).
 */
public final class SplineBinding {
    /** Floats per influence slot in {@link #parameterArray()}. */
    public static final int PARAMETER_FLOATS = 5;
    /**
     * Default stiffness a: 6 keeps a 170-degree fold within 2% of the rest volume on the bend
     * cylinder (the curve is shorter than the bent bones by 3% of its length there; a = 2 loses
     * half of it, docs/skinning.md) while still rounding the joint.
     */
    public static final float DEFAULT_STIFFNESS = 6f;
    /** Halvings of the search: x to 2^-40, below float precision. */
    private static final int SEARCH_STEPS = 40;

    private final float stiffness;
    private final int width;
    private final int[] curves;
    private final float[] parameters;

    private SplineBinding(float stiffness, int width, int[] curves, float[] parameters) {
        this.stiffness = stiffness;
        this.width = width;
        this.curves = curves;
        this.parameters = parameters;
    }

    /**
     * The binding of a geometry's points with {@link #DEFAULT_STIFFNESS}.
     *
     * @param geometry the geometry, with its bones ({@link SkinnedGeometry#bones()}); its current rest
     *                 positions are bound
     * @return a new binding; bind-time work, a binary search per influence slot
     */
    public static SplineBinding of(SkinnedGeometry geometry) {
        return of(geometry, DEFAULT_STIFFNESS);
    }

    /**
     * The binding of a geometry's points (its current rest positions) to curves of stiffness a.
     *
     * @param geometry the geometry, with its bones ({@link SkinnedGeometry#bones()})
     * @param a        the curves' stiffness, at least 1 (see the class comment)
     * @return a new binding; bind-time work, a binary search per influence slot
     * @throws IllegalArgumentException unless {@code a >= 1}
     */
    public static SplineBinding of(SkinnedGeometry geometry, float a) {
        if (!(a >= 1f)) {
            throw new IllegalArgumentException("stiffness must be at least 1, not " + a);
        }
        Bones bones = geometry.bones();
        int width = geometry.influencesPerPoint();
        int points = geometry.pointCount();
        float[] positions = geometry.positionArray();
        int[] joints = geometry.jointArray();
        int[] curves = new int[width * points];
        float[] parameters = new float[PARAMETER_FLOATS * width * points];
        double[] controls = new double[9];
        for (int i = 0; i < points; i++) {
            for (int k = 0; k < width; k++) {
                int slot = width * i + k;
                int curve = curveOf(bones, joints[slot], positions, i);
                curves[slot] = curve;
                if (curve < 0) {
                    continue;
                }
                restControls(bones, curve, controls);
                double x = search(controls, a, positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]);
                int o = PARAMETER_FLOATS * slot;
                parameters[o] = (float) x;
                parameters[o + 1] = (float) (1 - Math.pow(1 - x, a));
                parameters[o + 2] = (float) Math.pow(x, a);
                parameters[o + 3] = (float) (a * Math.pow(1 - x, a - 1));
                parameters[o + 4] = (float) (a * Math.pow(x, a - 1));
            }
        }
        return new SplineBinding(a, width, curves, parameters);
    }

    /**
     * Whether a curve crosses joint c: its parent continues into it and both bones have length.
     *
     * @param bones the bones of a geometry's palette
     * @param c     a palette joint
     * @return true when c has a parent whose tail joint is c, and both bones are longer than 0
     */
    public static boolean hasCurve(Bones bones, int c) {
        int p = bones.parent(c);
        return p >= 0 && bones.tailJoint(p) == c && bones.length(p) > 0f && bones.length(c) > 0f;
    }

    /** The curve influence (point i, joint j) follows, or -1 for rigid (class comment). */
    private static int curveOf(Bones bones, int j, float[] positions, int i) {
        float length = bones.length(j);
        if (!(length > 0f)) {
            return -1;
        }
        double along = 0;
        for (int axis = 0; axis < 3; axis++) {
            along += (positions[3 * i + axis] - bones.head(j, axis)) * (double) (bones.tail(j, axis) - bones.head(j, axis));
        }
        int c = along < 0.5 * length * length ? j : bones.tailJoint(j);
        return c >= 0 && hasCurve(bones, c) ? c : -1;
    }

    /** The rest control points p1, p2, p3 of the curve across joint c, into {@code dest[0..9)}. */
    private static void restControls(Bones bones, int c, double[] dest) {
        int p = bones.parent(c);
        for (int axis = 0; axis < 3; axis++) {
            dest[axis] = 0.5 * ((double) bones.head(p, axis) + bones.tail(p, axis));
            dest[3 + axis] = bones.head(c, axis);
            dest[6 + axis] = 0.5 * ((double) bones.head(c, axis) + bones.tail(c, axis));
        }
    }

    /** The thesis' binary search for x with (q - f(x)) . f'(x) = 0, from the middle of the curve. */
    private static double search(double[] controls, double a, double qx, double qy, double qz) {
        double lo = 0;
        double hi = 1;
        for (int step = 0; step < SEARCH_STEPS; step++) {
            double x = 0.5 * (lo + hi);
            double side = side(controls, a, x, qx, qy, qz);
            if (side == 0) {
                return x;
            }
            if (side > 0) {
                lo = x;
            } else {
                hi = x;
            }
        }
        return 0.5 * (lo + hi);
    }

    /** (q - f(x)) . f'(x): positive when q lies beyond the plane at x. */
    private static double side(double[] c, double a, double x, double qx, double qy, double qz) {
        double b1 = 1 - Math.pow(1 - x, a);
        double b2 = Math.pow(x, a);
        double d1 = a * Math.pow(1 - x, a - 1);
        double d2 = a * Math.pow(x, a - 1);
        double sum = 0;
        double[] q = {qx, qy, qz};
        for (int axis = 0; axis < 3; axis++) {
            double e12 = c[3 + axis] - c[axis];
            double e23 = c[6 + axis] - c[3 + axis];
            double f = c[axis] + e12 * b1 + e23 * b2;
            sum += (q[axis] - f) * (e12 * d1 + e23 * d2);
        }
        return sum;
    }

    /**
     * The stiffness a of the curves this binding was made for.
     *
     * @return a, at least 1
     */
    public float stiffness() {
        return stiffness;
    }

    /**
     * Influence slots per point, as in the geometry.
     *
     * @return the geometry's {@link SkinnedGeometry#influencesPerPoint()}
     */
    public int influencesPerPoint() {
        return width;
    }

    /**
     * The joint whose curve slot {@code slot} of point {@code point} follows, or -1 (rigid).
     *
     * @param point a point of the geometry
     * @param slot  an influence slot of that point, {@code [0, influencesPerPoint())}
     * @return the palette joint the curve crosses, or -1 when the influence moves rigidly with its joint
     */
    public int curve(int point, int slot) {
        return curves[width * point + slot];
    }

    /**
     * The curve parameter x of a slot (0 for a rigid one).
     *
     * @param point a point of the geometry
     * @param slot  an influence slot of that point, {@code [0, influencesPerPoint())}
     * @return x in [0, 1]: 0 at the middle of the parent's bone, 1 at the middle of the crossed joint's
     */
    public float x(int point, int slot) {
        return parameters[PARAMETER_FLOATS * (width * point + slot)];
    }

    /** Per influence slot (point-major, as the geometry's joints) the curve joint or -1. Read-only. */
    int[] curveArray() {
        return curves;
    }

    /**
     * Per influence slot {@link #PARAMETER_FLOATS} floats: x, 1 - (1-x)^a, x^a, a (1-x)^(a-1),
     * a x^(a-1). Read-only.
     */
    float[] parameterArray() {
        return parameters;
    }
}
