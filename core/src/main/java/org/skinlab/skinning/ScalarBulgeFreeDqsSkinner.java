package org.skinlab.skinning;

/**
 * Bulge-free DQS in plain Java (Kim and Han 2014, as the thesis' section "DQS - Wölbungen" and
 * the public readings of the paper describe it): DQS exactly ({@link ScalarDqsSkinner}, whose
 * output this kernel then corrects), then per point, with k its bone and r its rest distance
 * ({@link BulgeFreeBinding}):
 * <ol>
 * <li>c, the nearest point to the DQS position q on k's posed bone, the segment from M h to M t
 *     (rows 0 and 1 of {@link JointPalette#boneRows()});</li>
 * <li>d = |q - c|; when d > r the point is moved towards c, {@code q' = c + (q - c) d' / d}, to
 *     {@code d' = r + e a / sqrt(a^2 + e^2)} with e = d - r the excess and
 *     a = {@link BulgeFreeBinding#ALLOWANCE} s r, s the sine of half the angle between the
 *     rotations of the point's two heaviest influences ({@link BulgeFreeBinding#spread},
 *     {@link BulgeFreeBinding#pulledDistance}): the thesis' formula (d' = r) is its limit a = 0;
 *     with a > 0 a small excess stays nearly as DQS made it and a large one is cut smoothly to at
 *     most a, which keeps a fixed part of DQS's bulge and of the volume it held (the fold's inside
 *     loses volume that only the bulge made up for; docs/skinning.md has the figures). Points
 *     that came nearer (the inside of a bend) stay.</li>
 * </ol>
 * <b>Scaled joints.</b> When the palette has scale, r is the rest offset from the bone as k's
 * matrix maps it, {@code |M_k (p - c_rest)|} (c_rest the nearest point of the rest bone): a joint
 * scaled across its bone widens the skin it carries, and comparing with the unscaled rest
 * distance would pull that widening back. Without scale it is the rest distance itself.
 *
 * <p><b>Normals</b> are DQS's: the pull moves points along the direction from the bone, which
 * changes the surface's normal only where neighbours are pulled by different ratios; the seam
 * measure ({@link NormalSeams}) and docs/skinning.md quantify what that leaves.
 */
public final class ScalarBulgeFreeDqsSkinner extends AbstractSkinner {
    private final ScalarDqsSkinner dqs;
    private final float[] restPositions;
    private final int[] boneJoints;
    private final int[] pairs;
    private final float[] restDistances;
    private final BulgeFreeBinding binding;

    /**
     * A skinner whose binding ({@link BulgeFreeBinding#of}) is computed now: bind-time work.
     *
     * @param geometry the geometry to skin, with its bones
     * @param normals  how normals move (as DQS moves them); not {@link NormalTransform#NONE}
     * @throws IllegalArgumentException under {@link NormalTransform#NONE}
     */
    public ScalarBulgeFreeDqsSkinner(SkinnedGeometry geometry, NormalTransform normals) {
        super(SkinningMethod.BFDQS, "scalar", geometry, normals);
        this.dqs = new ScalarDqsSkinner(geometry, normals);
        this.restPositions = geometry.positionArray();
        this.binding = BulgeFreeBinding.of(geometry);
        this.boneJoints = binding.jointArray();
        this.pairs = binding.pairArray();
        this.restDistances = binding.restDistanceArray();
    }

    @Override
    public void skin(JointPalette palette, float[] outPositions, float[] outNormals, int from, int to) {
        dqs.skin(palette, outPositions, outNormals, from, to);
        pull(palette, outPositions, 3, 0, from, to);
    }

    @Override
    public void skinDeformations(JointPalette palette, float[] outDeformations, int from, int to) {
        dqs.skinDeformations(palette, outDeformations, from, to);
        // A deformation's position sits at floats 8..10 (Skinner.skinDeformations).
        pull(palette, outDeformations, DEFORMATION_FLOATS, 8, from, to);
    }

