package org.skinlab.animation;

import org.joml.Quaternionfc;
import org.joml.Vector3f;
import org.joml.Vector3fc;

/**
 * A dual quaternion {@code q = r + e d} (e^2 = 0) with real part r and dual part d, in the JOML
 * style: public fields, mutating methods that return {@code this}, an explicit {@code dest} where
 * a result goes elsewhere, no allocation.
 *
 * <p>A unit dual quaternion is a rigid transform: rotation r (|r| = 1) followed by translation t,
 * with {@code d = t r / 2} (t read as the pure quaternion (t, 0)); Kavan et al. 2008, "Geometric
 * skinning with approximate dual quaternion blending", section 3.
 */
public final class DualQuaternion {
    /** The x component of the real part r (the rotation quaternion). */
    public float rx;
    /** The y component of the real part r (the rotation quaternion). */
    public float ry;
    /** The z component of the real part r (the rotation quaternion). */
    public float rz;
    /** The w (scalar) component of the real part r (the rotation quaternion); 1 for the identity. */
    public float rw = 1f;
    /** The x component of the dual part d, which encodes the translation ({@code d = t r / 2}). */
    public float dx;
    /** The y component of the dual part d, which encodes the translation ({@code d = t r / 2}). */
    public float dy;
    /** The z component of the dual part d, which encodes the translation ({@code d = t r / 2}). */
    public float dz;
    /** The w (scalar) component of the dual part d, which encodes the translation ({@code d = t r / 2}). */
    public float dw;

    /** The identity transform. */
    public DualQuaternion() {
    }

    /**
     * A copy of {@code other}.
     *
     * @param other the dual quaternion whose eight components are copied
     */
    public DualQuaternion(DualQuaternion other) {
        set(other);
    }

    /**
     * Sets this to the identity transform: r = (0, 0, 0, 1), d = 0.
     *
     * @return this
     */
    public DualQuaternion identity() {
        rx = ry = rz = 0f;
        rw = 1f;
        dx = dy = dz = dw = 0f;
        return this;
    }

    /**
     * Copies the eight components of {@code o} into this.
     *
     * @param o the dual quaternion to copy
     * @return this
     */
    public DualQuaternion set(DualQuaternion o) {
        rx = o.rx;
        ry = o.ry;
        rz = o.rz;
        rw = o.rw;
        dx = o.dx;
        dy = o.dy;
        dz = o.dz;
        dw = o.dw;
        return this;
    }

    /**
     * Rotation {@code rotation} (unit) followed by translation {@code translation}.
     *
     * @param rotation the rotation, a unit quaternion; it becomes the real part
     * @param translation the translation, applied after the rotation
     * @return this
     */
    public DualQuaternion set(Quaternionfc rotation, Vector3fc translation) {
        return set(rotation.x(), rotation.y(), rotation.z(), rotation.w(), translation.x(), translation.y(),
                translation.z());
    }

    /**
     * Rotation (x, y, z, w), unit, followed by translation (tx, ty, tz): d = (t, 0) r / 2.
     *
     * @param x the x of the unit rotation quaternion
     * @param y the y of the unit rotation quaternion
     * @param z the z of the unit rotation quaternion
     * @param w the w (scalar) of the unit rotation quaternion
     * @param tx the x of the translation, applied after the rotation
     * @param ty the y of the translation, applied after the rotation
     * @param tz the z of the translation, applied after the rotation
     * @return this
     */
    public DualQuaternion set(float x, float y, float z, float w, float tx, float ty, float tz) {
        rx = x;
        ry = y;
        rz = z;
        rw = w;
        dx = 0.5f * (tx * w + ty * z - tz * y);
        dy = 0.5f * (-tx * z + ty * w + tz * x);
        dz = 0.5f * (tx * y - ty * x + tz * w);
        dw = -0.5f * (tx * x + ty * y + tz * z);
        return this;
    }

