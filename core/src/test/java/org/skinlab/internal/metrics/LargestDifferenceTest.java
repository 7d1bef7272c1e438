package org.skinlab.internal.metrics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;

import org.junit.jupiter.api.Test;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.importer.ModelImporter;
import org.skinlab.model.ImportException;
import org.skinlab.model.Model;
import org.skinlab.testing.TestPaths;

/**
 * The largest LBS-DQS distance over a clip, on the twist cylinder (assets/README.md): 172 degrees
 * of twist at the clip's end (4 s), where LBS pulls the joint ring (radius 0.25, each side of it
 * half on each joint) in to 0.25 cos 86 degrees while DQS keeps it: 0.25 (1 - cos 86 deg) =
 * 0.2326 apart, over the cylinder's diagonal sqrt(0.5^2 + 0.5^2 + 2^2) = 2.1213: 0.1096.
 */
class LargestDifferenceTest {
    private static Model cylinder() throws IOException, ImportException {
        return ModelImporter.read(TestPaths.asset("cylinders/cylinder-twist-high.dae"));
    }

    @Test
    void theTwistIsLargestAtItsEndAsTheRingCollapses() throws Exception {
        Model model = cylinder();
        LargestDifference d = LargestDifference.over(model, model.clips().get(0), RotationInterpolation.SLERP);
        double byHand = 0.25 * (1 - Math.cos(Math.toRadians(86))) / Math.sqrt(0.5 * 0.5 + 0.5 * 0.5 + 2 * 2);
        // The ring's vertices lie on the polygon, not the circle: within a percent of the hand value.
        assertEquals(byHand, d.relative(), 0.01 * byHand);
        assertEquals(4f, d.clipTime(), 1e-6f);
        // 30 samples a second over 4 s, and the end.
        assertEquals(121, d.samples());
    }

    @Test
    void atRestTheMethodsAgreeAndAnInterruptStopsIt() throws Exception {
        Model model = cylinder();
        LargestDifference rest = LargestDifference.over(model, null, RotationInterpolation.SLERP);
        assertEquals(1, rest.samples());
        assertTrue(rest.relative() < 1e-6, "at rest: " + rest.relative());
        Thread.currentThread().interrupt();
        try {
            LargestDifference stopped = LargestDifference.over(model, model.clips().get(0),
                    RotationInterpolation.SLERP);
            assertEquals(0, stopped.samples());
        } finally {
            Thread.interrupted();
        }
    }
}
