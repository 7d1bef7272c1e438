package org.skinlab.skinning;

/**
 * How a skinner moves normals.
 *
 * <p>A blended LBS matrix is not a rotation, and a joint with non-uniform scale is not one either;
 * a normal moved by such a matrix is no longer perpendicular to the surface. The exact rule is the
 * inverse-transpose (computed as the cofactor matrix, which differs from it only by the positive
 * factor det M) followed by renormalisation. Many runtimes and the shared C++ benchmark reference
 * apply the blended matrix itself and leave the length to the fragment shader; that variant is
 * kept so benchmarks compare identical work, and its checksum matches the reference's.
 *
 * <p>{@link #NONE} skins positions only, for a caller that has no use for normals (a depth or
 * shadow pass, collision, a benchmark asking what normals cost); only the methods whose
 * {@link SkinningMethod#skinsPositionsOnly()} holds have kernels for it.
 */
public enum NormalTransform {
    /** Cofactor (inverse-transpose up to a positive factor) of the blended linear part, renormalised. */
    INVERSE_TRANSPOSE,
    /** The blended linear part applied as is, not renormalised (the benchmark reference's rule). */
    BLENDED_MATRIX,
    /**
     * Positions only: normals are neither read nor written, and {@code outNormals} may be null.
     * The positions are the same, bit for bit, as under the other rules. Only for methods whose
     * {@link SkinningMethod#skinsPositionsOnly()} holds (LBS and DQS); a skinner for another method
     * refuses it with an {@link IllegalArgumentException}, and {@link Skinner#skinDeformations}
     * (whose records are normal matrices) is refused too.
     */
    NONE
}
