package org.skinlab.model;

/**
 * How a keyframe track moves from one key to the next (COLLADA's INTERPOLATION names). CARDINAL
 * and BSPLINE are imported as {@link #LINEAR} with a warning.
 */
public enum Interpolation {
    /** The value blends linearly to the next key's (rotations as {@code RotationInterpolation} says). */
    LINEAR,
    /** The value holds the key's until the next key. */
    STEP,
    /** A cubic Bezier, the key's out- and the next key's in-tangent its inner control points; glTF's CUBICSPLINE. */
    BEZIER,
    /** A cubic Hermite curve, its derivatives stored as Bezier control points (see {@link KeyframeTrack}). */
    HERMITE
}
