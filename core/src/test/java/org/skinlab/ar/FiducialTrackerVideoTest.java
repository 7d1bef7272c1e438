package org.skinlab.ar;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.skinlab.internal.synthetic.PlacedMarker;
import org.skinlab.internal.synthetic.SceneOptions;
import org.skinlab.internal.synthetic.SyntheticCamera;

/**
 * {@link FiducialTracker#track}'s search near the last markers against {@link FiducialTracker#detect}
 * on the same synthetic frames: the same markers (ids), corners within {@link #CORNER_TOLERANCE}.
 * BoofCV refines each side to the image's gray edge, so where the markers are found does not move
 * their corners; only the local threshold, computed over a different window at a region's border,
 * may change which contour pixels seed the fit (measured: at most 0.03 px apart on a real video).
 */
class FiducialTrackerVideoTest {
    /** Pixels; BoofCV's own corner noise on these frames is 0.05-0.1 px. */
    static final double CORNER_TOLERANCE = 0.05;
    static final double SIZE = 0.08;

    /**
     * Three markers near three corners of the view, the camera drifting: one box around them would
     * cover most of the frame.
     */
    private static List<PlacedMarker> farApart(double s) {
        double dx = 0.03 * Math.sin(2 * Math.PI * s);
        double dy = 0.02 * Math.cos(2 * Math.PI * s);
        double[] r = PlacedMarker.facingCamera(15 * Math.sin(2 * Math.PI * s), 10, 30 * s);
        return List.of(marker(3, r, -0.19 + dx, -0.12 + dy), marker(17, r, 0.19 + dx, -0.12 + dy),
                marker(200, r, 0.19 + dx, 0.12 + dy));
    }

    private static PlacedMarker marker(int id, double[] r, double x, double y) {
        return PlacedMarker.of(MarkerPattern.of(MarkerDictionary.DEFAULT, id), SIZE, r, new double[] {x, y, 0.7});
    }

    /**
     * Tracks {@code frames} and checks every one against the whole-frame search; returns how many
     * were found in the regions.
     */
    private static int compare(CameraIntrinsics k, List<List<PlacedMarker>> frames, int expected) {
        SyntheticCamera camera = new SyntheticCamera(k);
        FiducialTracker video = new FiducialTracker(TrackerConfig.defaults(SIZE), k);
        FiducialTracker still = new FiducialTracker(TrackerConfig.defaults(SIZE), k);
        int inRegion = 0;
        for (int i = 0; i < frames.size(); i++) {
            GrayImage image = camera.render(frames.get(i), options(500 + i));
            List<MarkerDetection> a = sorted(video.track(image));
            inRegion += video.lastFoundInRegion() ? 1 : 0;
            List<MarkerDetection> b = sorted(still.detect(image));
            assertEquals(frames.get(i).size(), b.size(), "frame " + i + ": the whole-frame search");
            assertEquals(ids(b), ids(a), "frame " + i);
            for (int m = 0; m < a.size(); m++) {
                for (int c = 0; c < 8; c++) {
                    double d = Math.abs(a.get(m).corners()[c] - b.get(m).corners()[c]);
                    assertTrue(d <= CORNER_TOLERANCE, "frame " + i + ", marker " + a.get(m).id() + ": corner " + c / 2
                            + " off by " + d + " px");
                }
            }
        }
        assertTrue(expected >= 0, "markers per frame");
        return inRegion;
    }

    /** A camera's blur, noise and falloff; 2x2 samples a pixel keep the rendering quick. */
    private static SceneOptions options(long seed) {
        return new SceneOptions(0.8, 3, 0.3, 0, 2, seed);
    }

    private static List<MarkerDetection> sorted(List<MarkerDetection> found) {
        List<MarkerDetection> s = new ArrayList<>(found);
        s.sort(Comparator.comparingInt(MarkerDetection::id));
        return s;
    }

    private static List<Integer> ids(List<MarkerDetection> found) {
        List<Integer> ids = new ArrayList<>();
        for (MarkerDetection d : found) {
            ids.add(d.id());
        }
        return ids;
    }

    @Test
    void markersFarApartAreEachFoundInTheirOwnRegionAsInTheWholeFrame() {
        CameraIntrinsics k = CameraIntrinsics.fromHorizontalFov(640, 480, 60);
        int n = 24;
        List<List<PlacedMarker>> frames = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            frames.add(farApart(i / (double) n));
        }
        // The three markers span about 500 x 330 px of the 640 x 480 frame: one box around them
        // (more than half the frame) would send every frame to the whole-frame search.
        int inRegion = compare(k, frames, 3);
        // The first frame and every FULL_FRAME_EVERY-th search the whole frame on purpose.
        assertTrue(inRegion >= n - 1 - n / FiducialTracker.FULL_FRAME_EVERY, "found in the regions: " + inRegion);
    }

    @Test
    void throughADistortedLensTheRegionsGiveTheWholeFrameCorners() {
        // A wide phone lens's barrel distortion (k1 = -0.25: 6% at the frame's corner): a region
        // searched with the lens of the frame's corner instead of its own bends the sides by
        // tenths of a pixel.
        CameraIntrinsics k = CameraIntrinsics.fromHorizontalFov(640, 480, 70)
                .withDistortion(new LensDistortion(-0.25, 0.08, 0, 0.002, -0.001));
        int n = 12;
        List<List<PlacedMarker>> frames = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            frames.add(farApart(i / (double) n));
        }
        int inRegion = compare(k, frames, 3);
        assertTrue(inRegion >= n - 1 - n / FiducialTracker.FULL_FRAME_EVERY, "found in the regions: " + inRegion);
    }

    @Test
    void aMarkerThatLeavesIsLookedForInTheWholeFrameOnceThenNoMore() {
        CameraIntrinsics k = CameraIntrinsics.fromHorizontalFov(640, 480, 60);
        SyntheticCamera camera = new SyntheticCamera(k);
        FiducialTracker video = new FiducialTracker(TrackerConfig.defaults(SIZE), k);
        List<PlacedMarker> three = farApart(0);
        List<PlacedMarker> two = three.subList(0, 2);
        video.track(camera.render(three, options(1)));
        assertEquals(3, video.track(camera.render(three, options(2))).size());
        assertTrue(video.lastFoundInRegion());
        // Marker 200 is gone: its region comes back empty, so this frame is searched whole.
        assertEquals(List.of(3, 17), ids(sorted(video.track(camera.render(two, options(3))))));
        assertFalse(video.lastFoundInRegion());
        // From then on only the two markers left are looked for, in their regions.
        assertEquals(List.of(3, 17), ids(sorted(video.track(camera.render(two, options(4))))));
        assertTrue(video.lastFoundInRegion());
    }
}