    /**
     * The 8 components r.x, r.y, r.z, r.w, d.x, d.y, d.z, d.w from {@code src} at {@code offset}.
     *
     * @param src holds the components at {@code src[offset .. offset + 7]}
     * @param offset the index in {@code src} of r.x
     * @return this
     */
    public DualQuaternion set(float[] src, int offset) {
        rx = src[offset];
        ry = src[offset + 1];
        rz = src[offset + 2];
        rw = src[offset + 3];
        dx = src[offset + 4];
        dy = src[offset + 5];
        dz = src[offset + 6];
        dw = src[offset + 7];
        return this;
    }

    /**
     * Writes the 8 components in the order of {@link #set(float[], int)}.
     *
     * @param dest receives the components at {@code dest[offset .. offset + 7]}
     * @param offset the index in {@code dest} for r.x
     * @return {@code dest}
     */
    public float[] get(float[] dest, int offset) {
        dest[offset] = rx;
        dest[offset + 1] = ry;
        dest[offset + 2] = rz;
        dest[offset + 3] = rw;
        dest[offset + 4] = dx;
        dest[offset + 5] = dy;
        dest[offset + 6] = dz;
        dest[offset + 7] = dw;
        return dest;
    }

    /**
     * Dot product of the real parts: negative when the rotations lie in opposite hemispheres.
     *
     * @param o the other dual quaternion
     * @return the 4D dot product of this real part and {@code o}'s
     */
    public float realDot(DualQuaternion o) {
        return rx * o.rx + ry * o.ry + rz * o.rz + rw * o.rw;
    }

    /**
     * {@code this += weight * o}, the blending step of DLB (Kavan et al. 2008, eq. 6).
     *
     * @param weight the factor for {@code o}, typically a skinning weight, negated by the caller for an
     *     opposite-hemisphere rotation
     * @param o the dual quaternion to add; not modified
     * @return this, not normalised
     */
    public DualQuaternion addScaled(float weight, DualQuaternion o) {
        rx += weight * o.rx;
        ry += weight * o.ry;
        rz += weight * o.rz;
        rw += weight * o.rw;
        dx += weight * o.dx;
        dy += weight * o.dy;
        dz += weight * o.dz;
        dw += weight * o.dw;
        return this;
    }

    /**
     * Multiplies all eight components by {@code s}.
     *
     * @param s the factor
     * @return this
     */
    public DualQuaternion scale(float s) {
        rx *= s;
        ry *= s;
        rz *= s;
        rw *= s;
        dx *= s;
        dy *= s;
        dz *= s;
        dw *= s;
        return this;
    }

    /**
     * Makes this a unit dual quaternion: divides both parts by |r| and removes the part of d
     * along r, so that {@code r . d = 0} holds exactly (Kavan et al. 2008, section 3.1). The
     * zero dual quaternion (blend weights cancelling out) becomes the identity.
     *
     * @return this
     */
    public DualQuaternion normalize() {
        float len = (float) Math.sqrt(rx * rx + ry * ry + rz * rz + rw * rw);
        if (!(len > 0f)) {
            return identity();
        }
        float inv = 1f / len;
        rx *= inv;
        ry *= inv;
        rz *= inv;
        rw *= inv;
        dx *= inv;
        dy *= inv;
        dz *= inv;
        dw *= inv;
        float along = rx * dx + ry * dy + rz * dz + rw * dw;
        dx -= along * rx;
        dy -= along * ry;
        dz -= along * rz;
        dw -= along * rw;
        return this;
    }

    /**
     * {@code dest = this * o}: apply o first, then this.
     *
     * @param o the right-hand factor, the transform applied first
     * @param dest receives the product; may be this or {@code o}
     * @return {@code dest}
     */
    public DualQuaternion mul(DualQuaternion o, DualQuaternion dest) {
        float nrx = rw * o.rx + rx * o.rw + ry * o.rz - rz * o.ry;
        float nry = rw * o.ry - rx * o.rz + ry * o.rw + rz * o.rx;
        float nrz = rw * o.rz + rx * o.ry - ry * o.rx + rz * o.rw;
        float nrw = rw * o.rw - rx * o.rx - ry * o.ry - rz * o.rz;
        // dual = r1 d2 + d1 r2
        float ndx = rw * o.dx + rx * o.dw + ry * o.dz - rz * o.dy + dw * o.rx + dx * o.rw + dy * o.rz - dz * o.ry;
        float ndy = rw * o.dy - rx * o.dz + ry * o.dw + rz * o.dx + dw * o.ry - dx * o.rz + dy * o.rw + dz * o.rx;
        float ndz = rw * o.dz + rx * o.dy - ry * o.dx + rz * o.dw + dw * o.rz + dx * o.ry - dy * o.rx + dz * o.rw;
        float ndw = rw * o.dw - rx * o.dx - ry * o.dy - rz * o.dz + dw * o.rw - dx * o.rx - dy * o.ry - dz * o.rz;
        dest.rx = nrx;
        dest.ry = nry;
        dest.rz = nrz;
        dest.rw = nrw;
        dest.dx = ndx;
        dest.dy = ndy;
        dest.dz = ndz;
        dest.dw = ndw;
        return dest;
    }

