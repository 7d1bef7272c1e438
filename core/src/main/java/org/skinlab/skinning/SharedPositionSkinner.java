package org.skinlab.skinning;

/**
 * Skins a geometry whose render vertices share positions ({@link SkinnedGeometry#sharedPositions()})
 * by deforming each position once, with a kernel built on the position-level geometry, and then
 * deriving every point from its position's deformation ({@link DeformationExpansion}).
 *
 * <p>Each call deforms all positions, whatever range of points it is asked for: the deformations
 * of a range's points are not a contiguous range. So split a frame over threads at the level of
 * the position kernel, not by wrapping this skinner in a {@link ParallelSkinner} (which would
 * repeat the position work per chunk). The deformations live in a per-thread scratch array.
 *
 * <p>Positions only ({@link NormalTransform#NONE}) need no deformation: the kernel skins the
 * positions into the scratch and each point copies its position's three floats, the same bits as
 * skinning the point (its position and influences are its position's).
 */
final class SharedPositionSkinner extends AbstractSkinner {
    private final Skinner positionKernel;
    private final DeformationExpansion expansion;
    private final int[] deformationOfPoint;
    private final int positionCount;
    /** Per thread, the positions' deformations, or their skinned positions under {@link NormalTransform#NONE}. */
    private final ThreadLocal<float[]> deformations;
    /** ns per point to copy its skinned position (positions only; see {@link #pays}). */
    static final double COPY_NS = 1;

    /**
     * @param expansion how points are derived from deformations; null for a positions-only kernel
     *                  ({@link NormalTransform#NONE}), whose points copy their positions
     */
    SharedPositionSkinner(SkinnedGeometry geometry, Skinner positionKernel, DeformationExpansion expansion) {
        super(positionKernel.method(), positionKernel.implementation() + ", each position once ("
                + (expansion == null ? "positions copied" : expansion.implementation() + " expansion") + ")", geometry,
                positionKernel.normalTransform());
        if ((expansion == null) != (normals == NormalTransform.NONE)) {
            throw new IllegalArgumentException("an expansion is needed exactly when normals are skinned");
        }
        this.positionKernel = positionKernel;
        this.expansion = expansion;
        this.deformationOfPoint = geometry.deformationOfPointArray();
        this.positionCount = positionKernel.geometry().pointCount();
        int size = (expansion == null ? 3 : DEFORMATION_FLOATS) * positionCount;
        this.deformations = ThreadLocal.withInitial(() -> new float[size]);
    }

    /** The kernel that deforms the positions. */
    Skinner positionKernel() {
        return positionKernel;
    }

    /**
     * Whether skinning each of {@code positions} positions once and deriving {@code points} points
     * from them is cheaper than skinning every point, for a method and {@code influences} per
     * point. The costs per point in ns, fitted to the vector kernels (the scalar kernels favour
     * sharing at least as much; the measurements are in docs/benchmarks.md, "The shared-position
     * rule, measured"):
     * <ul>
     * <li>LBS: directly {@code 2 + 2.2 k}, into a deformation {@code 3 + 1.75 k}, derived from a
     *     deformation 3.4 (with the renormalisation of its normal);</li>
     * <li>DQS: directly {@code 4 + 1.1 k} (8 points per lane group), into a deformation
     *     {@code 6 + k}, derived from a deformation 2 (rotations keep unit normals).</li>
     * <li>CoR: directly {@code 4 + 2.2 k} (two 8-float blends per influence, as LBS), into a
     *     deformation {@code 6 + 2.2 k}, derived from a deformation 2 (its normal matrices are
     *     rotations too).</li>
     * <li>The bone methods (bulge-free DQS, STBS, spline) take CoR's model: each costs more per
     *     point than CoR does, on top of a deformation derived as cheaply, so sharing pays for them
     *     wherever it pays for CoR, and the model errs towards skinning every point.</li>
     * </ul>
     * So the stormtrooper (5174 points on 3275 positions, 6 influences) shares for LBS and,
     * narrowly, for DQS, the thesis' cowboy (4252 on 740) for both by far.
     *
     * <p>Positions only ({@link NormalTransform#NONE}): a position costs what skinning a point
     * directly costs, and a point then copies three floats, {@link #COPY_NS}; so sharing pays from
     * about 1.3 points per position (the stormtrooper's 1.58 shares).
     */
    static boolean pays(SkinningMethod method, NormalTransform rule, int points, int positions, int influences) {
        double direct;
        double intoDeformation;
        double derived;
        if (method == SkinningMethod.LBS) {
            direct = 2 + 2.2 * influences;
            intoDeformation = 3 + 1.75 * influences;
            derived = 3.4;
        } else if (method == SkinningMethod.DQS) {
            direct = 4 + 1.1 * influences;
            intoDeformation = 6 + influences;
            derived = 2;
        } else {
            direct = 4 + 2.2 * influences;
            intoDeformation = 6 + 2.2 * influences;
            derived = 2;
        }
        if (rule == NormalTransform.NONE) {
            return positions * direct + points * COPY_NS < points * direct;
        }
        return positions * intoDeformation + points * derived < points * direct;
    }

