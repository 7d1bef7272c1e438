package org.skinlab.ar;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicReference;

import org.junit.jupiter.api.Test;
import org.skinlab.internal.synthetic.PlacedMarker;
import org.skinlab.internal.ar.PoseMath;

/** {@link MarkerTracking}'s states and flip rule, and {@link ArSession}'s publication across threads. */
class MarkerTrackingTest {
    private static final long FRAME = 33_333_333L;

    private static MarkerDetection at(int id, double[] r, double... t) {
        return new MarkerDetection(id, new double[8], r, t, 0.1);
    }

    @Test
    void searchingTrackingHoldingLost() {
        MarkerTracking tracking = new MarkerTracking(-1, 500_000_000L);
        assertEquals(TrackingState.SEARCHING, tracking.update(0, List.of()));
        double[] r = PlacedMarker.facingCamera(30, 0, 0);
        assertEquals(TrackingState.TRACKING, tracking.update(FRAME, List.of(at(4, r, 0, 0, 0.5))));
        assertEquals(TrackingState.HOLDING, tracking.update(2 * FRAME, List.of()));
        assertEquals(TrackingState.HOLDING, tracking.update(FRAME + 499_000_000L, List.of()));
        assertEquals(TrackingState.LOST, tracking.update(FRAME + 500_000_000L, List.of()));
        assertTrue(!TrackingState.LOST.showsModel() && TrackingState.HOLDING.showsModel());
        // Found again far away: no smoothing from the old pose.
        tracking.update(40 * FRAME, List.of(at(4, r, 0.3, 0, 1.0)));
        assertEquals(0.3, tracking.translation(new double[3])[0], 0, "the filter restarted");
    }

    @Test
    void theTargetIdOrElseTheNearestMarker() {
        double[] r = PlacedMarker.facingCamera(0, 0, 0);
        List<MarkerDetection> two = List.of(at(1, r, 0, 0, 1.0), at(2, r, 0.1, 0, 0.6));
        MarkerTracking any = new MarkerTracking();
        any.update(0, two);
        assertEquals(0.6, any.translation(new double[3])[2], 0, "the nearer one, id 2");
        MarkerTracking one = new MarkerTracking(1, MarkerTracking.DEFAULT_HOLD_NANOS);
        one.update(0, two);
        assertEquals(1.0, one.translation(new double[3])[2], 0, "id 1");
        assertEquals(TrackingState.SEARCHING, new MarkerTracking(3, 0).update(0, two));
    }

    @Test
    void anyIdKeepsTheMarkerItPickedUntilLostOrReset() {
        double[] r = PlacedMarker.facingCamera(0, 0, 0);
        MarkerTracking any = new MarkerTracking(-1, 2 * FRAME);
        assertEquals(-1, any.followedId(), "none while searching");
        any.update(FRAME, List.of(at(1, r, 0, 0, 0.7), at(2, r, 0.1, 0, 0.8)));
        assertEquals(1, any.followedId());
        any.update(2 * FRAME, List.of(at(1, r, 0, 0, 0.7), at(2, r, 0.1, 0, 0.5)));
        assertEquals(1, any.followedId(), "2 came nearer: still 1");
        assertEquals(0.7, any.translation(new double[3])[2], 1e-9);
        assertEquals(TrackingState.HOLDING, any.update(3 * FRAME, List.of(at(2, r, 0.1, 0, 0.5))));
        assertEquals(1, any.followedId(), "holding 1 while only 2 is in view");
        assertEquals(TrackingState.LOST, any.update(4 * FRAME, List.of(at(2, r, 0.1, 0, 0.5))));
        assertEquals(-1, any.followedId());
        assertEquals(TrackingState.TRACKING,
                any.update(5 * FRAME, List.of(at(1, r, 0, 0, 0.7), at(2, r, 0.1, 0, 0.5))));
        assertEquals(2, any.followedId(), "lost: the nearest anew");
        any.reset();
        any.update(6 * FRAME, List.of(at(1, r, 0, 0, 0.4), at(2, r, 0.1, 0, 0.5)));
        assertEquals(1, any.followedId(), "reset: the nearest anew");
    }

    @Test
    void aOneOrTwoFrameFlipIsIgnoredAPersistentTurnIsTaken() {
        MarkerTracking tracking = new MarkerTracking();
        double[] a = PlacedMarker.facingCamera(8, 0, 0);
        double[] flipped = PlacedMarker.facingCamera(-8 - 40, 0, 0); // the other planar solution's kind of jump
        long t = 0;
        for (int i = 0; i < 10; i++) {
            tracking.update(t += FRAME, List.of(at(0, a, 0, 0, 0.5)));
        }
        double[] out = new double[9];
        for (int i = 0; i < MarkerTracking.FLIP_FRAMES - 1; i++) {
            tracking.update(t += FRAME, List.of(at(0, flipped, 0.01, 0, 0.5)));
            assertTrue(PoseMath.angleDegrees(a, tracking.rotation(out)) < 0.5, "flip " + i + " ignored");
        }
        assertEquals(0.01, tracking.translation(new double[3])[0], 0.008, "the position still follows");
        tracking.update(t += FRAME, List.of(at(0, a, 0, 0, 0.5)));
        for (int i = 0; i < MarkerTracking.FLIP_FRAMES; i++) {
            tracking.update(t += FRAME, List.of(at(0, flipped, 0, 0, 0.5)));
        }
        assertTrue(PoseMath.angleDegrees(flipped, tracking.rotation(out)) < 0.5, "a persistent turn is taken");
    }

    @Test
    void theRendererNeverSeesATornPose() throws Exception {
        // The feeder publishes poses whose translation is (k, k, k) and rotation a turn by k/100
        // degrees; a reader that ever sees parts of two poses fails.
        MarkerTracking tracking = new MarkerTracking(-1, Long.MAX_VALUE);
        List<MarkerDetection> one = new ArrayList<>(1);
        double[] k = new double[1];
        ArSession session = new ArSession(image -> {
            one.clear();
            one.add(at(0, PlacedMarker.facingCamera(0, 0, k[0] / 100), k[0], k[0], k[0]));
            return one;
        }, tracking);
        GrayImage image = GrayImage.blank(4, 4);
        AtomicReference<String> torn = new AtomicReference<>();
        CountDownLatch done = new CountDownLatch(1);
        Thread reader = new Thread(() -> {
            while (done.getCount() > 0) {
                ArPose p = session.current();
                if (p.frameNumber() == 0) {
                    continue; // ArPose.NONE, before the first frame
                }
                double[] tr = p.translation();
                if (tr[0] != tr[1] || tr[1] != tr[2]) {
                    torn.set("translation " + java.util.Arrays.toString(tr));
                }
            }
        });
        reader.start();
        Thread feeder = new Thread(() -> {
            for (int i = 0; i < 20000; i++) {
                k[0] = i;
                session.onCameraFrame(image, i * FRAME);
            }
            done.countDown();
        });
        feeder.start();
        feeder.join(60_000);
        reader.join(60_000);
        assertEquals(null, torn.get());
        assertEquals(20000, session.current().frameNumber());
        // A second feeder is refused.
        AtomicReference<Throwable> refused = new AtomicReference<>();
        Thread other = new Thread(() -> {
            try {
                session.onCameraFrame(image, 0);
            } catch (IllegalStateException e) {
                refused.set(e);
            }
        });
        other.start();
        other.join();
        assertTrue(refused.get() != null, "a second thread's frame is refused");
    }
}
