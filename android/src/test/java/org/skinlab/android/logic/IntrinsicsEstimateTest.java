package org.skinlab.android.logic;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.skinlab.ar.CameraIntrinsics;
import org.skinlab.ar.LensDistortion;

/**
 * {@link IntrinsicsEstimate} and {@link Camera2Lens} on hand-made camera reports: the pinhole's
 * crop and scale, each lens key at the API levels that read it, the device's own correction, and
 * every way a lens is refused. Expected values are worked out by hand in the comments (Camera2's
 * pixel x is centred at x + 0.5, ours at x); the old key is also checked against its defining
 * formula applied in pixels, independently of the conversion.
 */
class IntrinsicsEstimateTest {
    private static final int[] ARRAY_4_3 = {0, 0, 4000, 3000};
    private static final float[] CALIBRATION_4_3 = {3200, 3210, 2010, 1490, 0};
    private static final float[] LENS = {-0.1f, 0.02f, -0.003f, 0.0004f, -0.0005f};
    private static final int[] MODES = {0, 1, 2};

    private static CameraReport report(int sdk, int[] pre, int[] active, float[] calibration, float[] lens,
            float[] radial, int[] modes) {
        return new CameraReport(sdk, pre, active, calibration, lens, radial, modes, Double.NaN, Double.NaN);
    }

    @Test
    void thePinholeIsCroppedAndScaledToTheStream() {
        // 4000x3000 to 640x480: a scale by 0.16. cx = (2010 - 0.5 + 0.5) * 0.16 - 0.5 = 321.1.
        CameraIntrinsics k = IntrinsicsEstimate.of(report(28, null, ARRAY_4_3, CALIBRATION_4_3, null, null, null), 640,
                480).intrinsics();
        assertEquals(512, k.fx(), 1e-9);
        assertEquals(513.6, k.fy(), 1e-4);
        assertEquals(321.1, k.cx(), 1e-9);
        assertEquals(237.9, k.cy(), 1e-9);
        assertFalse(k.isDistorted());
        // A 16:9 array streamed at 4:3: the centred 3000x2250 crop (from x = 500), then 640 / 3000.
        // Camera2's centre of a 4000x2250 array is (2000, 1125); the stream's is (319.5, 239.5).
        CameraIntrinsics crop = IntrinsicsEstimate.of(report(28, null, new int[] {0, 0, 4000, 2250},
                new float[] {3000, 3000, 2000, 1125, 0}, null, null, null), 640, 480).intrinsics();
        assertEquals(319.5, crop.cx(), 1e-6, "the centre stays the centre");
        assertEquals(239.5, crop.cy(), 1e-6);
        assertEquals(640, crop.fx(), 1e-6);
        // Focal length 4.3 mm on a 5.6 mm wide sensor: fx = 4.3 / 5.6 of the width.
        CameraIntrinsics physical = IntrinsicsEstimate.of(new CameraReport(28, null, ARRAY_4_3, null, null, null, null,
                4.3, 5.6), 640, 480).intrinsics();
        assertEquals(4.3 / 5.6 * 640, physical.fx(), 1e-9);
        CameraIntrinsics guess = IntrinsicsEstimate.of(report(28, null, null, null, null, null, null), 640, 480)
                .intrinsics();
        assertEquals(IntrinsicsEstimate.FALLBACK_FOV_DEGREES, guess.horizontalFovDegrees(), 1e-9);
        CameraIntrinsics nanCalibration = IntrinsicsEstimate.of(report(28, null, ARRAY_4_3,
                new float[] {3200, 3200, Float.NaN, 1500, 0}, null, null, null), 640, 480).intrinsics();
        assertEquals(IntrinsicsEstimate.FALLBACK_FOV_DEGREES, nanCalibration.horizontalFovDegrees(), 1e-9,
                "a calibration with NaN is none");
    }

    @Test
    void withoutALensTheCalibrationMovesIntoTheActiveArray() {
        // Pre-correction 4032x3024, active (16, 12)-(4016, 3012), 4000x3000; the optical centre
        // at Camera2's (2016, 1512) of the pre-correction array is our (1999.5, 1499.5) of the
        // active one, the middle: the stream's (319.5, 239.5).
        IntrinsicsEstimate e = IntrinsicsEstimate.of(report(28, new int[] {0, 0, 4032, 3024},
                new int[] {16, 12, 4016, 3012}, new float[] {3200, 3200, 2016, 1512, 0}, null, null, MODES), 640, 480);
        assertEquals(319.5, e.intrinsics().cx(), 1e-9);
        assertEquals(239.5, e.intrinsics().cy(), 1e-9);
        assertEquals(512, e.intrinsics().fx(), 1e-9);
        assertFalse(e.correctionOff(), "the device's correction left as it is");
        assertNull(e.problem());
    }

