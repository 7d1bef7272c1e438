package org.skinlab.animation;

/**
 * How rotations between two keys are blended (the thesis' user-switchable choice). All three
 * take the shortest arc: the second quaternion is negated when the two lie in opposite
 * hemispheres, since q and -q are the same rotation.
 */
public enum RotationInterpolation {
    /**
     * Component-wise linear blend of the two quaternions, not renormalised. Between keys the result
     * is shorter than a unit quaternion; the matrix built from it (homogeneous form, see
     * {@link AnimationHelper#rotationMatrix}) scales the bone by |q|^2, at the midpoint between
     * keys a rotation phi apart by cos^2(phi / 4): the shrinking artifact the thesis showed.
     */
    LERP,
    /** Spherical linear interpolation: constant angular speed, exact great-circle path. */
    SLERP,
    /** Linear blend, then renormalised: same path as SLERP, slightly uneven speed, cheaper. */
    NLERP
}
