package org.skinlab.skinning;

import org.joml.Matrix4f;
import org.skinlab.animation.AnimationHelper;

/**
 * One frame's joint data for a skinner: the skinning matrices, and what DQS derives from them once
 * per joint per frame (not per vertex, as the thesis did).
 *
 * <p>{@link #matrices()}: per joint a 3x4 affine matrix, row-major (r00 r01 r02 tx, r10 ...), the
 * layout of the shared benchmark reference. Filled by
 * {@link org.skinlab.animation.Skeleton#skinningMatrices}.
 *
 * <p><b>DQS with scale: the two-phase split.</b> A dual quaternion holds only rotation and
 * translation. Following Kavan et al. 2008 (section 4, "scale and shear") each skinning matrix is
 * split into {@code M = D * S}, D rigid and S a scale/shear; per vertex the S are blended
 * linearly (unscaled joints contribute the identity), the D as dual quaternions, and the vertex
 * goes through the blended S first. Where S is centred matters once blended; we centre it on the
 * joint's bind frame, as Blender's armature modifier does with "preserve volume" (its
 * {@code mat4_to_dquat} uses the bone's rest matrix), so that scaling a bone along its own axis
 * scales the skin about that bone. Concretely, with {@code B} the rigid part of the joint's bind
 * frame {@code inverse(bind)} (bind = INV_BIND, the points being in bind space; see
 * {@code SkinnedGeometry}): {@code X = M B} is the joint's posed frame;
 * {@code X = [R|t] S0}; then {@code S = B S0 B^-1} and {@code D = [R|t] B^-1}. Joints whose posed
 * frame has unit columns (within 1e-4, Blender's threshold) and no reflection skip the split: S
 * is the identity and D = M.
 *
 * <p>Which rotation R a scaled frame has is a convention once the frame is sheared (a child of a
 * non-uniformly scaled joint is). We take Blender 3.4's: keep the frame's Y axis (the bone axis
 * in Blender's rigs and in files exported from them) and orthogonalise the others to it
 * ({@code orthogonalize_m4(m, 1)}), so our DQS agrees with Blender's to float precision on our
 * own assets; the polar rotation would differ by 0.7% of the tentacle's size (see
 * docs/references.md). Frames without a usable Y axis fall back to the polar rotation.
 */
public final class JointPalette {
    private final int joints;
    private final float[] matrices;
    private final float[] dualQuaternions;
    private final float[] scales;
    /** Per joint this frame's rigid part D, row-major 3x4 (the bone rows read it too). */
    private final float[] rigidParts;
    /** Derives {@link #scales}, {@link #rigidParts} and {@link #dualQuaternions} from the matrices. */
    private final ScaleSplit split;
    private boolean scaled;
    /** The bone rows' owner, or null for a palette without bones. */
    private final BoneRows boneRows;
    /** Whether the dual quaternions and scales, and the bone rows, follow the current matrices. */
    private boolean dualQuaternionsReady;
    private boolean boneRowsReady;

    /**
     * @param bindMatrices per joint 16 floats column-major, the matrix that takes bind-shape
     *                     coordinates into the joint's frame (INV_BIND)
     */
    public JointPalette(float[] bindMatrices) {
        this(bindMatrices, null);
    }

    /**
     * As {@link #JointPalette(float[])} for a palette whose joints have bones, for the methods
     * that read them ({@link #boneRows()}).
     *
     * @param bindMatrices as {@link #JointPalette(float[])}
     * @param bones        the bones of the same joints ({@link SkinnedGeometry#bones()}), or null
     */
    public JointPalette(float[] bindMatrices, Bones bones) {
        if (bindMatrices.length % 16 != 0) {
            throw new IllegalArgumentException("bind matrices need 16 floats each");
        }
        if (bones != null && bones.jointCount() != bindMatrices.length / 16) {
            throw new IllegalArgumentException(bones.jointCount() + " bones for " + bindMatrices.length / 16 + " joints");
        }
        this.boneRows = bones == null ? null : new BoneRows(bones);
        joints = bindMatrices.length / 16;
        matrices = new float[12 * joints];
        dualQuaternions = new float[8 * joints];
        scales = new float[12 * joints];
        rigidParts = new float[12 * joints];
        split = new ScaleSplit(bindMatrices, matrices, rigidParts, scales, dualQuaternions);
        for (int j = 0; j < joints; j++) {
            setIdentity3x4(matrices, 12 * j);
        }
    }

