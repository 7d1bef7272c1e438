package org.skinlab.skinning;

/**
 * Spline-based skinning (Forstmann et al. 2007) in plain Java, any number of influences. Each
 * influence of a point follows a curve across a joint or its joint rigidly ({@link SplineBinding}
 * says which, and where on the curve). Per influence on the curve across joint c (parent p) at x:
 * <ol>
 * <li>the curve from the palette's bone rows: posed control points p1 = (M_p h_p + M_p t_p)/2,
 *     p2 = M_c h_c, p3 = (M_c h_c + M_c t_c)/2 (rows 0 and 1), rest ones from the rest segments
 *     (rows 4 and 5); f(x), f'(x) and the rest f0(x), f0'(x) from the binding's powers;</li>
 * <li>the frame at x: {@code Q = slerp(q_p, q_c, x)} of the joints' rotations (the palette's dual
 *     quaternions' real parts, the rigid parts D), then turned by the minimal rotation T that
 *     takes {@code Q f0'(x)} onto {@code f'(x)}: {@code F = T Q}, so the cross-section stays
 *     perpendicular to the curve and the twist is spread linearly in x. In the rest pose F = I;</li>
 * <li>{@code p_k = f(x) + F (p - f0(x))}, the normal turned by F; with joint scale this frame
 *     the offset first goes through the scale parts blended along the curve,
 *     {@code p_k = f(x) + F S(x) (p - f0(x))}, {@code S(x) = (1 - x) S_p + x S_c} (linear parts;
 *     see {@link JointPalette}), so cross-sections squash and stretch with their bones.</li>
 * </ol>
 * A rigid influence gives {@code p_k = M_j p}, its normal matrix M_j's (cofactor under exact
 * normals). The point is {@code sum_k w_k p_k}, its normal matrix {@code sum_k w_k N_k}. At the
 * ends of a curve F is the bone's rotation and f the bone's middle, so a point moves with its
 * bone there whichever side it is bound to (M = D S). The palette must have its
 * dual quaternions and bone rows prepared.
 */
public final class ScalarSplineSkinner extends AbstractSkinner {
    private final float[] positions;
    private final float[] restNormals;
    private final int[] joints;
    private final float[] weights;
    private final int width;
    private final int[] curves;
    private final float[] parameters;
    /**
     * Offsets in the per-thread scratch, after p' (0..2), the normal matrix row-major (3..11) and
     * one influence's F (12..20): that influence's normal matrix (3x3), and S(x) as a 3x4 for its
     * cofactor (the translation column unused).
     */
    private static final int NORMAL_MATRIX = 21, SCALE = 30;
    private final ThreadLocal<float[]> scratch = ThreadLocal.withInitial(() -> new float[SCALE + 12]);

    /**
     * A skinner with the default binding ({@link SplineBinding#of(SkinnedGeometry)}), computed now:
     * bind-time work.
     *
     * @param geometry the geometry to skin, with its bones
     * @param normals  how normals move; not {@link NormalTransform#NONE}
     * @throws IllegalArgumentException under {@link NormalTransform#NONE}
     */
    public ScalarSplineSkinner(SkinnedGeometry geometry, NormalTransform normals) {
        this(geometry, normals, SplineBinding.of(geometry));
    }

    /**
     * A skinner with a binding of the caller's choice of stiffness (made for this geometry).
     *
     * @param geometry the geometry to skin
     * @param normals  how normals move; not {@link NormalTransform#NONE}
     * @param binding  the binding of this geometry's points ({@link SplineBinding#of(SkinnedGeometry, float)})
     * @throws IllegalArgumentException when the binding's influence slots do not match the geometry's,
     *                                  or under {@link NormalTransform#NONE}
     */
    public ScalarSplineSkinner(SkinnedGeometry geometry, NormalTransform normals, SplineBinding binding) {
        super(SkinningMethod.SPLINE, "scalar", geometry, normals);
        if (binding.influencesPerPoint() != geometry.influencesPerPoint()
                || binding.curveArray().length != geometry.jointArray().length) {
            throw new IllegalArgumentException("the binding was made for another geometry");
        }
        this.positions = geometry.positionArray();
        this.restNormals = geometry.normalArray();
        this.joints = geometry.jointArray();
        this.weights = geometry.weightArray();
        this.width = geometry.influencesPerPoint();
        this.curves = binding.curveArray();
        this.parameters = binding.parameterArray();
    }

