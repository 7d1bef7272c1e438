package org.skinlab.ar;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.skinlab.internal.synthetic.PlacedMarker;
import org.skinlab.internal.synthetic.SceneOptions;
import org.skinlab.internal.synthetic.SyntheticCamera;

/**
 * The tracker's conventions on sharp synthetic frames ({@link SyntheticCamera}: an ideal pinhole
 * camera, 4x4 rays per pixel, no blur or noise): corners TL, TR, BR, BL at the projections of the
 * black square's corners, pixel centres at integers, pose {@code X_cam = R X_marker + t}.
 *
 * <p>Tolerances: on a clean frame of a 10 cm marker 130-250 px wide, BoofCV's sub-pixel corner
 * refinement (line fits along each edge) lands within about 0.05 px; a half-pixel convention error
 * would show as 0.5 px, so corners are held to 0.1 px face-on. Tilted and turned, edges cross the
 * pixel grid at every angle and the foreshortened ones are shorter, so the line fits carry more
 * of the area-averaged pixels' error: 0.2 px (seen: up to 0.11). Pose: 0.1 px of corner error at fx = 600
 * and 0.3-0.5 m moves a corner's ray by 0.1/600 rad, about 0.08 mm, and the marker's normal by
 * about 0.1/150 rad = 0.04 degrees; held to 1 mm and 0.2 degrees.
 */
class FiducialTrackerTest {
    static final CameraIntrinsics CAMERA = new CameraIntrinsics(640, 480, 600, 600, 319.5, 239.5);
    static final double SIZE = 0.10;

    private static PlacedMarker marker(int id, double[] r, double... t) {
        return PlacedMarker.of(MarkerPattern.of(MarkerDictionary.DEFAULT, id), SIZE, r, t);
    }

    @Test
    void aFaceOnMarkerHasTheFacingRotationAndItsCornersWhereTheyProject() {
        SyntheticCamera camera = new SyntheticCamera(CAMERA);
        PlacedMarker m = marker(7, PlacedMarker.facingCamera(0, 0, 0), 0.02, -0.01, 0.4);
        GrayImage frame = camera.render(List.of(m), SceneOptions.clean(1));
        List<MarkerDetection> found = new FiducialTracker(TrackerConfig.defaults(SIZE), CAMERA).detect(frame);
        assertEquals(1, found.size(), "one marker");
        MarkerDetection d = found.get(0);
        assertEquals(7, d.id());
        double[] truth = camera.projectCorners(m);
        for (int i = 0; i < 8; i++) {
            assertEquals(truth[i], d.corners()[i], 0.1, "corner coordinate " + i);
        }
        double[] r = d.rotation();
        double[] facing = {1, 0, 0, 0, -1, 0, 0, 0, -1};
        for (int i = 0; i < 9; i++) {
            assertEquals(facing[i], r[i], 0.004, "R entry " + i);
        }
        assertEquals(0.02, d.translation()[0], 1e-3);
        assertEquals(-0.01, d.translation()[1], 1e-3);
        assertEquals(0.4, d.translation()[2], 1e-3);
        assertTrue(d.reprojectionError() < 0.1, "reprojection error " + d.reprojectionError());
    }

    @Test
    void tiltedAndTurnedMarkersGiveTheirPose() {
        SyntheticCamera camera = new SyntheticCamera(CAMERA);
        double[][] poses = {{30, 0, 0, 0.05, 0.03, 0.45}, {0, 45, 20, -0.06, 0.02, 0.5}, {15, -10, 60, 0, 0, 0.3},
            {-35, 20, -120, 0.03, -0.04, 0.4}};
        FiducialTracker tracker = new FiducialTracker(TrackerConfig.defaults(SIZE), CAMERA);
        for (double[] p : poses) {
            PlacedMarker m = marker(3, PlacedMarker.facingCamera(p[0], p[1], p[2]), p[3], p[4], p[5]);
            List<MarkerDetection> found = tracker.detect(camera.render(List.of(m), SceneOptions.clean(2)));
            assertEquals(1, found.size());
            MarkerDetection d = found.get(0);
            double[] truth = camera.projectCorners(m);
            for (int i = 0; i < 8; i++) {
                assertEquals(truth[i], d.corners()[i], 0.2, "corner coordinate " + i + " of pose " + p[0] + "," + p[1]);
            }
            assertTrue(PoseError.rotationDegrees(m.rotation(), d.rotation()) < 0.2, "rotation error "
                    + PoseError.rotationDegrees(m.rotation(), d.rotation()));
            assertTrue(PoseError.distance(m.translation(), d.translation()) < 1e-3, "position error");
        }
    }

