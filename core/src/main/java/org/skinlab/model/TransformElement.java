package org.skinlab.model;

import org.joml.Matrix4f;

/**
 * One entry of a node's ordered transform stack: {@code <matrix>}, {@code <translate>},
 * {@code <rotate>}, {@code <scale>}, {@code <lookat>} or {@code <skew>} from COLLADA, or glTF's
 * rotation quaternion, with its values exactly as written in the file. A node's local matrix is the product of its stack in document order
 * (COLLADA 1.4.1, "Transformation elements": each element post-multiplies the previous ones).
 *
 * <p>Value layouts (the same layout animation channels address, see
 * {@link AnimationChannel#valueOffset()}):
 * <ul>
 * <li>MATRIX: 16 values, row-major as in the file (translation in values 3, 7, 11). The bottom row
 *     is treated as (0 0 0 1) whatever it holds; the importer warns when it is not.</li>
 * <li>TRANSLATE, SCALE: x y z.</li>
 * <li>ROTATE: axis x y z, then the angle in degrees.</li>
 * <li>QUATERNION: x y z w (glTF's {@code rotation}), in homogeneous form: a quaternion of length
 *     l rotates and scales by l^2, so the shrinking of a linearly blended quaternion stays
 *     visible (see {@code RotationInterpolation.LERP}); a unit quaternion is a pure rotation.</li>
 * <li>LOOKAT: eye, interest point, up vector (9 values); it places the node at the eye looking
 *     at the interest point, i.e. the inverse of a view matrix. Without a view direction (the eye
 *     on the interest point, or the up vector along the view) it places the node at the eye
 *     without rotation.</li>
 * <li>SKEW: angle in degrees, rotation axis, translation axis (7 values); points move along the
 *     translation axis by tan(angle) times their component along the rotation axis
 *     (RenderMan's skew, exact when the two axes are perpendicular).</li>
 * </ul>
 */
public final class TransformElement {
    /** The kinds of transform element and how many values each holds. */
    public enum Kind {
        /** COLLADA {@code <matrix>} (glTF {@code matrix}, transposed): 16 values, row-major. */
        MATRIX(16),
        /** COLLADA {@code <translate>} (glTF {@code translation}): x y z. */
        TRANSLATE(3),
        /** COLLADA {@code <rotate>}: axis x y z, then the angle in degrees. */
        ROTATE(4),
        /** COLLADA {@code <scale>} (glTF {@code scale}): x y z. */
        SCALE(3),
        /** COLLADA {@code <lookat>}: eye, interest point, up vector (9 values). */
        LOOKAT(9),
        /** COLLADA {@code <skew>}: angle in degrees, rotation axis, translation axis (7 values). */
        SKEW(7),
        /** glTF {@code rotation}: quaternion x y z w, in homogeneous form (see the class comment). */
        QUATERNION(4);

        private final int size;

        Kind(int size) {
            this.size = size;
        }

        /**
         * Number of values an element of this kind holds.
         *
         * @return the value count, 3 to 16
         */
        public int size() {
            return size;
        }

        /**
         * The COLLADA element name, e.g. "translate".
         *
         * @return the constant's name in lower case ("quaternion" for {@link #QUATERNION}, which COLLADA lacks)
         */
        public String elementName() {
            return name().toLowerCase(java.util.Locale.ROOT);
        }
    }

    private final Kind kind;
    private final String sid;
    private final float[] values;

    /**
     * An element with the given values.
     *
     * @param kind   what kind of transform it is
     * @param sid    the element's sid, or null
     * @param values {@code kind.size()} values in the layout described in the class comment; copied
     * @throws IllegalArgumentException when {@code values} does not hold exactly {@code kind.size()} values
     */
    public TransformElement(Kind kind, String sid, float[] values) {
        if (values.length != kind.size) {
            throw new IllegalArgumentException(kind + " needs " + kind.size + " values, got " + values.length);
        }
        this.kind = kind;
        this.sid = sid;
        this.values = values.clone();
    }

    /**
     * What kind of transform the element is.
     *
     * @return the kind, which fixes the number and layout of the values
     */
    public Kind kind() {
        return kind;
    }

    /**
     * The element's sid (what animation channels target), or null.
     *
     * @return the sid, or null when the element has none
     */
    public String sid() {
        return sid;
    }

    /**
     * A copy of the values, in the layout described in the class comment.
     *
     * @return a new array of {@code kind().size()} floats the caller may change
     */
    public float[] values() {
        return values.clone();
    }

    /**
     * One value, without copying the array.
     *
     * @param i the value's index, 0 to {@code kind().size() - 1}, in the layout described in the class comment
     * @return the value as written in the file
     * @throws ArrayIndexOutOfBoundsException when {@code i} is out of that range
     */
    public float value(int i) {
        return values[i];
    }

    /**
     * Copies the values into {@code dest} at {@code offset}.
     *
     * @param dest   the array written: {@code kind().size()} values from {@code offset} on
     * @param offset index in {@code dest} of the first value written
     * @throws IndexOutOfBoundsException when {@code dest} is too short
     */
    public void copyValues(float[] dest, int offset) {
        System.arraycopy(values, 0, dest, offset, values.length);
    }