    @Test
    void lensDistortionOnACameraThatDoesNotCorrectIsTakenAsItIs() {
        IntrinsicsEstimate e = IntrinsicsEstimate.of(report(28, ARRAY_4_3, ARRAY_4_3, CALIBRATION_4_3, LENS, null,
                null), 640, 480);
        LensDistortion d = e.intrinsics().distortion();
        // [k1, k2, k3, p1, p2]: kappa_4 multiplies 2 x y in x_c (OpenCV's p1), kappa_5 r^2 + 2 x^2 (p2).
        assertEquals(new LensDistortion(-0.1f, 0.02f, -0.003f, 0.0004f, -0.0005f), d);
        assertEquals(512, e.intrinsics().fx(), 1e-9, "the pinhole as without a lens");
        assertEquals(321.1, e.intrinsics().cx(), 1e-9);
        assertFalse(e.correctionOff(), "nothing to turn off");
        assertNull(e.problem());
        // The lens survives the 16:9 crop unchanged (normalised terms); the pinhole is cropped as ever.
        IntrinsicsEstimate wide = IntrinsicsEstimate.of(report(28, null, ARRAY_4_3, CALIBRATION_4_3, LENS, null, null),
                640, 360);
        assertEquals(d, wide.intrinsics().distortion());
        assertEquals(3200 * 640 / 4000.0, wide.intrinsics().fx(), 1e-9);
    }

    @Test
    void aCameraThatCorrectsIsToldNotToAndTheRawArrayIsUsed() {
        // The raw image is the pre-correction array's: the calibration is not moved.
        IntrinsicsEstimate e = IntrinsicsEstimate.of(report(28, new int[] {0, 0, 4032, 3024},
                new int[] {16, 12, 4016, 3012}, new float[] {3225.6f, 3225.6f, 2016, 1512, 0}, LENS, null, MODES), 640,
                480);
        assertTrue(e.correctionOff());
        assertTrue(e.intrinsics().isDistorted());
        // 4032 / 640 = 6.3: fx = 3225.6 / 6.3 = 512; cx = 2016 / 6.3 - 0.5 = 319.5.
        assertEquals(512, e.intrinsics().fx(), 1e-4);
        assertEquals(319.5, e.intrinsics().cx(), 1e-9);
        assertEquals(239.5, e.intrinsics().cy(), 1e-9);
        // Correction listed but OFF missing (Camera2 says OFF is always listed): the lens cannot be used.
        IntrinsicsEstimate noOff = IntrinsicsEstimate.of(report(28, new int[] {0, 0, 4032, 3024},
                new int[] {16, 12, 4016, 3012}, CALIBRATION_4_3, LENS, null, new int[] {1, 2}), 640, 480);
        assertFalse(noOff.intrinsics().isDistorted());
        assertFalse(noOff.correctionOff());
        assertTrue(noOff.problem().contains("cannot be told not to"), noOff.problem());
        // Only OFF listed: a device without correction; nothing to set.
        IntrinsicsEstimate onlyOff = IntrinsicsEstimate.of(report(28, ARRAY_4_3, ARRAY_4_3, CALIBRATION_4_3, LENS, null,
                new int[] {0}), 640, 480);
        assertTrue(onlyOff.intrinsics().isDistorted());
        assertFalse(onlyOff.correctionOff());
    }