    /**
     * Point {@code i}: its deformed position into {@code out[0..3)} and its normal matrix (row-major
     * 3x3) into {@code out[3..12)}.
     */
    private void deform(JointPalette palette, int i, boolean exactNormals, boolean mirrors, float[] out) {
        java.util.Arrays.fill(out, 0, 12, 0f);
        int o = width * i;
        int v = 3 * i;
        float px = positions[v], py = positions[v + 1], pz = positions[v + 2];
        for (int k = 0; k < width; k++) {
            float w = weights[o + k];
            if (w == 0f) {
                continue;
            }
            int c = curves[o + k];
            if (c < 0) {
                addRigid(palette.matrices(), 12 * joints[o + k], w, px, py, pz, exactNormals, mirrors, out);
            } else if (firstOnCurve(o, k, c)) {
                addCurve(palette, c, PARAMETER_OFFSET * (o + k), curveWeight(o, k, c), px, py, pz, exactNormals, out);
            }
        }
    }

    /**
     * Whether slot k is the first weighted slot of its point on curve c. Slots on one curve share
     * x (one search on one rest curve), so the curve is evaluated once with their summed weight:
     * near a joint the parent's and the child's influences usually land on the same curve.
     */
    private boolean firstOnCurve(int o, int k, int c) {
        for (int m = 0; m < k; m++) {
            if (curves[o + m] == c && weights[o + m] != 0f) {
                return false;
            }
        }
        return true;
    }

    /** The weight of slot k plus that of the later slots on the same curve. */
    private float curveWeight(int o, int k, int c) {
        float w = weights[o + k];
        for (int m = k + 1; m < width; m++) {
            if (curves[o + m] == c) {
                w += weights[o + m];
            }
        }
        return w;
    }

    private static final int PARAMETER_OFFSET = SplineBinding.PARAMETER_FLOATS;

    /**
     * Adds w M_j p and w N_j: M_j's linear part, or under exact normals its
     * {@linkplain SkinningSteps#signedCofactor cofactor} (signed when the palette mirrors), built in
     * {@code out[NORMAL_MATRIX..)}.
     */
    private static void addRigid(float[] m, int o, float w, float px, float py, float pz, boolean exactNormals,
            boolean mirrors, float[] out) {
        out[0] += w * (m[o] * px + m[o + 1] * py + m[o + 2] * pz + m[o + 3]);
        out[1] += w * (m[o + 4] * px + m[o + 5] * py + m[o + 6] * pz + m[o + 7]);
        out[2] += w * (m[o + 8] * px + m[o + 9] * py + m[o + 10] * pz + m[o + 11]);
        if (exactNormals) {
            SkinningSteps.signedCofactor(m, o, mirrors, out, NORMAL_MATRIX);
        } else {
            SkinningSteps.linearPart(m, o, out, NORMAL_MATRIX);
        }
        for (int c = 0; c < 9; c++) {
            out[3 + c] += w * out[NORMAL_MATRIX + c];
        }
    }

    private static void addScaled(float[] out, float w, float n0, float n1, float n2, float n3, float n4, float n5,
            float n6, float n7, float n8) {
        out[3] += w * n0;
        out[4] += w * n1;
        out[5] += w * n2;
        out[6] += w * n3;
        out[7] += w * n4;
        out[8] += w * n5;
        out[9] += w * n6;
        out[10] += w * n7;
        out[11] += w * n8;
    }

