package org.skinlab.android;

import static org.junit.Assert.assertArrayEquals;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertNull;
import static org.junit.Assert.assertTrue;
import static org.robolectric.Shadows.shadowOf;

import android.graphics.Rect;
import android.hardware.camera2.CameraCharacteristics;
import android.hardware.camera2.CameraMetadata;
import android.os.Build;

import org.junit.After;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.robolectric.RobolectricTestRunner;
import org.robolectric.annotation.Config;
import org.robolectric.shadows.ShadowCameraCharacteristics;
import org.skinlab.android.logic.CameraReport;
import org.skinlab.android.logic.IntrinsicsEstimate;
import org.skinlab.ar.CameraIntrinsics;
import org.skinlab.ar.LensDistortion;

/**
 * The lens as CameraSource reads it from Robolectric's shadowed characteristics: at API 28 and
 * later LENS_DISTORTION and the correction modes, below 28 LENS_RADIAL_DISTORTION (and never the
 * other key: the API-28 key does not exist at 26), into intrinsics with that lens; and a lens that
 * cannot be used, said in the status line. The capture request's DISTORTION_CORRECTION_MODE is not
 * checked: Robolectric's capture session keeps no request to look at ({@code IntrinsicsEstimate}'s
 * JVM tests decide when it is set).
 */
@RunWith(RobolectricTestRunner.class)
@Config(minSdk = 26, shadows = ShadowPermissionRequestState.class)
public class CameraLensTest {
    /** A square 3000x3000 array (the old key converts exactly there), fx = 2400, centre in the middle. */
    private static final float[] CALIBRATION = {2400, 2400, 1500, 1500, 0};
    private static final float[] LENS = {-0.1f, 0.02f, -0.003f, 0.0004f, -0.0005f};
    private static final float[] KAPPA = {1, -0.05f, 0.01f, 0, 0.0002f, -0.0001f};

    private final AppDriver app = new AppDriver();

    @After
    public void finish() {
        app.finish();
    }

    /** The arrays (both the same) and the calibration; Robolectric's shadow takes each key once. */
    private static void geometry(CameraCharacteristics c, int width, int height, float[] calibration) {
        shadowOf(c).set(CameraCharacteristics.SENSOR_INFO_ACTIVE_ARRAY_SIZE, new Rect(0, 0, width, height));
        shadowOf(c).set(CameraCharacteristics.SENSOR_INFO_PRE_CORRECTION_ACTIVE_ARRAY_SIZE,
                new Rect(0, 0, width, height));
        shadowOf(c).set(CameraCharacteristics.LENS_INTRINSIC_CALIBRATION, calibration);
    }

    private static void geometry(CameraCharacteristics c) {
        geometry(c, 3000, 3000, CALIBRATION);
    }

    // LENS_RADIAL_DISTORTION is deprecated; it is what cameras below API 28 report.
    @SuppressWarnings("deprecation")
    private static void lens(CameraCharacteristics c, float[] lens) {
        if (Build.VERSION.SDK_INT >= 28) {
            shadowOf(c).set(CameraCharacteristics.LENS_DISTORTION, lens);
            shadowOf(c).set(CameraCharacteristics.DISTORTION_CORRECTION_AVAILABLE_MODES, new int[] {
                CameraMetadata.DISTORTION_CORRECTION_MODE_OFF, CameraMetadata.DISTORTION_CORRECTION_MODE_FAST});
        }
        shadowOf(c).set(CameraCharacteristics.LENS_RADIAL_DISTORTION, KAPPA);
    }

    @Test
    public void theCamerasLensReachesTheIntrinsics() {
        CameraCharacteristics c = ShadowCameraCharacteristics.newCameraCharacteristics();
        geometry(c);
        lens(c, LENS);
        CameraReport report = CameraSource.geometry(c);
        assertEquals(Build.VERSION.SDK_INT, report.sdk());
        assertArrayEquals(new int[] {0, 0, 3000, 3000}, report.active());
        assertArrayEquals(CALIBRATION, report.calibration(), 0f);
        IntrinsicsEstimate e = IntrinsicsEstimate.of(report, 600, 600);
        CameraIntrinsics k = e.intrinsics();
        assertNull(e.problem());
        assertEquals(480, k.fx(), 1e-9);
        assertEquals(299.5, k.cx(), 1e-9);
        if (Build.VERSION.SDK_INT >= 28) {
            assertArrayEquals("the API-28 key read", LENS, report.lensDistortion(), 0f);
            assertNull("the deprecated key not read", report.radialDistortion());
            assertEquals(new LensDistortion(LENS[0], LENS[1], LENS[2], LENS[3], LENS[4]), k.distortion());
            assertTrue("the device's correction turned off", e.correctionOff());
            assertEquals(CameraMetadata.DISTORTION_CORRECTION_MODE_OFF, CameraReport.CORRECTION_OFF);
        } else {
            assertNull("the API-28 keys not read", report.lensDistortion());
            assertNull(report.correctionModes());
            assertArrayEquals(KAPPA, report.radialDistortion(), 0f);
            // a = b = 2400 / 1500 = 1.6 and kappa_0 = 1: k1 = kappa_1 1.6^2, p1 = kappa_4 1.6, ...
            LensDistortion d = k.distortion();
            assertEquals(KAPPA[1] * 2.56, d.k1(), 1e-7);
            assertEquals(KAPPA[2] * 2.56 * 2.56, d.k2(), 1e-7);
            assertEquals(KAPPA[4] * 1.6, d.p1(), 1e-9);
            assertEquals(KAPPA[5] * 1.6, d.p2(), 1e-9);
            assertFalse("no control below 28", e.correctionOff());
        }
    }

    @Test
    public void aCameraWithALensOpensWithoutANote() {
        CameraCharacteristics c = app.addBackCamera("0");
        geometry(c);
        lens(c, LENS);
        app.start(true);
        app.surfaceReady();
        app.awaitStatus("the camera opened and tracking started", s -> s.contains("marker: searching"));
        if (Build.VERSION.SDK_INT >= 28) {
            // The repeating request, with DISTORTION_CORRECTION_MODE OFF, set without a problem.
            app.await("the capture running", () -> !app.status().contains("\n"));
        }
        assertFalse(app.status(), app.status().contains("lens distortion not used"));
    }

    @Test
    public void aLensThatCannotBeUsedIsSaidInTheStatusLine() {
        CameraCharacteristics c = app.addBackCamera("0");
        // At 28 and later a NaN in LENS_DISTORTION; below 28 an old key that Brown-Conrady cannot
        // express (a 4:3 array with its centre in the middle: f/R differs in x and y).
        geometry(c, 4000, 3000, new float[] {3200, 3200, 2000, 1500, 0});
        lens(c, new float[] {Float.NaN, 0, 0, 0, 0});
        if (Build.VERSION.SDK_INT < 28) {
            assertTrue(IntrinsicsEstimate.of(CameraSource.geometry(c), 640, 480).problem()
                    .contains("normalised differently in x and y"));
            // The status line's one camera problem is then Robolectric's missing capture session
            // (CameraSourceTest), which replaces this note at 26: the note is checked above.
            return;
        }
        app.start(true);
        app.surfaceReady();
        app.awaitStatus("the note shown", s -> s.contains("lens distortion not used: LENS_DISTORTION is not 5 finite"));
        app.awaitStatus("and tracking runs", s -> s.contains("marker: searching"));
    }
}
