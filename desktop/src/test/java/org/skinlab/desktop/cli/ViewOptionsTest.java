package org.skinlab.desktop.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.skinlab.desktop.Cli;

/**
 * {@code skinlab view}'s picture options refuse what they cannot show before a window opens: a usage
 * error (status 2) whose message names the option's rule, no stack trace. (What they draw is
 * tested in the app package: CheckerViewTest, DifferenceScaleTest, BindPoseViewTest.)
 */
class ViewOptionsTest {
    private static void assertUsage(String expected, String... args) {
        Cli r = Cli.run(args);
        assertEquals(2, r.status, r::toString);
        assertTrue(r.err.contains(expected), r::toString);
        assertFalse(r.err.contains("\tat ") || r.err.contains("Exception"), r::toString);
    }

    @Test
    void theDifferenceScaleIsAutoOrAPercentage() {
        assertUsage("'five' is neither auto nor a percentage of the model's size", "view", "--difference-scale",
                "five");
        assertUsage("'0': the percentage must lie between 0.01 and 100", "view", "--difference-scale", "0");
        assertUsage("'250%': the percentage must lie between", "view", "--difference-scale", "250%");
    }

    @Test
    void thePitchIsAnAngleFromBelowToAbove() {
        assertUsage("--pitch needs an angle from -90 to 90", "view", "--pitch", "95");
        assertUsage("--pitch needs an angle from -90 to 90", "view", "--pitch", "NaN");
    }

    @Test
    void theViewsAreNamed() {
        assertUsage("(expected shaded, weights, difference or checker)", "view", "--view", "checkers");
    }
}
