package org.skinlab.ar;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.junit.jupiter.api.Test;
import org.skinlab.internal.synthetic.PlacedMarker;
import org.skinlab.internal.ar.PoseMath;

/**
 * {@link OneEuroFilter} and {@link PoseFilter} against the numbers their parameters predict.
 *
 * <p>At rest (30 frames per second, minCutoff 1 Hz: alpha = 1 / (1 + 30 / (2 pi)) = 0.173) white
 * noise of standard deviation s leaves the first-order filter with
 * {@code s sqrt(alpha / (2 - alpha))} = 0.31 s, 3.2x less jitter; the noise's own speed raises the
 * cutoff a little (beta), so the test asks for 2.5x. A ramp at speed v is followed with a steady
 * lag of {@code v / (2 pi fc)} in value; at 0.3 m/s the speed estimate drives fc to 1 + 20 * 0.3 =
 * 7 Hz: 23 ms, 6.8 mm behind; a fixed 1 Hz filter would trail by 159 ms (48 mm). The test allows
 * 10 mm, and asks the fixed filter to trail at least 3x more.
 */
class PoseFilterTest {
    private static final long FRAME = 33_333_333L;

    @Test
    void jitterAtRestDropsAsPredicted() {
        OneEuroFilter f = new OneEuroFilter(1.0, 20, 1.0);
        Random random = new Random(5);
        double sumIn = 0, sumOut = 0;
        int n = 3000;
        for (int i = 0; i < n; i++) {
            double noisy = 0.5 + 0.002 * random.nextGaussian();
            double out = f.filter(noisy, i * FRAME);
            if (i > 100) {
                sumIn += (noisy - 0.5) * (noisy - 0.5);
                sumOut += (out - 0.5) * (out - 0.5);
            }
        }
        double ratio = Math.sqrt(sumIn / sumOut);
        assertTrue(ratio > 2.5, "jitter reduced " + ratio + "x");
    }

    @Test
    void aFastMoveLagsLittle() {
        OneEuroFilter f = new OneEuroFilter(1.0, 20, 1.0);
        double lag = 0;
        for (int i = 0; i < 90; i++) {
            double x = 0.3 * i * FRAME * 1e-9; // 0.3 m/s
            lag = x - f.filter(x, i * FRAME);
        }
        assertTrue(lag < 0.010 && lag > 0, "steady lag " + lag * 1000 + " mm at 0.3 m/s");
        OneEuroFilter fixed = new OneEuroFilter(1.0, 0, 1.0);
        double fixedLag = 0;
        for (int i = 0; i < 90; i++) {
            double x = 0.3 * i * FRAME * 1e-9;
            fixedLag = x - fixed.filter(x, i * FRAME);
        }
        assertTrue(fixedLag > 3 * lag, "without beta: " + fixedLag * 1000 + " mm");
    }

    @Test
    void theFirstSamplePassesAndRotationsStayRotationsWithoutSpinningOnSignFlips() {
        PoseFilter filter = new PoseFilter();
        double[] r = PlacedMarker.facingCamera(10, 20, 30);
        double[] outR = new double[9];
        double[] outT = new double[3];
        filter.update(r, new double[] {0.1, 0.2, 0.5}, 0, outR, outT);
        assertEquals(0, PoseMath.angleDegrees(r, outR), 1e-5);
        assertEquals(0.5, outT[2], 0);
        // Small rotation noise around r: the output stays within a degree and orthonormal.
        Random random = new Random(8);
        for (int i = 1; i < 200; i++) {
            double[] noisy = PlacedMarker.facingCamera(10 + 0.5 * random.nextGaussian(), 20 + 0.5 * random.nextGaussian(),
                    30 + 0.5 * random.nextGaussian());
            filter.update(noisy, new double[] {0.1, 0.2, 0.5}, i * FRAME, outR, outT);
            assertTrue(PoseMath.angleDegrees(r, outR) < 1.0, "frame " + i);
            double det = outR[0] * (outR[4] * outR[8] - outR[5] * outR[7]) - outR[1] * (outR[3] * outR[8] - outR[5] * outR[6])
                    + outR[2] * (outR[3] * outR[7] - outR[4] * outR[6]);
            assertEquals(1, det, 1e-9);
        }
        // A turn by 179 degrees and back arrives by the short way, never through 360.
        double[] far = PlacedMarker.facingCamera(10, 20, 30 + 179);
        for (int i = 200; i < 260; i++) {
            filter.update(far, new double[] {0.1, 0.2, 0.5}, i * FRAME, outR, outT);
        }
        assertTrue(PoseMath.angleDegrees(far, outR) < 1.0, "reached the turned rotation: " + PoseMath.angleDegrees(far, outR));
    }
}
