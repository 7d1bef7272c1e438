package org.skinlab.model;

/**
 * An affine map of texture coordinates applied before sampling (glTF's
 * {@code KHR_texture_transform}), in the model's texture coordinate convention (v up, (0, 0) the
 * image's bottom left, as COLLADA's): {@code u' = m00 u + m01 v + m02},
 * {@code v' = m10 u + m11 v + m12}. {@link #IDENTITY} for textures without one.
 *
 * <p>glTF writes its transform for its own convention (v down): {@code T(offset) R(rotation)
 * S(scale)} with {@code R = [cos r, sin r; -sin r, cos r]}; {@link #fromGltf} conjugates it by the
 * flip {@code v -> 1 - v} that the importer applies to the coordinates themselves.
 */
public final class TextureTransform {
    /** The transform that leaves texture coordinates as they are: {@code u' = u, v' = v}. */
    public static final TextureTransform IDENTITY = new TextureTransform(1, 0, 0, 0, 1, 0);

    private final float m00;
    private final float m01;
    private final float m02;
    private final float m10;
    private final float m11;
    private final float m12;

    /**
     * The transform {@code u' = m00 u + m01 v + m02}, {@code v' = m10 u + m11 v + m12}, in the model's
     * convention (v up).
     *
     * @param m00 weight of u in u'
     * @param m01 weight of v in u'
     * @param m02 added to u'
     * @param m10 weight of u in v'
     * @param m11 weight of v in v'
     * @param m12 added to v'
     * @throws IllegalArgumentException when a value is infinite or NaN
     */
    public TextureTransform(float m00, float m01, float m02, float m10, float m11, float m12) {
        for (float f : new float[] {m00, m01, m02, m10, m11, m12}) {
            if (!Float.isFinite(f)) {
                throw new IllegalArgumentException("texture transform values must be finite");
            }
        }
        this.m00 = m00;
        this.m01 = m01;
        this.m02 = m02;
        this.m10 = m10;
        this.m11 = m11;
        this.m12 = m12;
    }

    /**
     * KHR_texture_transform's offset, rotation (radians) and scale, in the model's convention.
     *
     * @param offsetU  {@code offset[0]} as glTF writes it (default 0)
     * @param offsetV  {@code offset[1]} as glTF writes it, in glTF's v-down convention (default 0)
     * @param rotation {@code rotation} in radians as glTF writes it (default 0)
     * @param scaleU   {@code scale[0]} as glTF writes it (default 1)
     * @param scaleV   {@code scale[1]} as glTF writes it (default 1)
     * @return the same map of texture coordinates, for the model's v-up coordinates
     * @throws IllegalArgumentException when a resulting value is infinite or NaN
     */
    public static TextureTransform fromGltf(float offsetU, float offsetV, float rotation, float scaleU, float scaleV) {
        float c = (float) Math.cos(rotation);
        float s = (float) Math.sin(rotation);
        // glTF: M = T R S = [c sx, s sy, ou; -s sx, c sy, ov]. With F(u, v) = (u, 1 - v):
        // F M F (u, v) = (a u - b v + b + ou, -d u + e v + (1 - e - ov)) for M = [a b ou; d e ov].
        float a = c * scaleU;
        float b = s * scaleV;
        float d = -s * scaleU;
        float e = c * scaleV;
        return new TextureTransform(a, -b, b + offsetU, -d, e, 1f - e - offsetV);
    }

    /**
     * Whether the transform leaves coordinates as they are, so a renderer can skip it.
     *
     * @return true when the six values are exactly those of {@link #IDENTITY}
     */
    public boolean isIdentity() {
        return m00 == 1f && m01 == 0f && m02 == 0f && m10 == 0f && m11 == 1f && m12 == 0f;
    }

    /**
     * Writes the transformed (u, v) into {@code dest[0..1]}.
     *
     * @param u    the texture coordinate u (model convention)
     * @param v    the texture coordinate v (model convention: v up)
     * @param dest at least 2 floats; {@code dest[0]} gets u', {@code dest[1]} gets v', the rest is untouched
     * @return {@code dest}
     */
    public float[] apply(float u, float v, float[] dest) {
        dest[0] = m00 * u + m01 * v + m02;
        dest[1] = m10 * u + m11 * v + m12;
        return dest;
    }

    /**
     * The six values, row-major: m00 m01 m02 m10 m11 m12 (for a shader's mat3).
     *
     * @return a new array of 6 floats the caller may change: the top two rows of the 3x3 matrix,
     *         whose third row is 0 0 1
     */
    public float[] values() {
        return new float[] {m00, m01, m02, m10, m11, m12};
    }

    @Override
    public String toString() {
        return "TextureTransform[" + m00 + " " + m01 + " " + m02 + "; " + m10 + " " + m11 + " " + m12 + "]";
    }
}