    @Test
    void paddedRowsGiveTheSamePoses() {
        // An Android Y plane: rows longer than the image, the last row without its padding.
        SyntheticCamera camera = new SyntheticCamera(CAMERA);
        PlacedMarker m = marker(5, PlacedMarker.facingCamera(25, -15, 40), 0.02, -0.01, 0.5);
        GrayImage packed = camera.render(List.of(m), SceneOptions.camera(4));
        int stride = CAMERA.width() + 64;
        byte[] padded = new byte[stride * (CAMERA.height() - 1) + CAMERA.width()];
        java.util.Arrays.fill(padded, (byte) 0x5a);
        for (int y = 0; y < CAMERA.height(); y++) {
            System.arraycopy(packed.pixels(), y * packed.rowStride(), padded, y * stride, CAMERA.width());
        }
        GrayImage strided = new GrayImage(CAMERA.width(), CAMERA.height(), stride, padded);
        for (boolean video : new boolean[] {false, true}) {
            FiducialTracker a = new FiducialTracker(TrackerConfig.defaults(SIZE), CAMERA);
            FiducialTracker b = new FiducialTracker(TrackerConfig.defaults(SIZE), CAMERA);
            List<MarkerDetection> expected = video ? a.track(packed) : a.detect(packed);
            List<MarkerDetection> found = video ? b.track(strided) : b.detect(strided);
            assertEquals(1, expected.size());
            assertEquals(1, found.size());
            for (int i = 0; i < 8; i++) {
                assertEquals(expected.get(0).corners()[i], found.get(0).corners()[i], 0, "corner coordinate " + i);
            }
            for (int i = 0; i < 3; i++) {
                assertEquals(expected.get(0).translation()[i], found.get(0).translation()[i], 0);
            }
        }
    }

    @Test
    void theTargetIdFiltersOtherMarkers() {
        SyntheticCamera camera = new SyntheticCamera(CAMERA);
        GrayImage frame = camera.render(List.of(marker(1, PlacedMarker.facingCamera(0, 0, 0), -0.1, 0, 0.5),
                marker(2, PlacedMarker.facingCamera(0, 0, 0), 0.1, 0, 0.5)), SceneOptions.clean(3));
        assertEquals(2, new FiducialTracker(TrackerConfig.defaults(SIZE), CAMERA).detect(frame).size());
        List<MarkerDetection> only = new FiducialTracker(TrackerConfig.defaults(SIZE).withTargetId(2), CAMERA)
                .detect(frame);
        assertEquals(1, only.size());
        assertEquals(2, only.get(0).id());
        assertTrue(only.get(0).translation()[0] > 0, "the right-hand marker");
    }

    @Test
    void anImageOfAnotherSizeThanTheCameraIsRefused() {
        FiducialTracker tracker = new FiducialTracker(TrackerConfig.defaults(SIZE), CAMERA);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> tracker.detect(GrayImage.blank(320, 240)));
        assertTrue(e.getMessage().contains("320x240") && e.getMessage().contains("640x480"), e.getMessage());
    }

    @Test
    void configsOutsideTheDictionaryAreRefused() {
        assertThrows(IllegalArgumentException.class, () -> TrackerConfig.defaults(SIZE).withTargetId(250));
        assertThrows(IllegalArgumentException.class, () -> TrackerConfig.defaults(SIZE).withMaxBitErrors(6));
        assertThrows(IllegalArgumentException.class, () -> TrackerConfig.defaults(0));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> MarkerDictionary.byName("aruco_99"));
        assertTrue(e.getMessage().contains("aruco_mip_36h12"), e.getMessage());
        assertEquals(MarkerDictionary.APRILTAG_36H11, MarkerDictionary.byName("APRILTAG_36h11"));
    }
}