    /** The correction of points [from, to) whose DQS positions are at {@code stride * i + offset}. */
    private void pull(JointPalette palette, float[] out, int stride, int offset, int from, int to) {
        float[] rows = palette.boneRows();
        float[] m = palette.matrices();
        float[] dq = palette.dualQuaternions();
        boolean scaled = palette.hasScale();
        for (int i = from; i < to; i++) {
            pullPoint(rows, scaled ? m : null, restPositions, i, boneJoints[i], restDistances[i],
                    BulgeFreeBinding.spread(dq, pairs[2 * i], pairs[2 * i + 1]), out, stride * i + offset);
        }
    }

    /**
     * Pulls one DQS position {@code out[o..o+3)} (rest position {@code rest[3i..3i+3)}, bone of
     * joint k, rest distance r) towards k's posed bone when it is farther than r from it, to
     * {@link BulgeFreeBinding#pulledDistance}. With {@code matrices} (a palette with scale) the
     * reference distance is {@code |M_k (p - c_rest)|} instead of r. Shared with the vector kernel.
     *
     * @param rows     the palette's bone rows ({@link JointPalette#boneRows()}), prepared this frame
     * @param matrices the palette's skinning matrices when it has scale ({@link JointPalette#hasScale()}),
     *                 else null
     * @param rest     the rest positions, 3 floats per point, bind space
     * @param i        the point
     * @param k        the palette joint of the point's bone ({@link BulgeFreeBinding#jointArray()})
     * @param r        the point's rest distance from that bone; unused when {@code matrices} is given
     * @param spread   the spread of the point's two heaviest influences ({@link BulgeFreeBinding#spread})
     * @param out      holds the DQS position at {@code o}, replaced by the pulled one
     * @param o        the offset of the position's x in {@code out}
     */
    public static void pullPoint(float[] rows, float[] matrices, float[] rest, int i, int k, float r, float spread,
            float[] out, int o) {
        int b = JointPalette.BONE_FLOATS * k;
        float hx = rows[b], hy = rows[b + 1], hz = rows[b + 2];
        float ex = rows[b + 4] - hx, ey = rows[b + 5] - hy, ez = rows[b + 6] - hz;
        float qx = out[o], qy = out[o + 1], qz = out[o + 2];
        float ax = qx - hx, ay = qy - hy, az = qz - hz;
        float t = BulgeFreeBinding.segmentParameter(ax, ay, az, ex, ey, ez);
        float ux = ax - t * ex, uy = ay - t * ey, uz = az - t * ez;
        float d2 = ux * ux + uy * uy + uz * uz;
        if (matrices != null) {
            r = scaledRestDistance(rows, matrices, rest, i, k);
        }
        if (d2 > r * r) {
            float d = (float) Math.sqrt(d2);
            float f = BulgeFreeBinding.pulledDistance(d, r, spread) / d;
            out[o] = hx + t * ex + ux * f;
            out[o + 1] = hy + t * ey + uy * f;
            out[o + 2] = hz + t * ez + uz * f;
        }
    }

    /** {@code |M_k (p - c_rest)|}: the rest offset from joint k's rest bone, through k's matrix. */
    private static float scaledRestDistance(float[] rows, float[] m, float[] rest, int i, int k) {
        int b = JointPalette.BONE_FLOATS * k;
        float hx = rows[b + 16], hy = rows[b + 17], hz = rows[b + 18];
        float ex = rows[b + 20] - hx, ey = rows[b + 21] - hy, ez = rows[b + 22] - hz;
        float ax = rest[3 * i] - hx, ay = rest[3 * i + 1] - hy, az = rest[3 * i + 2] - hz;
        float t = BulgeFreeBinding.segmentParameter(ax, ay, az, ex, ey, ez);
        float ux = ax - t * ex, uy = ay - t * ey, uz = az - t * ez;
        int c = 12 * k;
        float vx = m[c] * ux + m[c + 1] * uy + m[c + 2] * uz;
        float vy = m[c + 4] * ux + m[c + 5] * uy + m[c + 6] * uz;
        float vz = m[c + 8] * ux + m[c + 9] * uy + m[c + 10] * uz;
        return (float) Math.sqrt(vx * vx + vy * vy + vz * vz);
    }

    /** A morphed rest shape: the same bones, the distances of the new shape. */
    @Override
    public void restShapeChanged() {
        binding.restDistances(geometry.bones(), restPositions, restDistances);
    }
}