    @Test
    void lensesThatCannotBeUsedFallBackToTheUncorrectedPinholeAndSayWhy() {
        int[] pre = {0, 0, 4032, 3024};
        int[] active = {16, 12, 4016, 3012};
        float[] calibration = {3200, 3200, 2016, 1512, 0};
        // All zeros: an ideal lens, silently.
        IntrinsicsEstimate zeros = IntrinsicsEstimate.of(report(28, pre, active, calibration, new float[5], null,
                MODES), 640, 480);
        assertFalse(zeros.intrinsics().isDistorted());
        assertFalse(zeros.correctionOff());
        assertNull(zeros.problem());
        assertEquals(319.5, zeros.intrinsics().cx(), 1e-9, "the active array's pinhole");
        // NaN, or the wrong count.
        IntrinsicsEstimate nan = IntrinsicsEstimate.of(report(28, pre, active, calibration,
                new float[] {-0.1f, Float.NaN, 0, 0, 0}, null, MODES), 640, 480);
        assertFalse(nan.intrinsics().isDistorted());
        assertFalse(nan.correctionOff());
        assertEquals(319.5, nan.intrinsics().cx(), 1e-9);
        assertTrue(nan.problem().contains("LENS_DISTORTION is not 5 finite numbers"), nan.problem());
        assertTrue(IntrinsicsEstimate.of(report(28, pre, active, calibration, new float[] {-0.1f, 0, 0}, null, MODES),
                640, 480).problem().contains("not 5 finite"));
        // k1 = -0.6 folds back at r = 1 / sqrt(3 * 0.6) = 0.745, where r_d peaks at 0.497; the
        // stream's corner is at r_d = hypot(2016, 1512) / 2000 = 1.26: no inverse there.
        IntrinsicsEstimate folded = IntrinsicsEstimate.of(report(28, pre, active,
                new float[] {2000, 2000, 2016, 1512, 0}, new float[] {-0.6f, 0, 0, 0, 0}, null, MODES), 640, 480);
        assertFalse(folded.intrinsics().isDistorted());
        assertFalse(folded.correctionOff(), "the device's own correction left on");
        assertTrue(folded.problem().contains("cannot be undone at the stream's pixel (-0.5, -0.5)"), folded.problem());
        // k1 = -2, k2 = 1.2: r (1 - 2 r^2 + 1.2 r^4) rises to 0.29 at r = 0.46, falls to 0.15 at
        // r = 0.89 and rises again. With fx = 4500 every border point (r_d 0.34 to 0.56) has its
        // only preimage on the outer branch (r 1.09 to 1.16) and undoes; the image folds inside.
        IntrinsicsEstimate foldAndRise = IntrinsicsEstimate.of(report(28, pre, active,
                new float[] {4500, 4500, 2016, 1512, 0}, new float[] {-2, 1.2f, 0, 0, 0}, null, MODES), 640, 480);
        assertFalse(foldAndRise.intrinsics().isDistorted());
        assertTrue(foldAndRise.problem().contains("folds over inside the stream, toward pixel (-0.5, -0.5)"),
                foldAndRise.problem());
        // A lens without a calibration to normalise it.
        IntrinsicsEstimate uncalibrated = IntrinsicsEstimate.of(new CameraReport(28, pre, active, null, LENS, null,
                MODES, 4.3, 5.6), 640, 480);
        assertFalse(uncalibrated.intrinsics().isDistorted());
        assertTrue(uncalibrated.problem().contains("no LENS_INTRINSIC_CALIBRATION"), uncalibrated.problem());
        // No correction modes reported although the arrays differ: correction cannot be ruled out
        // nor turned off.
        IntrinsicsEstimate unknown = IntrinsicsEstimate.of(report(28, pre, active, calibration, LENS, null, null), 640,
                480);
        assertFalse(unknown.intrinsics().isDistorted());
        assertTrue(unknown.problem().contains("cannot be told not to"), unknown.problem());
    }

    /** A square 3000x3000 array, centre (1500, 1500), fx = fy = 2400: a = b = 2400 / 1500 = 1.6. */
    private static final int[] SQUARE = {0, 0, 3000, 3000};
    private static final float[] SQUARE_CALIBRATION = {2400, 2400, 1500, 1500, 0};
    private static final float[] KAPPA = {1.02f, -0.2f, 0.05f, 0.01f, 0.001f, -0.002f};

