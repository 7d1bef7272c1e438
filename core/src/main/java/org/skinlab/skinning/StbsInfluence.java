package org.skinlab.skinning;

/**
 * The per-influence step of stretchable and twistable bones (Jacobson and Sorkine 2011), shared
 * by both blends of {@link ScalarStbsSkinner}: joint j's rigid transformation for one point p,
 * from this frame's {@link JointPalette#boneRows()} (named by their rows below) and the joint's
 * dual quaternion (its rigid part D).
 * <ol>
 * <li>The endpoint weight {@code e = clamp(((p - h) . (t - h)) / L^2, 0, 1)} (rows 4, 5): 0 at and
 *     before the head, 1 at and beyond the tail, linear between; {@code e = 1} for a point-like
 *     bone (L = 0), which then moves with its joint unchanged.</li>
 * <li>The twist still missing at e: a turn by {@code -(1 - e) theta} (row 0's w) about the posed
 *     bone axis a (row 3) through the posed head H (row 0), so the head follows the parent's twist
 *     and the tail the bone's own; as a quaternion {@code u = (a sin(phi/2), cos(phi/2))},
 *     {@code phi = -(1 - e) theta}, and the influence's rotation {@code r = u q_D}.</li>
 * <li>The stretch: e times the tail's stretch offset s (row 2), so points beyond the tail move
 *     rigidly with it and the bone in between stretches evenly.</li>
 * </ol>
 * Together {@code T(p) = H + R(r) (p - h) + e s}, since D maps the rest head h to H and the twist
 * leaves H in place: a rotation r and a translation {@code x = H + e s - R(r) h}.
 */
final class StbsInfluence {
    /** Floats written by {@link #transform}: r (x y z w), then x. */
    static final int FLOATS = 7;

    private StbsInfluence() {
    }

    /**
     * sin(a) for |a| <= pi/2 by its Taylor series to a^11 (the first term left out is below 6e-8
     * there; |a| <= pi/2 since the angle is -(1 - e) theta / 2 with |theta| <= pi). The SIMD
     * kernel's polynomial, so both paths round alike; on the humanoid the scalar kernel runs about
     * a fifth faster with it than with Math.sin and Math.cos.
     */
    static float sin(float a) {
        float a2 = a * a;
        return a * (1f + a2 * (-1f / 6 + a2 * (1f / 120 + a2 * (-1f / 5040 + a2 * (1f / 362880 + a2 * (-1f / 39916800))))));
    }

    /** cos(a) for |a| <= pi/2 by its Taylor series to a^12 (the first term left out is below 7e-9 there). */
    static float cos(float a) {
        float a2 = a * a;
        return 1f + a2 * (-0.5f + a2 * (1f / 24 + a2 * (-1f / 720 + a2 * (1f / 40320 + a2 * (-1f / 3628800
                + a2 * (1f / 479001600))))));
    }

    /** The endpoint weight of point p on joint j's bone (see the class comment). */
    static float endpointWeight(float[] rows, int j, float px, float py, float pz) {
        int b = JointPalette.BONE_FLOATS * j;
        float length = rows[b + 19];
        if (!(length > 0f)) {
            return 1f;
        }
        float hx = rows[b + 16], hy = rows[b + 17], hz = rows[b + 18];
        float along = (px - hx) * (rows[b + 20] - hx) + (py - hy) * (rows[b + 21] - hy) + (pz - hz) * (rows[b + 22] - hz);
        return Math.min(1f, Math.max(0f, along / (length * length)));
    }

    /** Joint j's transformation of point p: r into {@code out[o..o+4)}, x into {@code out[o+4..o+7)}. */
    static void transform(float[] rows, float[] dq, int j, float px, float py, float pz, float[] out, int o) {
        int b = JointPalette.BONE_FLOATS * j;
        float e = endpointWeight(rows, j, px, py, pz);
        float half = (e - 1f) * rows[b + 3] * 0.5f;
        float sin = sin(half);
        float uw = cos(half);
        float ux = rows[b + 12] * sin, uy = rows[b + 13] * sin, uz = rows[b + 14] * sin;
        int q = 8 * j;
        float qx = dq[q], qy = dq[q + 1], qz = dq[q + 2], qw = dq[q + 3];
        float rx = uw * qx + ux * qw + (uy * qz - uz * qy);
        float ry = uw * qy + uy * qw + (uz * qx - ux * qz);
        float rz = uw * qz + uz * qw + (ux * qy - uy * qx);
        float rw = uw * qw - (ux * qx + uy * qy + uz * qz);
        float hx = rows[b + 16], hy = rows[b + 17], hz = rows[b + 18];
        // R(r) h = h + 2 r.xyz x (r.xyz x h + rw h)
        float cx = ry * hz - rz * hy + rw * hx;
        float cy = rz * hx - rx * hz + rw * hy;
        float cz = rx * hy - ry * hx + rw * hz;
        out[o] = rx;
        out[o + 1] = ry;
        out[o + 2] = rz;
        out[o + 3] = rw;
        out[o + 4] = rows[b] + e * rows[b + 8] - (hx + 2 * (ry * cz - rz * cy));
        out[o + 5] = rows[b + 1] + e * rows[b + 9] - (hy + 2 * (rz * cx - rx * cz));
        out[o + 6] = rows[b + 2] + e * rows[b + 10] - (hz + 2 * (rx * cy - ry * cx));
    }
}
