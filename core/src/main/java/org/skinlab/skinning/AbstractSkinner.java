package org.skinlab.skinning;

/**
 * What every skinner holds besides its kernel: the method, the geometry it reads, how it moves
 * normals, and a name for reports. Subclasses (scalar here, SIMD in the desktop's simd module)
 * add only their data layout and {@link #skin}. The one place that refuses
 * {@link NormalTransform#NONE} for a method without positions-only kernels, so no kernel can be
 * made that would write normals its caller did not ask for.
 */
public abstract class AbstractSkinner implements Skinner {
    private final SkinningMethod method;
    private final String implementation;
    /** The geometry the kernel reads, as {@link #geometry()} returns it. */
    protected final SkinnedGeometry geometry;
    /** How the kernel moves normals, as {@link #normalTransform()} returns it. */
    protected final NormalTransform normals;

    /**
     * Binds the common part of a skinner.
     *
     * @param method         the method the subclass's kernel implements
     * @param implementation a short name for reports, e.g. "scalar"
     * @param geometry       the geometry the kernel reads
     * @param normals        how the kernel moves normals
     * @throws IllegalArgumentException for {@link NormalTransform#NONE} with a method that has no
     *                                  positions-only kernels ({@link SkinningMethod#skinsPositionsOnly()})
     */
    protected AbstractSkinner(SkinningMethod method, String implementation, SkinnedGeometry geometry,
            NormalTransform normals) {
        if (normals == NormalTransform.NONE && !method.skinsPositionsOnly()) {
            throw new IllegalArgumentException(method.key() + " skinning has no positions-only kernel"
                    + " (NormalTransform.NONE): it is for lbs and dqs; use BLENDED_MATRIX or INVERSE_TRANSPOSE");
        }
        this.method = method;
        this.implementation = implementation;
        this.geometry = geometry;
        this.normals = normals;
    }

    @Override
    public final SkinningMethod method() {
        return method;
    }

    @Override
    public final NormalTransform normalTransform() {
        return normals;
    }

    @Override
    public final SkinnedGeometry geometry() {
        return geometry;
    }

    @Override
    public final String implementation() {
        return implementation;
    }

    /**
     * For {@link #skinDeformations} under {@link NormalTransform#NONE}: a deformation's record is
     * mostly its normal matrix, which positions-only skinning does not compute.
     *
     * @return the exception to throw, naming the method and implementation
     */
    protected final UnsupportedOperationException noDeformationsWithoutNormals() {
        return new UnsupportedOperationException(method.key() + " skinner (" + implementation
                + ") with NormalTransform.NONE skins positions only: skinDeformations needs a normal rule");
    }
}