    /** Adds w (f(x) + F (p - f0(x))) and w F for the curve across joint c (class comment). */
    private void addCurve(JointPalette palette, int c, int q, float w, float px, float py, float pz,
            boolean exactNormals, float[] out) {
        final float[] rows = palette.boneRows();
        final float[] dq = palette.dualQuaternions();
        int b = JointPalette.BONE_FLOATS * c;
        int parent = (int) rows[b + 23];
        int a = JointPalette.BONE_FLOATS * parent;
        float x = parameters[q], b1 = parameters[q + 1], b2 = parameters[q + 2];
        float d1 = parameters[q + 3], d2 = parameters[q + 4];
        // Posed curve: p1 the middle of the parent's posed bone, p2 the joint, p3 the middle of c's.
        float p2x = rows[b], p2y = rows[b + 1], p2z = rows[b + 2];
        float e12x = p2x - 0.5f * (rows[a] + rows[a + 4]);
        float e12y = p2y - 0.5f * (rows[a + 1] + rows[a + 5]);
        float e12z = p2z - 0.5f * (rows[a + 2] + rows[a + 6]);
        float e23x = 0.5f * (rows[b + 4] - p2x), e23y = 0.5f * (rows[b + 5] - p2y), e23z = 0.5f * (rows[b + 6] - p2z);
        // f(x) = p2 - D12 (1 - b1) + D23 b2, written from p2 so that p1 need not be kept.
        float fx = p2x - e12x * (1f - b1) + e23x * b2;
        float fy = p2y - e12y * (1f - b1) + e23y * b2;
        float fz = p2z - e12z * (1f - b1) + e23z * b2;
        float tx = e12x * d1 + e23x * d2, ty = e12y * d1 + e23y * d2, tz = e12z * d1 + e23z * d2;
        // Rest curve, from the rest segments.
        float r2x = rows[b + 16], r2y = rows[b + 17], r2z = rows[b + 18];
        float g12x = r2x - 0.5f * (rows[a + 16] + rows[a + 20]);
        float g12y = r2y - 0.5f * (rows[a + 17] + rows[a + 21]);
        float g12z = r2z - 0.5f * (rows[a + 18] + rows[a + 22]);
        float g23x = 0.5f * (rows[b + 20] - r2x), g23y = 0.5f * (rows[b + 21] - r2y), g23z = 0.5f * (rows[b + 22] - r2z);
        float lx = px - (r2x - g12x * (1f - b1) + g23x * b2);
        float ly = py - (r2y - g12y * (1f - b1) + g23y * b2);
        float lz = pz - (r2z - g12z * (1f - b1) + g23z * b2);
        float ux = g12x * d1 + g23x * d2, uy = g12y * d1 + g23y * d2, uz = g12z * d1 + g23z * d2;
        float[] f = out;
        frame(dq, 8 * parent, 8 * c, x, ux, uy, uz, tx, ty, tz, f);
        if (palette.hasScale()) {
            addScaledCurve(palette.scales(), 12 * parent, 12 * c, x, w, fx, fy, fz, lx, ly, lz, exactNormals, out);
            return;
        }
        out[0] += w * (fx + f[12] * lx + f[13] * ly + f[14] * lz);
        out[1] += w * (fy + f[15] * lx + f[16] * ly + f[17] * lz);
        out[2] += w * (fz + f[18] * lx + f[19] * ly + f[20] * lz);
        addScaled(out, w, f[12], f[13], f[14], f[15], f[16], f[17], f[18], f[19], f[20]);
    }

    /**
     * With joint scale: the offset goes through {@code S(x) = (1 - x) S_p + x S_c} (the linear
     * parts of the joints' scale parts, {@link JointPalette}) before F, so the cross-section
     * squashes and stretches with the bones and a curve's end moves exactly as its bone's matrix
     * (M = D S); the normal matrix is F times S(x)'s cofactor (times the sign of its determinant)
     * or S(x) itself.
     */
    private static void addScaledCurve(float[] sc, int p, int c, float x, float w, float fx, float fy, float fz,
            float lx, float ly, float lz, boolean exactNormals, float[] out) {
        float y = 1f - x;
        for (int r = 0; r < 3; r++) {
            for (int col = 0; col < 3; col++) {
                out[SCALE + 4 * r + col] = y * sc[p + 4 * r + col] + x * sc[c + 4 * r + col];
            }
        }
        int s = SCALE;
        float mx = out[s] * lx + out[s + 1] * ly + out[s + 2] * lz;
        float my = out[s + 4] * lx + out[s + 5] * ly + out[s + 6] * lz;
        float mz = out[s + 8] * lx + out[s + 9] * ly + out[s + 10] * lz;
        out[0] += w * (fx + out[12] * mx + out[13] * my + out[14] * mz);
        out[1] += w * (fy + out[15] * mx + out[16] * my + out[17] * mz);
        out[2] += w * (fz + out[18] * mx + out[19] * my + out[20] * mz);
        int k = NORMAL_MATRIX;
        if (exactNormals) {
            SkinningSteps.signedCofactor(out, s, true, out, k);
        } else {
            SkinningSteps.linearPart(out, s, out, k);
        }
        // N = F K, row by row.
        for (int r = 0; r < 3; r++) {
            float a0 = out[12 + 3 * r], a1 = out[13 + 3 * r], a2 = out[14 + 3 * r];
            out[3 + 3 * r] += w * (a0 * out[k] + a1 * out[k + 3] + a2 * out[k + 6]);
            out[4 + 3 * r] += w * (a0 * out[k + 1] + a1 * out[k + 4] + a2 * out[k + 7]);
            out[5 + 3 * r] += w * (a0 * out[k + 2] + a1 * out[k + 5] + a2 * out[k + 8]);
        }
    }

