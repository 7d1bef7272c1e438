package org.skinlab.ar;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.skinlab.internal.synthetic.PlacedMarker;
import org.skinlab.internal.synthetic.SceneOptions;
import org.skinlab.internal.synthetic.SyntheticCamera;

/**
 * Several markers of different ids in one synthetic camera (the 640x480, 60-degree camera of
 * {@link TrackerEvaluationTest}, typical phone blur and noise): the tracker reports each with its
 * own pose, and the session's model stays on the marker it follows ({@link MarkerTracking}) while
 * another one comes nearer.
 *
 * <p>Tolerances: at 0.59-0.8 m a 10 cm marker is 70-95 px wide; the evaluation's bounds at 1 m
 * (2 mm, 0.4 degrees median) scale with the distance, so a detection within 1 cm and 3 degrees of
 * its truth holds every frame with room for the planar ambiguity's worst face-on frames. The
 * session's model is filtered ({@link PoseFilter}), which lags a marker that moves 3 cm a frame by
 * up to about a frame's motion (23 mm measured): 3 cm. What the checks must tell apart is the markers,
 * 30 cm and 30 degrees apart.
 */
class SeveralMarkersTest {
    private static final CameraIntrinsics K = TrackerEvaluationTest.K;
    private static final double SIZE = TrackerEvaluationTest.SIZE;
    private static final long FRAME = 33_333_333L;
    private static final SyntheticCamera CAMERA = new SyntheticCamera(K);

    private static PlacedMarker marker(int id, double x, double y, double z, double tiltDegrees) {
        return PlacedMarker.of(MarkerPattern.of(MarkerDictionary.DEFAULT, id), SIZE,
                PlacedMarker.facingCamera(tiltDegrees, 0, 10 * id), new double[] {x, y, z});
    }

    private static GrayImage frame(long seed, PlacedMarker... markers) {
        // A phone's blur, noise and falloff (SceneOptions.camera) at 2x2 rays a pixel, not 4x4: a
        // quarter of the rendering time, and still edges the detector fits to a tenth of a pixel.
        return CAMERA.render(List.of(markers), new SceneOptions(0.8, 3, 0.3, 0, 2, seed));
    }

    private static void assertPose(PlacedMarker truth, double[] rotation, double[] translation, double toleranceMetres,
            String what) {
        double metres = PoseError.distance(translation, truth.translation());
        double degrees = PoseError.rotationDegrees(rotation, truth.rotation());
        assertTrue(metres < toleranceMetres, what + ": position off by " + metres + " m");
        assertTrue(degrees < 3, what + ": rotation off by " + degrees + " degrees");
    }

    @Test
    void eachOfThreeMarkersIsReportedWithItsPose() {
        PlacedMarker[] truth = {marker(3, -0.2, 0, 0.7, 20), marker(17, 0, 0.05, 0.6, -25),
            marker(42, 0.18, -0.05, 0.8, 30)};
        FiducialTracker tracker = new FiducialTracker(TrackerConfig.defaults(SIZE), K);
        for (int f = 0; f < 3; f++) {
            GrayImage image = frame(f, truth);
            // detect: the whole frame; track: one region around each of the last frame's markers,
            // which must find all three there (no fall back to the whole frame).
            List<MarkerDetection> found = f == 0 ? tracker.detect(image) : tracker.track(image);
            assertEquals(f > 0, tracker.lastFoundInRegion(), "frame " + f + " searched in the markers' regions");
            assertEquals(3, found.size(), "frame " + f + ": " + found);
            for (PlacedMarker m : truth) {
                int id = m.pattern().id();
                MarkerDetection d = found.stream().filter(x -> x.id() == id).findFirst().orElseThrow(
                        () -> new AssertionError("id " + id + " not reported: " + found));
                assertPose(m, d.rotation(), d.translation(), 0.01, "frame " + f + ", id " + id);
            }
        }
    }

