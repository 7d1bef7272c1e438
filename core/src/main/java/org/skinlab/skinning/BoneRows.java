package org.skinlab.skinning;

/**
 * A palette's bone rows ({@link JointPalette#boneRows()}, whose Javadoc has their layout): this
 * frame's posed segments, twists and stretches, derived once per frame from the skinning
 * matrices, their rigid parts and rotations, and the bones' rest segments. Owned by one palette;
 * allocation-free per frame.
 */
final class BoneRows {
    private final Bones bones;
    private final float[] rows;

    BoneRows(Bones bones) {
        this.bones = bones;
        this.rows = new float[JointPalette.BONE_FLOATS * bones.jointCount()];
    }

    float[] rows() {
        return rows;
    }

    /**
     * Fills the rows.
     *
     * @param m      per joint the skinning matrix M, row-major 3x4
     * @param d      per joint its rigid part D, row-major 3x4
     * @param q      per joint D's dual quaternion (8 floats, the rotation first)
     * @param pivots per joint the rigid part of its bind frame, row-major 3x4 (for the axis of a
     *               point-like bone: the bind frame's Y axis)
     */
    void fill(float[] m, float[] d, float[] q, float[] pivots) {
        int joints = bones.jointCount();
        float[] rows = this.rows;
        for (int j = 0; j < joints; j++) {
            int o = 12 * j;
            int b = JointPalette.BONE_FLOATS * j;
            float hx = bones.head(j, 0), hy = bones.head(j, 1), hz = bones.head(j, 2);
            float tx = bones.tail(j, 0), ty = bones.tail(j, 1), tz = bones.tail(j, 2);
            float ax = tx - hx, ay = ty - hy, az = tz - hz;
            float length = (float) Math.sqrt(ax * ax + ay * ay + az * az);
            if (length > 0f) {
                ax /= length;
                ay /= length;
                az /= length;
            } else {
                ax = pivots[o + 1];
                ay = pivots[o + 5];
                az = pivots[o + 9];
            }
            rows[b] = m[o] * hx + m[o + 1] * hy + m[o + 2] * hz + m[o + 3];
            rows[b + 1] = m[o + 4] * hx + m[o + 5] * hy + m[o + 6] * hz + m[o + 7];
            rows[b + 2] = m[o + 8] * hx + m[o + 9] * hy + m[o + 10] * hz + m[o + 11];
            float mtx = m[o] * tx + m[o + 1] * ty + m[o + 2] * tz + m[o + 3];
            float mty = m[o + 4] * tx + m[o + 5] * ty + m[o + 6] * tz + m[o + 7];
            float mtz = m[o + 8] * tx + m[o + 9] * ty + m[o + 10] * tz + m[o + 11];
            rows[b + 4] = mtx;
            rows[b + 5] = mty;
            rows[b + 6] = mtz;
            float sx = mtx - rows[b], sy = mty - rows[b + 1], sz = mtz - rows[b + 2];
            rows[b + 7] = length > 0f ? (float) Math.sqrt(sx * sx + sy * sy + sz * sz) / length : 1f;
            rows[b + 8] = mtx - (d[o] * tx + d[o + 1] * ty + d[o + 2] * tz + d[o + 3]);
            rows[b + 9] = mty - (d[o + 4] * tx + d[o + 5] * ty + d[o + 6] * tz + d[o + 7]);
            rows[b + 10] = mtz - (d[o + 8] * tx + d[o + 9] * ty + d[o + 10] * tz + d[o + 11]);
            rows[b + 11] = 0f;
            rows[b + 12] = d[o] * ax + d[o + 1] * ay + d[o + 2] * az;
            rows[b + 13] = d[o + 4] * ax + d[o + 5] * ay + d[o + 6] * az;
            rows[b + 14] = d[o + 8] * ax + d[o + 9] * ay + d[o + 10] * az;
            rows[b + 15] = 0f;
            rows[b + 16] = hx;
            rows[b + 17] = hy;
            rows[b + 18] = hz;
            rows[b + 19] = length;
            rows[b + 20] = tx;
            rows[b + 21] = ty;
            rows[b + 22] = tz;
            int parent = bones.parent(j);
            rows[b + 23] = parent;
            rows[b + 3] = parent < 0 ? 0f : twist(q, 8 * parent, 8 * j, ax, ay, az);
        }
    }

    /**
     * The twist about unit axis a of the rotation from the real part at {@code p} to the one at
     * {@code c}: with r = conj(q_p) q_c, {@code 2 atan2(r.xyz . a, r.w)}, in (-pi, pi].
     */
    private static float twist(float[] q, int p, int c, float ax, float ay, float az) {
        float px = -q[p], py = -q[p + 1], pz = -q[p + 2], pw = q[p + 3];
        float cx = q[c], cy = q[c + 1], cz = q[c + 2], cw = q[c + 3];
        float rx = pw * cx + px * cw + py * cz - pz * cy;
        float ry = pw * cy + py * cw + pz * cx - px * cz;
        float rz = pw * cz + pz * cw + px * cy - py * cx;
        float rw = pw * cw - px * cx - py * cy - pz * cz;
        float along = rx * ax + ry * ay + rz * az;
        if (rw < 0f) {
            along = -along;
            rw = -rw;
        }
        return 2f * (float) Math.atan2(along, rw);
    }
}