    /**
     * A palette of {@code joints} joints whose bind frames are at the origin (e.g. benchmarks).
     *
     * @param joints the number of joints, not negative
     * @return a new palette with identity bind matrices, identity skinning matrices and no bones
     */
    public static JointPalette withoutBindFrames(int joints) {
        float[] identities = new float[16 * joints];
        for (int j = 0; j < joints; j++) {
            identities[16 * j] = identities[16 * j + 5] = identities[16 * j + 10] = identities[16 * j + 15] = 1f;
        }
        return new JointPalette(identities);
    }

    /**
     * The number of joints.
     *
     * @return joints in the palette
     */
    public int jointCount() {
        return joints;
    }

    /**
     * Per joint 12 floats, the row-major 3x4 skinning matrix: read by skinners. Read-only: write
     * through {@link #writableMatrices()} or {@link #setMatrix}, which tell the palette that what
     * it derives from the matrices must be derived again.
     *
     * @return the matrices, not a copy
     */
    public float[] matrices() {
        return matrices;
    }

    /**
     * The matrices' array for writing this frame's skinning matrices into (e.g.
     * {@link org.skinlab.animation.Skeleton#skinningMatrices}): everything derived from them is
     * stale from now until the next {@link #prepare}.
     *
     * @return the matrices, not a copy
     */
    public float[] writableMatrices() {
        dualQuaternionsReady = false;
        boneRowsReady = false;
        return matrices;
    }

    /**
     * Per joint 8 floats (real x y z w, dual x y z w): the dual quaternion of the rigid part D,
     * once {@link #prepare} has run for a method that reads it. Read-only.
     *
     * @return the dual quaternions, not a copy
     */
    public float[] dualQuaternions() {
        return dualQuaternions;
    }

    /**
     * Per joint 12 floats, row-major 3x4: the scale/shear part S, once {@link #prepare} has run
     * for a method that reads dual quaternions. Read-only.
     *
     * @return the scale parts, not a copy
     */
    public float[] scales() {
        return scales;
    }

    /**
     * Whether some joint's skinning matrix mirrors (a negative determinant of its linear part) in
     * the current matrices. The kernels' exact normals then carry the sign of each blended
     * matrix's determinant (the cofactor alone would turn normals inwards there); without a
     * mirroring joint they use the cofactor as is, which keeps the common case free of that cost.
     * Computed from {@link #matrices()} on each call (9 multiplications per joint).
     *
     * @return whether some joint's matrix mirrors
     */
    public boolean mirrorsMatrices() {
        return mirrors(matrices, joints);
    }

    /**
     * As {@link #mirrorsMatrices()} for the DQS scale parts, once prepared.
     *
     * @return whether some joint's scale part mirrors
     */
    public boolean mirrorsScales() {
        return scaled && mirrors(scales, joints);
    }

    private static boolean mirrors(float[] m, int joints) {
        for (int j = 0; j < joints; j++) {
            int o = 12 * j;
            float det = m[o] * (m[o + 5] * m[o + 10] - m[o + 9] * m[o + 6])
                    + m[o + 1] * (m[o + 6] * m[o + 8] - m[o + 10] * m[o + 4])
                    + m[o + 2] * (m[o + 4] * m[o + 9] - m[o + 8] * m[o + 5]);
            if (det < 0f) {
                return true;
            }
        }
        return false;
    }

    /**
     * Whether some joint has a scale part this frame (DQS must run its first phase), once prepared.
     *
     * @return true when some scale part is not the identity
     */
    public boolean hasScale() {
        return scaled;
    }

    /**
     * Sets a joint's skinning matrix (as {@link #writableMatrices()}, derived data goes stale).
     *
     * @param j      the joint
     * @param matrix its skinning matrix (the affine part is taken)
     */
    public void setMatrix(int j, Matrix4f matrix) {
        AnimationHelper.putRowMajor3x4(matrix, writableMatrices(), 12 * j);
    }

    /**
     * A joint's skinning matrix as a JOML matrix.
     *
     * @param j    the joint
     * @param dest where to put it
     * @return dest
     */
    public Matrix4f getMatrix(int j, Matrix4f dest) {
        return AnimationHelper.getRowMajor3x4(matrices, 12 * j, dest);
    }

    /**
     * Derives from the current matrices what {@code method} reads besides them, unless that is
     * derived already: the dual quaternions and scale parts for the methods that read them
     * ({@link SkinningMethod#usesDualQuaternions()}), and the bone rows too for the methods that
     * read bones ({@link SkinningMethod#usesBones()}). Each is derived once per set of matrices,
     * however many methods or geometries ask. Allocation-free.
     *
     * @param method the method about to skin with this palette
     * @return this palette
     * @throws IllegalStateException for a bone method on a palette made without bones
     */
    public JointPalette prepare(SkinningMethod method) {
        if (method.usesDualQuaternions() || method.usesBones()) {
            prepareDualQuaternions();
        }
        if (method.usesBones()) {
            prepareBones();
        }
        return this;
    }

