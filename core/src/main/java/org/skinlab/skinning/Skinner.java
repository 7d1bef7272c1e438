package org.skinlab.skinning;

/**
 * A skinning kernel bound to one {@link SkinnedGeometry}: deforms a range of its points with one
 * frame's {@link JointPalette}. Implementations allocate nothing in {@link #skin} and keep no
 * per-frame state, so disjoint ranges may run on different threads at once.
 */
public interface Skinner {
    /**
     * The method this skinner implements.
     *
     * @return the method, which says what {@link JointPalette#prepare} must derive before {@link #skin}
     */
    SkinningMethod method();

    /**
     * How this skinner moves normals, fixed when it was made.
     *
     * @return the normal rule; {@link NormalTransform#NONE} when it writes positions only
     */
    NormalTransform normalTransform();

    /**
     * The geometry this skinner reads.
     *
     * @return the geometry it was bound to when made; its points are what {@link #skin} indexes
     */
    SkinnedGeometry geometry();

    /**
     * Deforms points {@code [from, to)}: writes 3 floats per point into {@code outPositions} and
     * {@code outNormals} at {@code 3 * point}. Under {@link NormalTransform#NONE} only positions
     * are written and {@code outNormals} is not touched (it may be null). For DQS the palette must
     * have been through {@link JointPalette#prepare} this frame.
     *
     * @param palette      this frame's skinning matrices for the geometry's joints, prepared for
     *                     {@link #method()} ({@link JointPalette#prepare})
     * @param outPositions receives the deformed positions, 3 floats per point, at least
     *                     {@code 3 * to} long
     * @param outNormals   receives the deformed normals (as {@link #normalTransform()} says), 3 floats
     *                     per point, at least {@code 3 * to} long; unused, and may be null, under
     *                     {@link NormalTransform#NONE}
     * @param from         the first point to deform
     * @param to           one past the last point to deform, at most the geometry's
     *                     {@link SkinnedGeometry#pointCount()}
     */
    void skin(JointPalette palette, float[] outPositions, float[] outNormals, int from, int to);

    /** Floats per point written by {@link #skinDeformations}. */
    int DEFORMATION_FLOATS = 16;

    /**
     * Deforms points {@code [from, to)} into <em>deformations</em>, from which any number of render
     * vertices sharing a point's position are derived ({@link DeformationExpansion}): per point 16 floats
     * at {@code 16 * point}, the columns of the normal matrix N and the deformed position p, each
     * padded to four: {@code N00 N10 N20 0, N01 N11 N21 0, px py pz 0, N02 N12 N22 0} (p before N's
     * last column so that a vector expansion stores it straight from the loaded half). A rest normal
     * n deforms to {@code N n}, renormalised under {@link NormalTransform#INVERSE_TRANSPOSE}, as is
     * under {@link NormalTransform#BLENDED_MATRIX}. Under INVERSE_TRANSPOSE N is the cofactor matrix
     * of the blended linear part times the sign of its determinant, so a mirroring transform keeps
     * normals outward; the geometry's normals are not read. Same threading rules as {@link #skin}.
     *
     * @param palette         this frame's skinning matrices for the geometry's joints, prepared for
     *                        {@link #method()} ({@link JointPalette#prepare})
     * @param outDeformations receives {@link #DEFORMATION_FLOATS} floats per point, at least
     *                        {@code 16 * to} long
     * @param from            the first point to deform
     * @param to              one past the last point to deform, at most the geometry's
     *                        {@link SkinnedGeometry#pointCount()}
     * @throws UnsupportedOperationException under {@link NormalTransform#NONE} (positions only)
     */
    void skinDeformations(JointPalette palette, float[] outDeformations, int from, int to);

    /**
     * Ranges handed to {@link #skin} by a splitter should start at multiples of this (a SIMD
     * kernel's lane count); any range is still correct, only slower.
     *
     * @return the preferred alignment of range starts, in points; 1 for the scalar kernels
     */
    default int rangeAlignment() {
        return 1;
    }

    /**
     * Tells the skinner that its geometry's rest positions and normals have been rewritten (a
     * morph with animated weights, {@link MorphedRestShape}, between frames): a kernel that copied
     * them into a layout of its own re-reads them here, allocation-free; one that reads the
     * geometry's arrays every call has nothing to do. Not concurrently with {@link #skin}.
     */
    default void restShapeChanged() {
    }

    /**
     * A short name of the implementation for reports, e.g. "scalar" or "vector-256".
     *
     * @return the implementation's name
     */
    String implementation();

    /**
     * Deforms all points, on the calling thread: {@link #skin} over {@code [0, pointCount())}.
     *
     * @param palette      this frame's skinning matrices, prepared for {@link #method()}
     *                     ({@link JointPalette#prepare})
     * @param outPositions receives the deformed positions, 3 floats per point
     * @param outNormals   receives the deformed normals, 3 floats per point; unused, and may be
     *                     null, under {@link NormalTransform#NONE}
     */
    default void skinAll(JointPalette palette, float[] outPositions, float[] outNormals) {
        skin(palette, outPositions, outNormals, 0, geometry().pointCount());
    }
}