    /**
     * The rest normals an expansion for this method and rule should read: for DQS and CoR under
     * the exact rule they are scaled to unit length once here, since the normal matrix of a
     * deformation without a scale part is a rotation, which keeps them unit, and the per-call
     * renormalisation can then be skipped; the geometry's own array otherwise.
     */
    static float[] expansionNormals(SkinningMethod method, NormalTransform rule, SkinnedGeometry geometry) {
        float[] n = geometry.normalArray();
        if (method == SkinningMethod.LBS || rule != NormalTransform.INVERSE_TRANSPOSE) {
            return n;
        }
        float[] unit = new float[n.length];
        for (int i = 0; i < n.length; i += 3) {
            float len2 = n[i] * n[i] + n[i + 1] * n[i + 1] + n[i + 2] * n[i + 2];
            float inv = len2 > 0f ? (float) (1.0 / Math.sqrt(len2)) : 0f;
            unit[i] = n[i] * inv;
            unit[i + 1] = n[i + 1] * inv;
            unit[i + 2] = n[i + 2] * inv;
        }
        return unit;
    }

    /** The positions are skinned by the position kernel; the expansion's normals do not morph here. */
    @Override
    public void restShapeChanged() {
        positionKernel.restShapeChanged();
    }

    @Override
    public void skin(JointPalette palette, float[] outPositions, float[] outNormals, int from, int to) {
        float[] f = deformations.get();
        if (expansion == null) {
            positionKernel.skin(palette, f, null, 0, positionCount);
            for (int i = from; i < to; i++) {
                System.arraycopy(f, 3 * deformationOfPoint[i], outPositions, 3 * i, 3);
            }
            return;
        }
        positionKernel.skinDeformations(palette, f, 0, positionCount);
        // DQS's and CoR's normal matrices without scale are rotations of unit normals (see
        // expansionNormals); LBS's and STBS-on-LBS's are cofactors of blended matrices, never
        // unit; spline's are blends of rotations.
        boolean normalise = normals == NormalTransform.INVERSE_TRANSPOSE && (method() == SkinningMethod.LBS
                || method() == SkinningMethod.STBS_LBS || method() == SkinningMethod.SPLINE || palette.hasScale());
        expansion.expand(f, outPositions, outNormals, from, to, normalise);
    }

    @Override
    public void skinDeformations(JointPalette palette, float[] outDeformations, int from, int to) {
        float[] f = deformations.get();
        positionKernel.skinDeformations(palette, f, 0, positionCount);
        for (int i = from; i < to; i++) {
            System.arraycopy(f, DEFORMATION_FLOATS * deformationOfPoint[i], outDeformations, DEFORMATION_FLOATS * i, DEFORMATION_FLOATS);
        }
    }
}
