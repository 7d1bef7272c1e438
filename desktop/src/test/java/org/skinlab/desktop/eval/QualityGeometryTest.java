package org.skinlab.desktop.eval;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.joml.Matrix4f;
import org.junit.jupiter.api.Test;
import org.skinlab.animation.AnimationHelper;

/**
 * The quality section's geometry against hand-derived cases: the joint angle unwrapped over a
 * whole turn, and the phone camera's pixels.
 */
class QualityGeometryTest {
    /** Two joints' skinning matrices (12 floats each): the parent at rest, the joint turned about {@code axis}. */
    private static float[] pose(double degrees, float ax, float ay, float az) {
        float[] m = new float[24];
        AnimationHelper.putRowMajor3x4(new Matrix4f(), m, 0);
        AnimationHelper.putRowMajor3x4(new Matrix4f().rotate((float) Math.toRadians(degrees), ax, ay, az), m, 12);
        return m;
    }

    @Test
    void aWholeTurnUnwrapsToAWholeTurn() {
        // A twist about z in steps of 7 degrees from 0 to 357, then 360: the rotation's own angle
        // goes up to 180 and back down, the unwrapped angle on to 360.
        JointAngle angle = new JointAngle(0, 1);
        double unwrapped = 0;
        double signed = 0;
        for (int step = 0; step <= 52; step++) {
            double degrees = Math.min(360, 7 * step);
            double s = angle.signedDegrees(pose(degrees, 0, 0, 1));
            unwrapped = step == 0 ? s : JointAngle.continued(unwrapped, signed, s);
            signed = s;
            assertEquals(degrees, unwrapped, 1e-3, "at " + degrees);
        }
        assertEquals(90, JointAngle.degrees(pose(270, 0, 0, 1), 0, 1), 1e-3, "the rotation's own size");
    }

    @Test
    void turningTheOtherWayIsNegative() {
        JointAngle angle = new JointAngle(0, 1);
        assertEquals(30, angle.signedDegrees(pose(30, 1, 0, 0)), 1e-4, "the first axis is the reference");
        assertEquals(-20, angle.signedDegrees(pose(-20, 1, 0, 0)), 1e-4);
        assertEquals(-20, angle.signedDegrees(pose(20, -1, 0, 0)), 1e-4);
    }

    @Test
    void thePhoneSeesAShiftAsTheFocalLengthTimesItOverTheDepth() {
        // A model 2 m tall scaled to 0.2 m: a shift of 0.01 m in the model is 0.001 m on the marker;
        // at the centre, 0.5 m from the camera, that is f * 0.001 / 0.5 pixels, f = 960 / tan(32.5).
        PhoneView view = new PhoneView(new double[] {-1, 0, -1}, new double[] {1, 2, 1});
        double f = 960 / Math.tan(Math.toRadians(32.5));
        assertEquals(f, PhoneView.FOCAL_PIXELS, 1e-9);
        double[] a = new double[2];
        double[] b = new double[2];
        view.project(new float[] {0, 1, 0}, 1, 0, a);
        view.project(new float[] {0.01f, 1, 0}, 1, 0, b);
        assertEquals(960, a[0], 1e-9, "the centre is the image's centre");
        assertEquals(540, a[1], 1e-9);
        assertEquals(f * 0.001 / 0.5, PhoneView.largestShift(a, b, 1), 1e-3);
        // Seen from the side (a quarter turn round), a shift along x is along the line of sight: 0
        // pixels sideways, a change of depth only, which moves the centre point not at all.
        view.project(new float[] {0, 1, 0}, 1, PhoneView.VIEWS / 4, a);
        view.project(new float[] {0.01f, 1, 0}, 1, PhoneView.VIEWS / 4, b);
        assertTrue(PhoneView.largestShift(a, b, 1) < 1e-6);
    }
}
