package org.skinlab.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

class KeyframeTrackTest {
    private static final float[] TIMES = {0f, 1f};
    private static final float[] VALUES = {0f, 2f};

    @Test
    void curvedKeysWithoutTangentsAreRefused() {
        // The sampler reads both tangent arrays for BEZIER/HERMITE segments; a hand-built track
        // without them must fail when built, not with a NullPointerException mid-animation.
        for (Interpolation curved : new Interpolation[] {Interpolation.BEZIER, Interpolation.HERMITE}) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new KeyframeTrack(
                    TIMES, VALUES, 1, new Interpolation[] {curved, Interpolation.LINEAR}, null, new float[4]));
            assertEquals(curved + " keys need in- and out-tangents", e.getMessage());
        }
    }

    @Test
    void linearAndStepKeysNeedNoTangents() {
        KeyframeTrack t = new KeyframeTrack(TIMES, VALUES, 1,
                new Interpolation[] {Interpolation.STEP, Interpolation.LINEAR}, null, null);
        assertEquals(2, t.keyCount());
        assertEquals(2f, t.value(1, 0));
    }

    @Test
    void decreasingTimesAreRefused() {
        assertThrows(IllegalArgumentException.class, () -> new KeyframeTrack(new float[] {1f, 0f}, VALUES, 1,
                new Interpolation[] {Interpolation.LINEAR, Interpolation.LINEAR}, null, null));
    }
}