    @Test
    void lensRadialDistortionBelowApi28IsConvertedExactlyWhenItsNormalisationIsIsotropic() {
        IntrinsicsEstimate e = IntrinsicsEstimate.of(report(26, SQUARE, SQUARE, SQUARE_CALIBRATION, LENS, KAPPA, null),
                600, 600);
        assertFalse(e.correctionOff(), "no control below API 28");
        assertNull(e.problem());
        LensDistortion d = e.intrinsics().distortion();
        double s = 1.6;
        double k0 = KAPPA[0];
        // k1 = kappa_1 s^2 / kappa_0, ..., p1 = kappa_4 s / kappa_0; the focal lengths times kappa_0.
        assertEquals(KAPPA[1] * s * s / k0, d.k1(), 1e-7);
        assertEquals(KAPPA[2] * Math.pow(s, 4) / k0, d.k2(), 1e-7);
        assertEquals(KAPPA[3] * Math.pow(s, 6) / k0, d.k3(), 1e-7);
        assertEquals(KAPPA[4] * s / k0, d.p1(), 1e-9);
        assertEquals(KAPPA[5] * s / k0, d.p2(), 1e-9);
        assertEquals(2400 * k0 * 0.2, e.intrinsics().fx(), 1e-4);
        // LENS_DISTORTION is not read below 28 (it does not exist there).
        assertEquals(e, IntrinsicsEstimate.of(report(26, SQUARE, SQUARE, SQUARE_CALIBRATION, null, KAPPA, null), 600,
                600));

        // Independently: the key's own formula in Camera2's pixels (edge-normalised, x_i = (u - c_x)
        // / R_x) against our intrinsics' projection, scaled by 600 / 3000 to the stream.
        double[] out = new double[2];
        for (double[] p : new double[][] {{0.3, 0.2}, {-0.5, 0.4}, {0.55, -0.55}, {0, 0.6}}) {
            double ui = 2400 * p[0] + 1500;
            double vi = 2400 * p[1] + 1500;
            double xi = (ui - 1500) / 1500;
            double yi = (vi - 1500) / 1500;
            double r2 = xi * xi + yi * yi;
            double radial = KAPPA[0] + KAPPA[1] * r2 + KAPPA[2] * r2 * r2 + KAPPA[3] * r2 * r2 * r2;
            double xc = xi * radial + KAPPA[4] * 2 * xi * yi + KAPPA[5] * (r2 + 2 * xi * xi);
            double yc = yi * radial + KAPPA[5] * 2 * xi * yi + KAPPA[4] * (r2 + 2 * yi * yi);
            double uc = 1500 * xc + 1500;
            double vc = 1500 * yc + 1500;
            e.intrinsics().toPixel(p[0], p[1], 1, out);
            assertEquals(uc * 0.2 - 0.5, out[0], 1e-6, "u at " + p[0] + ", " + p[1]);
            assertEquals(vc * 0.2 - 0.5, out[1], 1e-6, "v at " + p[0] + ", " + p[1]);
        }
    }

    @Test
    void lensRadialDistortionThatBrownConradyCannotExpressIsNotUsed() {
        // 4:3 with the centre in the middle: a = 3200 / 2000 = 1.6, b = 3200 / 1500 = 2.13.
        IntrinsicsEstimate elliptic = IntrinsicsEstimate.of(report(26, ARRAY_4_3, ARRAY_4_3,
                new float[] {3200, 3200, 2000, 1500, 0}, null, KAPPA, null), 640, 480);
        assertFalse(elliptic.intrinsics().isDistorted());
        assertTrue(elliptic.problem().contains("normalised differently in x and y (f/R 1.6000 and 2.1333)"),
                elliptic.problem());
        assertEquals(512, elliptic.intrinsics().fx(), 1e-9, "the plain pinhole");
        IntrinsicsEstimate negative = IntrinsicsEstimate.of(report(26, SQUARE, SQUARE, SQUARE_CALIBRATION, null,
                new float[] {-1, 0, 0, 0, 0, 0}, null), 600, 600);
        assertTrue(negative.problem().contains("kappa_0 is not positive"), negative.problem());
        IntrinsicsEstimate zeros = IntrinsicsEstimate.of(report(26, SQUARE, SQUARE, SQUARE_CALIBRATION, null,
                new float[6], null), 600, 600);
        assertNull(zeros.problem(), "all zeros: nothing reported");
        assertFalse(zeros.intrinsics().isDistorted());
        IntrinsicsEstimate five = IntrinsicsEstimate.of(report(26, SQUARE, SQUARE, SQUARE_CALIBRATION, null, LENS,
                null), 600, 600);
        assertTrue(five.problem().contains("not 6 finite numbers"), five.problem());
        // Arrays that differ below API 28: the device may correct, and there is no control to stop it.
        IntrinsicsEstimate correcting = IntrinsicsEstimate.of(report(26, new int[] {0, 0, 3032, 3032},
                new int[] {16, 16, 3016, 3016}, new float[] {2400, 2400, 1516, 1516, 0}, null, KAPPA, null), 600, 600);
        assertFalse(correcting.intrinsics().isDistorted());
        assertFalse(correcting.correctionOff());
        assertTrue(correcting.problem().contains("cannot be told not to"), correcting.problem());
        // At API 28 the old key is not read.
        IntrinsicsEstimate at28 = IntrinsicsEstimate.of(report(28, SQUARE, SQUARE, SQUARE_CALIBRATION, null, KAPPA,
                null), 600, 600);
        assertFalse(at28.intrinsics().isDistorted());
        assertNull(at28.problem());
    }
}
