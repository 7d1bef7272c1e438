package org.skinlab.desktop.ar;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

import boofcv.alg.geo.calibration.CalibrationObservation;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.skinlab.ar.CameraIntrinsics;
import org.skinlab.ar.GrayImage;
import org.skinlab.ar.LensDistortion;

/**
 * The acceptance: a calibration from synthetic photos of the printed target
 * ({@link CalibrationPhotos}: 14 views, tilts up to 45 degrees, blur, noise, uneven light)
 * recovers the synthetic camera's focal lengths and distortion within 1%.
 *
 * <p>How the distortion is compared: k1 within 1% of its value, and the lens' displacement of
 * each image corner pixel within 1% of the true displacement (about 60 px here). The latter is
 * what matters for the picture and is well determined; the single higher terms (k2, p1, p2) trade
 * against each other and against the principal point, so they are held to looser bounds (k2 within
 * 5% of its value, p1 and p2 within 2e-4 absolute, the principal point within 1 px).
 */
class CameraCalibrationTest {
    private static CameraCalibration.Result result;
    private static List<CalibrationObservation> views;

    @BeforeAll
    static void calibrate() {
        TargetDetector detector = new TargetDetector(CalibrationPhotos.TARGET);
        views = new ArrayList<>();
        List<GrayImage> images = CalibrationPhotos.images();
        for (int i = 0; i < images.size(); i++) {
            assertTrue(CalibrationPhotos.clearance(i) > 0, "view " + i + " shows the whole target");
            TargetDetector.View v = detector.detect(images.get(i));
            assertTrue(v.found(), () -> "view " + v.problem());
            views.add(v.points());
        }
        result = CameraCalibration.calibrate(detector.layout(), views, 640, 480, false);
    }

    /** Where the true lens puts each image corner pixel's ideal point, in pixels, under {@code k}'s lens and focal lengths. */
    private static double[] cornerDisplacements(CameraIntrinsics truth, CameraIntrinsics k) {
        double[] u = {0, 639, 639, 0};
        double[] v = {0, 0, 479, 479};
        double[] out = new double[8];
        double[] ideal = new double[2];
        double[] distorted = new double[2];
        for (int i = 0; i < 4; i++) {
            assertTrue(truth.toNormalized(u[i], v[i], ideal));
            k.distortion().distort(ideal[0], ideal[1], distorted);
            out[2 * i] = k.fx() * (distorted[0] - ideal[0]);
            out[2 * i + 1] = k.fy() * (distorted[1] - ideal[1]);
        }
        return out;
    }

    @Test
    void recoversTheFocalLengthsAndTheLensWithinOnePercent() {
        CameraIntrinsics truth = CalibrationPhotos.CAMERA;
        CameraIntrinsics k = result.intrinsics();
        assertEquals(640, k.width());
        assertEquals(480, k.height());
        assertEquals(truth.fx(), k.fx(), 0.01 * truth.fx(), "fx");
        assertEquals(truth.fy(), k.fy(), 0.01 * truth.fy(), "fy");
        assertEquals(truth.cx(), k.cx(), 1.0, "cx");
        assertEquals(truth.cy(), k.cy(), 1.0, "cy");
        LensDistortion t = truth.distortion();
        LensDistortion d = k.distortion();
        assertEquals(t.k1(), d.k1(), 0.01 * Math.abs(t.k1()), "k1");
        assertEquals(t.k2(), d.k2(), 0.05 * Math.abs(t.k2()), "k2");
        assertEquals(0, d.k3(), "k3 not estimated");
        assertEquals(t.p1(), d.p1(), 2e-4, "p1");
        assertEquals(t.p2(), d.p2(), 2e-4, "p2");
        double[] expected = cornerDisplacements(truth, truth);
        double[] found = cornerDisplacements(truth, k);
        for (int i = 0; i < 4; i++) {
            double size = Math.hypot(expected[2 * i], expected[2 * i + 1]);
            assertTrue(size > 40, "the lens moves corner " + i + " visibly: " + size);
            double error = Math.hypot(found[2 * i] - expected[2 * i], found[2 * i + 1] - expected[2 * i + 1]);
            assertTrue(error < 0.01 * size, "corner " + i + ": displacement off by " + error + " px of " + size);
        }
        double[] shift = CameraCalibration.cornerShift(truth);
        for (int i = 0; i < 4; i++) {
            assertEquals(Math.hypot(expected[2 * i], expected[2 * i + 1]), shift[i], 1e-6, "cornerShift " + i);
        }
    }

    @Test
    void reportsASmallReprojectionErrorAndNoGaps() {
        assertEquals(views.size(), result.rms().length);
        assertTrue(result.meanRms() < 0.3, "mean RMS " + result.meanRms());
        assertTrue(result.maxRms() < 0.3, "max RMS " + result.maxRms());
        assertTrue(result.maxRms() > 0.005, "noise and blur leave some error: " + result.maxRms());
        for (int i = 0; i < views.size(); i++) {
            assertTrue(result.maxError()[i] >= result.rms()[i], "max >= RMS in view " + i);
        }
        assertEquals(List.of(), result.warnings(), "14 views reaching every corner and edge, tilted both ways");
    }

    /**
     * With k3 free the model has a term the true lens lacks; it is fitted where the points are and
     * extrapolated beyond, so the very corner pixels are held to 2% (the fit inside the views'
     * reach is as good as without k3).
     */
    @Test
    void withK3TheLensIsStillRecovered() {
        TargetDetector detector = new TargetDetector(CalibrationPhotos.TARGET);
        CameraIntrinsics k = CameraCalibration.calibrate(detector.layout(), views, 640, 480, true).intrinsics();
        CameraIntrinsics truth = CalibrationPhotos.CAMERA;
        assertEquals(truth.fx(), k.fx(), 0.01 * truth.fx(), "fx");
        assertEquals(truth.fy(), k.fy(), 0.01 * truth.fy(), "fy");
        double[] expected = cornerDisplacements(truth, truth);
        double[] found = cornerDisplacements(truth, k);
        for (int i = 0; i < 4; i++) {
            double size = Math.hypot(expected[2 * i], expected[2 * i + 1]);
            double error = Math.hypot(found[2 * i] - expected[2 * i], found[2 * i + 1] - expected[2 * i + 1]);
            assertTrue(error < 0.02 * size, "corner " + i + ": displacement off by " + error + " px of " + size);
        }
    }

    @Test
    void refusesTooFewViews() {
        TargetDetector detector = new TargetDetector(CalibrationPhotos.TARGET);
        IllegalArgumentException e = org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class,
                () -> CameraCalibration.calibrate(detector.layout(), views.subList(0, 2), 640, 480, false));
        assertTrue(e.getMessage().contains("too few views") && e.getMessage().contains("2"), e.getMessage());
    }
}
