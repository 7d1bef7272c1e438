package org.skinlab.ar;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import boofcv.alg.distort.brown.LensDistortionBrown;
import boofcv.struct.distort.Point2Transform2_F64;
import georegression.struct.point.Point2D_F64;
import org.junit.jupiter.api.Test;

/**
 * The lens model against BoofCV's implementation of the same formulas (an independent reference),
 * and its inverse against itself.
 */
class LensDistortionTest {
    /** A strong webcam barrel lens with decentring, and a phone's mild pincushion. */
    static final LensDistortion WEBCAM = new LensDistortion(-0.32, 0.12, -0.02, 0.0012, -0.0008);
    static final LensDistortion PHONE = new LensDistortion(0.08, -0.21, 0.15, -0.0004, 0.0003);

    @Test
    void distortAgreesWithBoofCvsBrownModelWithin1e9Pixels() {
        for (LensDistortion d : new LensDistortion[] {WEBCAM, PHONE}) {
            CameraIntrinsics k = new CameraIntrinsics(640, 480, 520, 515, 318.2, 241.7, d);
            Point2Transform2_F64 boof = new LensDistortionBrown(BoofCameras.toBoof(k)).distort_F64(true, true);
            Random random = new Random(7);
            double[] ours = new double[2];
            Point2D_F64 theirs = new Point2D_F64();
            for (int i = 0; i < 2000; i++) {
                // Undistorted pixels over the image; BoofCV's are ours plus half a pixel.
                double u = random.nextDouble() * 640 - 0.5;
                double v = random.nextDouble() * 480 - 0.5;
                k.toPixel((u - k.cx()) / k.fx(), (v - k.cy()) / k.fy(), 1, ours);
                boof.compute(u + 0.5, v + 0.5, theirs);
                assertEquals(theirs.x - 0.5, ours[0], 1e-9, d + " at " + u + ", " + v);
                assertEquals(theirs.y - 0.5, ours[1], 1e-9, d + " at " + u + ", " + v);
            }
        }
    }

    @Test
    void undistortInvertsDistortOverTheImageWithin1e10() {
        for (LensDistortion d : new LensDistortion[] {WEBCAM, PHONE, LensDistortion.NONE}) {
            CameraIntrinsics k = new CameraIntrinsics(640, 480, 520, 515, 318.2, 241.7, d);
            double[] ideal = new double[2];
            double[] back = new double[2];
            for (int v = -1; v <= 480; v += 7) {
                for (int u = -1; u <= 640; u += 7) {
                    assertTrue(k.toNormalized(u, v, ideal), d + " at pixel " + u + ", " + v);
                    k.toPixel(ideal[0], ideal[1], 1, back);
                    assertEquals(u, back[0], 1e-10);
                    assertEquals(v, back[1], 1e-10);
                }
            }
        }
    }

    @Test
    void beyondTheFoldOfABarrelLensUndistortRefuses() {
        // x (1 - 0.5 x^2) peaks at x = 0.816 (x_d = 0.544): a distorted 0.6 has no ideal point.
        LensDistortion d = new LensDistortion(-0.5, 0, 0, 0, 0);
        double[] out = new double[2];
        assertFalse(d.undistort(0.6, 0, out));
        assertTrue(d.undistort(0.5, 0, out));
        assertEquals(0.5, out[0] * (1 - 0.5 * out[0] * out[0]), 1e-12);
        // Far past the fold Newton can converge on the other branch: for k1 = -0.6 the point
        // (-1.008, -0.756) (r_d = 1.26; the fold is at r_d = 0.497) is the exact image of a point
        // at r = 1.7 on the opposite side, where 1 - 0.6 r^2 < 0 and det > 0 again. Not an inverse.
        assertFalse(new LensDistortion(-0.6, 0, 0, 0, 0).undistort(-1.008, -0.756, out));
    }

    @Test
    void badTermsAndAMissingLensAreRefused() {
        assertThrows(IllegalArgumentException.class, () -> new LensDistortion(Double.NaN, 0, 0, 0, 0));
        assertThrows(IllegalArgumentException.class, () -> new CameraIntrinsics(640, 480, 500, 500, 320, 240, null));
    }

    @Test
    void scalingKeepsTheLensAndBoofCvsModelRoundTrips() {
        CameraIntrinsics k = new CameraIntrinsics(1280, 960, 1040, 1030, 637.4, 483.9, WEBCAM);
        assertEquals(WEBCAM, k.scaledTo(640, 480).distortion());
        CameraIntrinsics back = BoofCameras.fromBoof(BoofCameras.toBoof(k));
        assertEquals(k, back);
    }
}
