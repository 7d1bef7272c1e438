package org.skinlab.skinning;

/**
 * Skins a geometry whose render vertices share positions ({@link SkinnedGeometry#sharedPositions()})
 * by deforming each position once into a frame, with a kernel built on the position-level
 * geometry, and then deriving every point from its position's frame ({@link DeformationExpansion}).
 *
 * <p>Each call deforms all positions, whatever range of points it is asked for: the frames of a
 * range's positions are not a contiguous range. So split a frame over threads at the level of the
 * position kernel, not by wrapping this skinner in a {@link ParallelSkinner} (which would repeat
 * the position work per chunk). The frames live in a per-thread scratch array.
 */
final class SharedPositionSkinner extends AbstractSkinner {
    private final Skinner positionKernel;
    private final DeformationExpansion expansion;
    private final int[] deformationOfPoint;
    private final int positionCount;
    private final ThreadLocal<float[]> frames;

    SharedPositionSkinner(SkinnedGeometry geometry, Skinner positionKernel, DeformationExpansion expansion) {
        super(positionKernel.method(), positionKernel.implementation() + ", each position once ("
                + expansion.implementation() + " expansion)", geometry, positionKernel.normalTransform());
        this.positionKernel = positionKernel;
        this.expansion = expansion;
        this.deformationOfPoint = geometry.deformationOfPointArray();
        this.positionCount = positionKernel.geometry().pointCount();
        int size = DEFORMATION_FLOATS * positionCount;
        this.frames = ThreadLocal.withInitial(() -> new float[size]);
    }

    /** The kernel that deforms the positions. */
    Skinner positionKernel() {
        return positionKernel;
    }

    /**
     * Whether skinning each of {@code positions} positions once and deriving {@code points} points
     * from them is cheaper than skinning every point, for a method and {@code influences} per
     * point. The costs per point in ns, fitted to the vector kernels on JDK 17 (docs/benchmarks.md,
     * "Each position once"; the scalar kernels favour sharing at least as much):
     * <ul>
     * <li>LBS: directly {@code 2 + 2.2 k}, into a frame {@code 3 + 1.75 k}, derived from a frame 3.4
     *     (with the renormalisation of its normal);</li>
     * <li>DQS: directly {@code 4 + 1.1 k} (8 points per lane group), into a frame {@code 6 + k},
     *     derived from a frame 2 (rotations keep unit normals).</li>
     * <li>CoR: directly {@code 4 + 2.2 k} (two 8-float blends per influence, as LBS), into a frame
     *     {@code 6 + 2.2 k}, derived from a frame 2 (its frames are rotations too); measured on
     *     the stormtrooper (JDK 25), both ways take the same time (58 and 59 µs), on the cowboy sharing
     *     wins by far (19 against 44 µs).</li>
     * <li>The bone methods (bulge-free DQS, STBS, spline) take CoR's model: each costs more per
     *     point than CoR does, on top of a frame derived as cheaply, so sharing pays for them
     *     wherever it pays for CoR, and the model errs towards skinning every point.</li>
     * </ul>
     * So the stormtrooper (5174 points on 3275 positions, 6 influences) shares for LBS (measured
     * 61 against 81 µs) and, narrowly, for DQS (48 against 53 µs), the thesis' cowboy (4252 on
     * 740) for both by far.
     */
    static boolean pays(SkinningMethod method, int points, int positions, int influences) {
        double direct;
        double frame;
        double derived;
        if (method == SkinningMethod.LBS) {
            direct = 2 + 2.2 * influences;
            frame = 3 + 1.75 * influences;
            derived = 3.4;
        } else if (method == SkinningMethod.DQS) {
            direct = 4 + 1.1 * influences;
            frame = 6 + influences;
            derived = 2;
        } else {
            direct = 4 + 2.2 * influences;
            frame = 6 + 2.2 * influences;
            derived = 2;
        }
        return positions * frame + points * derived < points * direct;
    }

    /**
     * The rest normals an expansion for this method and rule should read: for DQS and CoR under
     * the exact rule they are scaled to unit length once here, since a frame without a scale part is a
     * rotation, which keeps them unit, and the per-call renormalisation can then be skipped; the
     * geometry's own array otherwise.
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
        float[] f = frames.get();
        positionKernel.skinDeformations(palette, f, 0, positionCount);
        // DQS and CoR frames without scale are rotations of unit normals (see expansionNormals);
        // LBS's and STBS-on-LBS's are cofactors of blended matrices, never unit; spline frames are
        // blends of rotations.
        boolean normalise = normals == NormalTransform.INVERSE_TRANSPOSE && (method() == SkinningMethod.LBS
                || method() == SkinningMethod.STBS_LBS || method() == SkinningMethod.SPLINE || palette.hasScale());
        expansion.expand(f, outPositions, outNormals, from, to, normalise);
    }

    @Override
    public void skinDeformations(JointPalette palette, float[] outDeformations, int from, int to) {
        float[] f = frames.get();
        positionKernel.skinDeformations(palette, f, 0, positionCount);
        for (int i = from; i < to; i++) {
            System.arraycopy(f, DEFORMATION_FLOATS * deformationOfPoint[i], outDeformations, DEFORMATION_FLOATS * i, DEFORMATION_FLOATS);
        }
    }
}