    /**
     * Derives everything a palette can carry ({@link #prepare} for every method): for a reader
     * that may apply any method to this frame, e.g. a renderer drawing two methods side by side.
     *
     * @return this palette
     */
    public JointPalette prepareAll() {
        prepareDualQuaternions();
        if (boneRows != null) {
            prepareBones();
        }
        return this;
    }

    /**
     * Makes this palette a copy of {@code source}: its matrices and whatever it has derived from
     * them, and which of that is current. Allocation-free.
     *
     * @param source a palette of as many joints, with bones when this one has them
     * @throws IllegalArgumentException when the two differ in joints or bones
     */
    public void set(JointPalette source) {
        if (source.joints != joints || (boneRows == null) != (source.boneRows == null)) {
            throw new IllegalArgumentException("a palette of " + source.joints + " joints"
                    + (source.boneRows == null ? "" : " with bones") + " copied into one of " + joints
                    + (boneRows == null ? "" : " with bones"));
        }
        System.arraycopy(source.matrices, 0, matrices, 0, matrices.length);
        System.arraycopy(source.dualQuaternions, 0, dualQuaternions, 0, dualQuaternions.length);
        System.arraycopy(source.scales, 0, scales, 0, scales.length);
        System.arraycopy(source.rigidParts, 0, rigidParts, 0, rigidParts.length);
        if (boneRows != null) {
            System.arraycopy(source.boneRows.rows(), 0, boneRows.rows(), 0, boneRows.rows().length);
        }
        scaled = source.scaled;
        dualQuaternionsReady = source.dualQuaternionsReady;
        boneRowsReady = source.boneRowsReady;
    }

    /**
     * Derives each joint's dual quaternion (and scale part) from {@link #matrices()}, when not done
     * for these matrices yet ({@link ScaleSplit}).
     */
    private void prepareDualQuaternions() {
        if (dualQuaternionsReady) {
            return;
        }
        scaled = split.run();
        dualQuaternionsReady = true;
    }

    /** Floats per joint in {@link #boneRows()}: six rows of four. */
    public static final int BONE_FLOATS = 24;

    /**
     * Per joint {@link #BONE_FLOATS} floats, once {@link #prepare} has run for a bone method: what the bone methods
     * ({@link SkinningMethod#usesBones()}) read of this frame, in rows of four (the GPU uploads
     * them as they are). With M the joint's skinning matrix, D its rigid part (the DQS split),
     * h and t its bone's rest head and tail ({@link Bones}, bind space), L = |t - h|:
     * <pre>
     * row 0  M h (the posed head)                 | twist angle (radians, see below)
     * row 1  M t (the posed tail)                 | stretch |M (t - h)| / L (1 when L = 0)
     * row 2  M t - D t (the tail's stretch offset) | 0
     * row 3  D's rotation of (t - h) / L          | 0   (the posed bone axis; Y of the bind frame when L = 0)
     * row 4  h                                    | L
     * row 5  t                                    | the parent joint's index (-1 for a root)
     * </pre>
     * The twist is the angle of the joint's rotation relative to its parent's (both D's, so since
     * the bind pose) about its rest bone axis, the twist of the swing-twist split, in (-pi, pi];
     * 0 for a root, whose turns are rigid motions of everything it carries.
     *
     * @return the bone rows, not a copy
     * @throws IllegalStateException for a palette made without bones
     */
    public float[] boneRows() {
        if (boneRows == null) {
            throw new IllegalStateException("this palette was made without bones");
        }
        return boneRows.rows();
    }

    /**
     * Whether the palette was made with bones, so that {@link #boneRows()} exists.
     *
     * @return true when made with {@link Bones} (as {@link SkinnedGeometry#newPalette()} does)
     */
    public boolean hasBones() {
        return boneRows != null;
    }

    /** Fills the bone rows from this frame's matrices and dual quaternions, when not done yet. */
    private void prepareBones() {
        if (boneRows == null) {
            throw new IllegalStateException("this palette was made without bones: its geometry's bones are needed");
        }
        if (!boneRowsReady) {
            boneRows.fill(matrices, rigidParts, dualQuaternions, split.pivots());
            boneRowsReady = true;
        }
    }

    private static void setIdentity3x4(float[] a, int o) {
        java.util.Arrays.fill(a, o, o + 12, 0f);
        a[o] = 1f;
        a[o + 5] = 1f;
        a[o + 10] = 1f;
    }
}