    /**
     * Post-multiplies {@code dest} by this element: {@code dest = dest * T}.
     *
     * @param dest    the matrix multiplied in place
     * @param scratch a matrix to work in, overwritten; not {@code dest}
     * @return {@code dest}
     */
    public Matrix4f multiply(Matrix4f dest, Matrix4f scratch) {
        return multiply(kind, values, 0, dest, scratch);
    }

    /**
     * Post-multiplies {@code dest} by the transform of the given kind whose values start at
     * {@code v[offset]}: {@code dest = dest * T}. Allocation-free; {@code scratch} is overwritten.
     * The one place where transform elements become matrices.
     *
     * @param kind    the kind of transform, which fixes how many values are read
     * @param v       the values, in the layout described in the class comment
     * @param o       index in {@code v} of the first value (the {@code offset} above)
     * @param dest    the matrix multiplied in place
     * @param scratch a matrix to work in, overwritten; not {@code dest}
     * @return {@code dest}
     */
    public static Matrix4f multiply(Kind kind, float[] v, int o, Matrix4f dest, Matrix4f scratch) {
        switch (kind) {
            case MATRIX:
                // Row-major in the file; JOML's set() takes columns. Bottom row forced to 0 0 0 1.
                scratch.set(v[o], v[o + 4], v[o + 8], 0f,
                        v[o + 1], v[o + 5], v[o + 9], 0f,
                        v[o + 2], v[o + 6], v[o + 10], 0f,
                        v[o + 3], v[o + 7], v[o + 11], 1f);
                return dest.mul(scratch);
            case TRANSLATE:
                return dest.translate(v[o], v[o + 1], v[o + 2]);
            case ROTATE: {
                float x = v[o];
                float y = v[o + 1];
                float z = v[o + 2];
                float len = (float) Math.sqrt(x * x + y * y + z * z);
                if (len == 0f) {
                    return dest; // a zero axis rotates nothing; the importer warned
                }
                return dest.rotate((float) Math.toRadians(v[o + 3]), x / len, y / len, z / len);
            }
            case SCALE:
                return dest.scale(v[o], v[o + 1], v[o + 2]);
            case QUATERNION:
                return dest.mul(quaternionMatrix(v[o], v[o + 1], v[o + 2], v[o + 3], scratch));
            case LOOKAT:
                scratch.setLookAt(v[o], v[o + 1], v[o + 2], v[o + 3], v[o + 4], v[o + 5],
                        v[o + 6], v[o + 7], v[o + 8]).invertAffine();
                if (!scratch.isFinite()) {
                    // No view direction: normalising a zero vector made NaNs that would spread
                    // through the whole skeleton. Keep the eye, skip the rotation; the importer warned.
                    scratch.translation(v[o], v[o + 1], v[o + 2]);
                }
                return dest.mul(scratch);
            case SKEW: {
                float t = (float) Math.tan(Math.toRadians(v[o]));
                float rx = v[o + 1];
                float ry = v[o + 2];
                float rz = v[o + 3];
                float tx = v[o + 4];
                float ty = v[o + 5];
                float tz = v[o + 6];
                float rl = (float) Math.sqrt(rx * rx + ry * ry + rz * rz);
                float tl = (float) Math.sqrt(tx * tx + ty * ty + tz * tz);
                if (rl == 0f || tl == 0f) {
                    return dest;
                }
                float k = t / (rl * tl);
                // M = I + k * tAxis * rAxis^T, written column by column.
                scratch.set(1f + k * tx * rx, k * ty * rx, k * tz * rx, 0f,
                        k * tx * ry, 1f + k * ty * ry, k * tz * ry, 0f,
                        k * tx * rz, k * ty * rz, 1f + k * tz * rz, 0f,
                        0f, 0f, 0f, 1f);
                return dest.mul(scratch);
            }
            default:
                throw new IllegalStateException(kind.toString());
        }
    }

    /**
     * The rotation matrix of the quaternion (x, y, z, w) in homogeneous form: {@code |q|^2} times
     * that of q/|q|, so no division and no special case for a zero quaternion (which gives the
     * zero matrix, as the blend of two opposite keys would).
     *
     * @param x    the quaternion's x (vector part)
     * @param y    the quaternion's y (vector part)
     * @param z    the quaternion's z (vector part)
     * @param w    the quaternion's w (scalar part)
     * @param dest the matrix to write; all of it is overwritten (no translation, bottom row 0 0 0 1)
     * @return {@code dest}
     */
    public static Matrix4f quaternionMatrix(float x, float y, float z, float w, Matrix4f dest) {
        float ww = w * w;
        float xx = x * x;
        float yy = y * y;
        float zz = z * z;
        return dest.set(ww + xx - yy - zz, 2 * (x * y + w * z), 2 * (x * z - w * y), 0f,
                2 * (x * y - w * z), ww - xx + yy - zz, 2 * (y * z + w * x), 0f,
                2 * (x * z + w * y), 2 * (y * z - w * x), ww - xx - yy + zz, 0f,
                0f, 0f, 0f, 1f);
    }

    @Override
    public String toString() {
        if (kind == Kind.QUATERNION) {
            return "rotation" + (sid == null ? "" : " " + sid);
        }
        return "<" + kind.elementName() + (sid == null ? "" : " sid=\"" + sid + "\"") + ">";
    }
}
