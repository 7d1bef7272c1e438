package org.skinlab.mixer;

/** How a {@link Layer} combines with the layers below it. */
public enum LayerMode {
    /**
     * The layer's pose replaces the pose below on the joints its clips animate, by the layer's
     * weight times the mask's: translation and scale blend linearly, rotation by slerp.
     */
    OVERRIDE,
    /**
     * The layer's clips' difference from their own pose at a reference time is added on top, by
     * the layer's weight times the mask's: {@code base * slerp(identity, delta, w)} for rotations,
     * {@code base + w * delta} for translation and scale (three.js' additive blend mode).
     */
    ADDITIVE
}