    /**
     * The inverse of a unit dual quaternion: its quaternion conjugate (both parts conjugated). Modifies this.
     *
     * @return this
     */
    public DualQuaternion conjugate() {
        rx = -rx;
        ry = -ry;
        rz = -rz;
        dx = -dx;
        dy = -dy;
        dz = -dz;
        return this;
    }

    /**
     * The translation of a unit dual quaternion: {@code t = 2 d r*}, written out as
     * {@code 2 (r.w d.xyz - d.w r.xyz + r.xyz x d.xyz)}.
     *
     * @param dest receives the translation
     * @return {@code dest}
     */
    public Vector3f getTranslation(Vector3f dest) {
        return dest.set(2 * (rw * dx - dw * rx + (ry * dz - rz * dy)),
                2 * (rw * dy - dw * ry + (rz * dx - rx * dz)),
                2 * (rw * dz - dw * rz + (rx * dy - ry * dx)));
    }

    /**
     * Transforms a point of a unit dual quaternion: rotate by r, then translate.
     *
     * @param v the point, transformed in place
     * @return {@code v}
     */
    public Vector3f transformPosition(Vector3f v) {
        float tx = 2 * (rw * dx - dw * rx + (ry * dz - rz * dy));
        float ty = 2 * (rw * dy - dw * ry + (rz * dx - rx * dz));
        float tz = 2 * (rw * dz - dw * rz + (rx * dy - ry * dx));
        transformDirection(v);
        return v.add(tx, ty, tz);
    }

    /**
     * Rotates a direction by the real part (unit): {@code v + 2 r x (r x v + w v)}. The translation is ignored.
     *
     * @param v the direction, rotated in place
     * @return {@code v}
     */
    public Vector3f transformDirection(Vector3f v) {
        float cx = ry * v.z - rz * v.y + rw * v.x;
        float cy = rz * v.x - rx * v.z + rw * v.y;
        float cz = rx * v.y - ry * v.x + rw * v.z;
        return v.set(v.x + 2 * (ry * cz - rz * cy), v.y + 2 * (rz * cx - rx * cz), v.z + 2 * (rx * cy - ry * cx));
    }

    /**
     * Dual quaternion linear blending between this (t = 0) and {@code o} (t = 1) along the
     * shortest arc, normalised: DLB of two transforms (Kavan et al. 2008, eq. 6).
     *
     * @param o the transform at t = 1
     * @param t the blend parameter, normally in [0, 1]
     * @param dest receives the normalised blend; may be this or {@code o}
     * @return {@code dest}
     */
    public DualQuaternion blend(DualQuaternion o, float t, DualQuaternion dest) {
        float wo = Math.copySign(t, realDot(o));
        float wt = 1 - t;
        dest.rx = wt * rx + wo * o.rx;
        dest.ry = wt * ry + wo * o.ry;
        dest.rz = wt * rz + wo * o.rz;
        dest.rw = wt * rw + wo * o.rw;
        dest.dx = wt * dx + wo * o.dx;
        dest.dy = wt * dy + wo * o.dy;
        dest.dz = wt * dz + wo * o.dz;
        dest.dw = wt * dw + wo * o.dw;
        return dest.normalize();
    }

    @Override
    public String toString() {
        return "DualQuaternion[r=(" + rx + ", " + ry + ", " + rz + ", " + rw + "), d=(" + dx + ", " + dy + ", " + dz
                + ", " + dw + ")]";
    }
}
