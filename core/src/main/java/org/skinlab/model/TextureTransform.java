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
    public static final TextureTransform IDENTITY = new TextureTransform(1, 0, 0, 0, 1, 0);

    private final float m00;
    private final float m01;
    private final float m02;
    private final float m10;
    private final float m11;
    private final float m12;

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

    /** KHR_texture_transform's offset, rotation (radians) and scale, in the model's convention. */
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

    public boolean isIdentity() {
        return m00 == 1f && m01 == 0f && m02 == 0f && m10 == 0f && m11 == 1f && m12 == 0f;
    }

    /** Writes the transformed (u, v) into {@code dest[0..1]}. */
    public float[] apply(float u, float v, float[] dest) {
        dest[0] = m00 * u + m01 * v + m02;
        dest[1] = m10 * u + m11 * v + m12;
        return dest;
    }

    /** The six values, row-major: m00 m01 m02 m10 m11 m12 (for a shader's mat3). */
    public float[] values() {
        return new float[] {m00, m01, m02, m10, m11, m12};
    }

    @Override
    public String toString() {
        return "TextureTransform[" + m00 + " " + m01 + " " + m02 + "; " + m10 + " " + m11 + " " + m12 + "]";
    }
}