    /**
     * The frame F = T Q at x as a row-major 3x3 into {@code dest[12..21)}: Q the slerp of the
     * rotations at {@code p} and {@code c} (signs aligned), T the minimal rotation from Q u to t
     * (u, t the rest and posed tangents, any length). T is the identity where t vanishes or points
     * opposite Q u (no unique minimal rotation).
     */
    private static void frame(float[] dq, int p, int c, float x, float ux, float uy, float uz, float tx, float ty,
            float tz, float[] dest) {
        float ax = dq[p], ay = dq[p + 1], az = dq[p + 2], aw = dq[p + 3];
        float bx = dq[c], by = dq[c + 1], bz = dq[c + 2], bw = dq[c + 3];
        float cos = ax * bx + ay * by + az * bz + aw * bw;
        if (cos < 0f) {
            bx = -bx;
            by = -by;
            bz = -bz;
            bw = -bw;
            cos = -cos;
        }
        float s0;
        float s1;
        if (cos > 0.9999f) {
            s0 = 1f - x;
            s1 = x;
        } else {
            float angle = acos(cos);
            float sin = (float) Math.sqrt(1f - cos * cos);
            s0 = (float) Math.sin((1f - x) * angle) / sin;
            s1 = (float) Math.sin(x * angle) / sin;
        }
        float qx = s0 * ax + s1 * bx, qy = s0 * ay + s1 * by, qz = s0 * az + s1 * bz, qw = s0 * aw + s1 * bw;
        float inv = 1f / (float) Math.sqrt(qx * qx + qy * qy + qz * qz + qw * qw);
        qx *= inv;
        qy *= inv;
        qz *= inv;
        qw *= inv;
        // v = Q u (u need not be unit: only directions matter below).
        float cx = qy * uz - qz * uy + qw * ux, cy = qz * ux - qx * uz + qw * uy, cz = qx * uy - qy * ux + qw * uz;
        float vx = ux + 2 * (qy * cz - qz * cy), vy = uy + 2 * (qz * cx - qx * cz), vz = uz + 2 * (qx * cy - qy * cx);
        // Minimal rotation from v to t: the quaternion (|v||t| + v.t, v x t), normalised.
        float vl = (float) Math.sqrt((vx * vx + vy * vy + vz * vz) * (tx * tx + ty * ty + tz * tz));
        float mw = vl + vx * tx + vy * ty + vz * tz;
        float mx = vy * tz - vz * ty, my = vz * tx - vx * tz, mz = vx * ty - vy * tx;
        float ml2 = mw * mw + mx * mx + my * my + mz * mz;
        if (mw > 1e-6f * vl && ml2 > 0f) {
            float ml = 1f / (float) Math.sqrt(ml2);
            mw *= ml;
            mx *= ml;
            my *= ml;
            mz *= ml;
            // F = T Q
            float fx = mw * qx + mx * qw + my * qz - mz * qy;
            float fy = mw * qy + my * qw + mz * qx - mx * qz;
            float fz = mw * qz + mz * qw + mx * qy - my * qx;
            float fw = mw * qw - mx * qx - my * qy - mz * qz;
            qx = fx;
            qy = fy;
            qz = fz;
            qw = fw;
        }
        SkinningSteps.rotationMatrix(qx, qy, qz, qw, dest, 12);
    }

    /**
     * arccos of c in [0, 1], Abramowitz and Stegun 4.4.46: {@code sqrt(1 - c)} times a polynomial of
     * degree 7, absolute error at most 2e-8 (below float precision). Math.acos is no intrinsic: a
     * call to it costs more than the rest of a curve's evaluation.
     */
    private static float acos(float c) {
        float poly = -0.0012624911f;
        poly = poly * c + 0.0066700901f;
        poly = poly * c - 0.0170881256f;
        poly = poly * c + 0.0308918810f;
        poly = poly * c - 0.0501743046f;
        poly = poly * c + 0.0889789874f;
        poly = poly * c - 0.2145988016f;
        poly = poly * c + 1.5707963050f;
        return (float) Math.sqrt(1f - c) * poly;
    }

    @Override
    public void skin(JointPalette palette, float[] outPositions, float[] outNormals, int from, int to) {
        final boolean exactNormals = normals == NormalTransform.INVERSE_TRANSPOSE;
        final boolean mirrors = exactNormals && palette.mirrorsMatrices();
        final float[] d = scratch.get();
        for (int i = from; i < to; i++) {
            deform(palette, i, exactNormals, mirrors, d);
            Deformations.putPoint(d, restNormals, i, exactNormals, outPositions, outNormals);
        }
    }

    @Override
    public void skinDeformations(JointPalette palette, float[] outDeformations, int from, int to) {
        final boolean exactNormals = normals == NormalTransform.INVERSE_TRANSPOSE;
        final boolean mirrors = exactNormals && palette.mirrorsMatrices();
        final float[] d = scratch.get();
        for (int i = from; i < to; i++) {
            deform(palette, i, exactNormals, mirrors, d);
            Deformations.put(outDeformations, DEFORMATION_FLOATS * i, d, 0);
        }
    }
}
