package org.skinlab.model;

/**
 * How a keyframe track moves from one key to the next (COLLADA's INTERPOLATION names). CARDINAL
 * and BSPLINE are imported as {@link #LINEAR} with a warning.
 */
public enum Interpolation {
    LINEAR, STEP, BEZIER, HERMITE
}