    /** Frames in which marker 17 moves from 0.8 m to 0.59 m while marker 3 stays at 0.65 m. */
    private static List<PlacedMarker[]> secondComesNearer() {
        List<PlacedMarker[]> frames = new ArrayList<>();
        for (int f = 0; f < 8; f++) {
            double z = 0.8 - 0.03 * f;
            frames.add(new PlacedMarker[] {marker(3, -0.15, 0, 0.65, 15), marker(17, 0.15, 0, z, -15)});
        }
        return frames;
    }

    /** The session over the frames; asserts the model's id and pose each frame and the count in view. */
    private static long follow(ArSession session, List<PlacedMarker[]> frames, long time, int expectedId) {
        for (PlacedMarker[] markers : frames) {
            time += FRAME;
            ArPose pose = session.onCameraFrame(frame(time, markers), time);
            assertEquals(TrackingState.TRACKING, pose.state(), "at " + time);
            assertEquals(expectedId, pose.markerId(), "the followed id at " + time);
            assertEquals(markers.length, pose.markers(), "all in view reported");
            PlacedMarker followed = markers[0].pattern().id() == expectedId ? markers[0] : markers[1];
            assertPose(followed, pose.rotation(), pose.translation(), 0.03, "the model on id " + expectedId);
        }
        return time;
    }

    @Test
    void anyIdLocksOnToTheFirstNearestAndStaysWhenAnotherComesNearer() {
        ArSession session = ArSession.of(new FiducialTracker(TrackerConfig.defaults(SIZE), K));
        List<PlacedMarker[]> frames = secondComesNearer();
        assertTrue(frames.get(frames.size() - 1)[1].translation()[2] < frames.get(0)[0].translation()[2],
                "the scene: 17 ends nearer than 3");
        long time = follow(session, frames, 0, 3);

        // Marker 3 leaves: the model holds, then is lost; 17, in view all along, is not taken meanwhile.
        PlacedMarker[] only17 = {marker(17, 0.15, 0, 0.59, -15)};
        time += FRAME;
        ArPose held = session.onCameraFrame(frame(time, only17), time);
        assertEquals(TrackingState.HOLDING, held.state());
        assertEquals(3, held.markerId(), "still on 3 while holding");
        assertEquals("holding id 3, 1 in view", held.markerLabel());
        time += MarkerTracking.DEFAULT_HOLD_NANOS;
        ArPose lost = session.onCameraFrame(frame(time, only17), time);
        assertEquals(TrackingState.LOST, lost.state());
        assertEquals(-1, lost.markerId());

        // Lost: the next frame chooses anew, the nearest of those reported. (track() looks near the
        // last frame's marker, 17, first, and finds 3 on its next whole-frame pass.)
        time += FRAME;
        ArPose again = session.onCameraFrame(frame(time, marker(3, -0.15, 0, 0.65, 15), only17[0]), time);
        assertEquals(TrackingState.TRACKING, again.state());
        assertEquals(17, again.markerId(), "after the loss, the nearest: 17");
        assertTrue(again.markerLabel().startsWith("tracking id 17, "), again.markerLabel());
    }

    @Test
    void aTargetIdStaysOnThatMarkerWhateverIsNearer() {
        // The detector reports every id (a tracker with a target id would drop the others before
        // MarkerTracking sees them); the tracking is told to follow 17.
        FiducialTracker tracker = new FiducialTracker(TrackerConfig.defaults(SIZE), K);
        ArSession session = new ArSession(tracker::track, new MarkerTracking(17, MarkerTracking.DEFAULT_HOLD_NANOS));
        // 17 starts farther than 3 (a lock-on to the nearest would take 3) and ends nearer; then
        // it stays on 17 whatever is nearer.
        List<PlacedMarker[]> frames = secondComesNearer();
        List<PlacedMarker[]> swapped = new ArrayList<>();
        for (int i = frames.size() - 1; i >= 0; i--) {
            swapped.add(frames.get(i));
        }
        follow(session, frames, 0, 17);
        follow(session, swapped, 20 * FRAME, 17);
    }
}
