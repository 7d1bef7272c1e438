package org.skinlab.skinning;

/**
 * A skinning kernel bound to one {@link SkinnedGeometry}: deforms a range of its points with one
 * frame's {@link JointPalette}. Implementations allocate nothing in {@link #skin} and keep no
 * per-frame state, so disjoint ranges may run on different threads at once.
 */
public interface Skinner {
    SkinningMethod method();

    NormalTransform normalTransform();

    /** The geometry this skinner reads. */
    SkinnedGeometry geometry();

    /**
     * Deforms points {@code [from, to)}: writes 3 floats per point into {@code outPositions} and
     * {@code outNormals} at {@code 3 * point}. For DQS the palette must have been through
     * {@link JointPalette#prepareDualQuaternions()} this frame.
     */
    void skin(JointPalette palette, float[] outPositions, float[] outNormals, int from, int to);

    /**
     * Ranges handed to {@link #skin} by a splitter should start at multiples of this (a SIMD
     * kernel's lane count); any range is still correct, only slower.
     */
    default int rangeAlignment() {
        return 1;
    }

    /** A short name of the implementation for reports, e.g. "scalar" or "vector-256". */
    String implementation();

    /** Deforms all points. */
    default void skinAll(JointPalette palette, float[] outPositions, float[] outNormals) {
        skin(palette, outPositions, outNormals, 0, geometry().pointCount());
    }
}
