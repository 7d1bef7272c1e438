package org.skinlab.android.logic;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.ByteBuffer;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;

import org.junit.jupiter.api.Test;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.ar.ArPose;
import org.skinlab.ar.GrayImage;
import org.skinlab.ar.MarkerScene;
import org.skinlab.ar.TrackingState;
import org.skinlab.simulation.AnimationConfig;
import org.skinlab.skinning.JointPalette;
import org.skinlab.skinning.SkinningMethod;

/**
 * What the Activity delegates to, on the JVM: buttons, permission flow, Y plane, palette, catalog
 * (the intrinsics: IntrinsicsEstimateTest).
 */
class AndroidLogicTest {
    @Test
    void everyButtonDoesItsAnimationConfigFunction() {
        AnimationConfig config = new AnimationConfig();
        AtomicInteger next = new AtomicInteger();
        double[] told = new double[1];
        MarkerSize marker = new MarkerSize(m -> told[0] = m);
        FakeMeasuring measuring = new FakeMeasuring();
        MixerControl mixer = new MixerControl(() -> new MarkerScene(0.1));
        List<AppActions.Action> actions = AppActions.of(config, next::incrementAndGet, mixer, marker, measuring);
        assertEquals(List.of("mesh-updates", "animation", "follow-camera", "method", "interpolation", "slower", "faster",
                "next-mesh", "cross-fade", "root-motion", "marker-size", "measure", "save-results"),
                actions.stream().map(AppActions.Action::id).toList());
        assertEquals("Marker 100 mm", actions.get(10).label().get(), "docs/marker's default");
        actions.get(10).run().run();
        assertEquals(0.15, told[0], 1e-12);
        assertEquals("Marker 150 mm", actions.get(10).label().get());
        for (int i = 1; i < MarkerSize.SIZES_MM.length; i++) {
            actions.get(10).run().run();
        }
        assertEquals(100, marker.millimetres(), 0, "round the sizes back to 100 mm");
        AppActions.Action mesh = actions.get(0);
        assertEquals("Stop mesh", mesh.label().get());
        mesh.run().run();
        assertFalse(config.isMeshUpdatesRunning());
        assertEquals("Start mesh", mesh.label().get());
        actions.get(1).run().run();
        assertFalse(config.isAnimationRunning());
        actions.get(2).run().run();
        assertTrue(config.isFollowCamera());
        assertEquals("Follow: on", actions.get(2).label().get());
        assertEquals("LBS", actions.get(3).label().get());
        actions.get(3).run().run();
        assertEquals(SkinningMethod.DQS, config.method());
        assertEquals("DQS", actions.get(3).label().get());
        RotationInterpolation before = config.interpolation();
        actions.get(4).run().run();
        assertTrue(config.interpolation() != before);
        actions.get(6).run().run();
        assertEquals(AnimationConfig.SPEED_STEP, config.speed(), 1e-12);
        actions.get(5).run().run();
        actions.get(5).run().run();
        assertEquals(1 / AnimationConfig.SPEED_STEP, config.speed(), 1e-12);
        actions.get(7).run().run();
        assertEquals(1, next.get());
        assertEquals("Cross-fade", actions.get(8).label().get(), "no model yet");
        assertFalse(actions.get(8).enabled().getAsBoolean());
        assertEquals("Root motion: off", actions.get(9).label().get());
        actions.get(9).run().run();
        assertEquals("Root motion: on", actions.get(9).label().get(), "kept for the models to come");
        assertEquals("Measure", actions.get(11).label().get());
        actions.get(11).run().run();
        assertEquals("Stop measuring", actions.get(11).label().get(), "a second tap stops it");
        actions.get(11).run().run();
        assertEquals("Measure", actions.get(11).label().get());
        assertEquals("Save results", actions.get(12).label().get());
        actions.get(12).run().run();
        assertEquals(1, measuring.saves);
    }

    /** A measurement that runs between two taps. */
    private static final class FakeMeasuring implements AppActions.Measuring {
        boolean running;
        int saves;

        @Override
        public boolean running() {
            return running;
        }

        @Override
        public void toggle() {
            running = !running;
        }

        @Override
        public void saveCopy() {
            saves++;
        }
    }

    @Test
    void aRefusedPermissionExplainsAndRetriesNeverOpensTheCamera() {
        PermissionFlow flow = new PermissionFlow();
        assertTrue(flow.onResume(false), "ask at first");
        assertFalse(flow.cameraAllowed());
        assertFalse(flow.onResult(PermissionFlow.Answer.DENIED, true));
        assertEquals(PermissionFlow.Screen.EXPLAIN_AND_RETRY, flow.screen());
        assertFalse(flow.onResume(false), "back from the background: no dialog storm, the explanation stays");
        assertTrue(flow.onRetry());
        flow.onResult(PermissionFlow.Answer.DENIED, false);
        assertEquals(PermissionFlow.Screen.EXPLAIN_SETTINGS, flow.screen());
        assertFalse(flow.onRetry(), "Android will not show the dialog again: settings");
        assertFalse(flow.cameraAllowed());
        assertFalse(flow.onResume(true), "allowed in settings meanwhile");
        assertTrue(flow.cameraAllowed());
    }

    @Test
    void aPendingRequestIsNotRepeatedAndACancelIsAskedAgainOnce() {
        PermissionFlow flow = new PermissionFlow();
        assertTrue(flow.onResume(false));
        assertFalse(flow.onResume(false), "the dialog pauses us: resuming under it asks nothing");
        assertTrue(flow.onResult(PermissionFlow.Answer.CANCELLED, true), "a cancelled request is asked again");
        assertEquals(PermissionFlow.Screen.ASKING, flow.screen(), "not taken as a refusal");
        assertFalse(flow.onResult(PermissionFlow.Answer.CANCELLED, true), "but only once");
        assertEquals(PermissionFlow.Screen.EXPLAIN_AND_RETRY, flow.screen(), "then the user may ask");
        assertTrue(flow.onRetry());
        assertFalse(flow.onResult(PermissionFlow.Answer.GRANTED, false));
        assertTrue(flow.cameraAllowed());
    }

    @Test
    void whatIsHeldDecidesTheAnswer() {
        assertEquals(PermissionFlow.Answer.GRANTED, PermissionFlow.Answer.of(new int[0], true),
                "cancelled, but granted meanwhile");
        assertEquals(PermissionFlow.Answer.CANCELLED, PermissionFlow.Answer.of(new int[0], false));
        assertEquals(PermissionFlow.Answer.DENIED, PermissionFlow.Answer.of(new int[] {-1}, false));
        assertEquals(PermissionFlow.Answer.DENIED, PermissionFlow.Answer.of(new int[] {0}, false),
                "a grant the system does not hold opens nothing");
    }

    @Test
    void thePermissionFlowSurvivesTheActivityBeingRecreated() {
        PermissionFlow flow = new PermissionFlow();
        flow.onResume(false);
        flow.onResult(PermissionFlow.Answer.CANCELLED, true);
        PermissionFlow restored = PermissionFlow.restore(flow.savedState());
        assertEquals(flow.savedState(), restored.savedState());
        assertFalse(restored.onResume(false), "the request still pending is not made twice");
        assertFalse(restored.onResult(PermissionFlow.Answer.CANCELLED, true), "the one retry was used");
        assertEquals(PermissionFlow.Screen.ASKING, PermissionFlow.restore("NONSENSE,x").screen(), "a strange state: anew");
        assertEquals(PermissionFlow.Screen.ASKING, PermissionFlow.restore(null).screen());
    }

    @Test
    void theStreamsShareOneAspectNearTheTrackersSize() {
        int[][] yuv = {{4032, 3024}, {1920, 1080}, {1280, 720}, {800, 600}, {640, 480}, {320, 240}};
        int[][] preview = {{4032, 3024}, {1920, 1440}, {1920, 1080}, {1280, 960}, {1280, 720}};
        assertEquals(new StreamSizes(640, 480, 1920, 1440, true), StreamSizes.choose(yuv, preview),
                "640x480 tracked, the largest 4:3 preview within the budget");
        // A camera whose previews are all 16:9: the tracking follows them rather than stretching the picture.
        StreamSizes wide = StreamSizes.choose(yuv, new int[][] {{1920, 1080}, {1280, 720}});
        assertEquals(new StreamSizes(1280, 720, 1920, 1080, true), wide);
        assertEquals("", wide.problem());
        // No common aspect at all: the nearest, and the status line says why the model may drift.
        StreamSizes odd = StreamSizes.choose(new int[][] {{640, 480}}, new int[][] {{1920, 1080}, {1280, 1024}});
        assertFalse(odd.sameAspect());
        assertEquals(1280, odd.previewWidth(), "5:4 is nearer to 4:3 than 16:9 is");
        assertTrue(odd.problem().contains("640x480"));
        // 1920x1088 is how some drivers list 16:9.
        assertTrue(StreamSizes.choose(new int[][] {{1920, 1088}}, new int[][] {{1920, 1080}}).sameAspect());
        assertThrows(IllegalArgumentException.class, () -> StreamSizes.choose(new int[0][], preview));
    }

    @Test
    void autofocusOnlyInAModeTheCameraLists() {
        assertEquals(FocusMode.CONTINUOUS_VIDEO, FocusMode.choose(new int[] {0, 1, 4, 3}));
        assertEquals(FocusMode.CONTINUOUS_PICTURE, FocusMode.choose(new int[] {0, 1, 4}));
        assertEquals(-1, FocusMode.choose(new int[] {0}), "fixed focus: none set");
        assertEquals(-1, FocusMode.choose(null));
    }

    @Test
    void theMethodButtonOffersEveryMethodAndTheChoiceOfEachIsSaved() {
        AnimationConfig config = new AnimationConfig();
        AppActions.Action method = AppActions.of(config, () -> { }, new MixerControl(() -> new MarkerScene(0.1)),
                new MarkerSize(m -> { }),
                new FakeMeasuring()).get(3);
        java.util.Set<SkinningMethod> offered = java.util.EnumSet.noneOf(SkinningMethod.class);
        for (SkinningMethod m : SkinningMethod.values()) {
            assertEquals(m, config.method());
            assertEquals(m.key().toUpperCase(java.util.Locale.ROOT), method.label().get());
            offered.add(m);
            SavedChoices saved = new SavedChoices(config.settings(), null, 100, null);
            assertEquals(m, SavedChoices.fromMap(saved.toMap(), AnimationConfig.Settings.DEFAULT).settings().method(),
                    m.key() + " is restored");
            method.run().run();
        }
        assertEquals(java.util.EnumSet.allOf(SkinningMethod.class), offered);
        assertEquals(SkinningMethod.LBS, config.method(), "round again");
    }

    @Test
    void theUsersChoicesRoundTripAndBadEntriesKeepTheDefaults() {
        AnimationConfig.Settings chosen = AnimationConfig.Settings.DEFAULT.withMethod(SkinningMethod.COR)
                .withSpeed(-2).withInterpolation(RotationInterpolation.LERP).withFollowCamera(true)
                .withAnimationRunning(false);
        SavedChoices saved = new SavedChoices(chosen, "tentacle-wave.dae", 150, "CAMERA,false,false");
        assertEquals(saved, SavedChoices.fromMap(saved.toMap(), AnimationConfig.Settings.DEFAULT));
        assertTrue(SavedChoices.KEYS.containsAll(saved.toMap().keySet()));
        SavedChoices bad = SavedChoices.fromMap(java.util.Map.of("speed", "NaN", "method", "xyz", "interpolation",
                "?", "followCamera", "maybe", "markerMillimetres", "big"), AnimationConfig.Settings.DEFAULT);
        assertEquals(AnimationConfig.Settings.DEFAULT, bad.settings());
        assertTrue(Double.isNaN(bad.markerMillimetres()));
        assertEquals(null, bad.model());
        MarkerSize marker = new MarkerSize(m -> {
            throw new AssertionError("a restored size is not a change");
        });
        assertTrue(marker.select(150));
        assertEquals("Marker 150 mm", marker.label());
        assertFalse(marker.select(Double.NaN));
        ModelCatalog catalog = new ModelCatalog(new String[] {"humanoid-walk.dae", "tentacle-wave.dae"});
        assertTrue(catalog.select("tentacle-wave.dae"));
        assertFalse(catalog.select(null));
        assertFalse(catalog.select("gone.dae"));
        assertEquals("tentacle-wave.dae", catalog.current());
    }

    /**
     * The preview's orientation, checked against an image turned by hand: a small "sensor image"
     * with a distinct value per pixel is turned clockwise by the sensor orientation pixel by pixel
     * (what Camera2's buffer transform shows); reading that upright image at sensorToNatural of a
     * sensor pixel's texture coordinates must give the sensor pixel.
     */
    @Test
    void thePreviewIsReadAtTheSensorsOwnPixels() {
        int w = 4;
        int h = 3;
        for (int orientation = 0; orientation < 360; orientation += 90) {
            // The upright image: the sensor's turned clockwise by `orientation`, row 0 at the top.
            int[][] upright = new int[h][w];
            for (int y = 0; y < h; y++) {
                for (int x = 0; x < w; x++) {
                    upright[y][x] = 10 * y + x;
                }
            }
            for (int turn = 0; turn < orientation / 90; turn++) {
                int rows = upright.length;
                int cols = upright[0].length;
                int[][] turned = new int[cols][rows];
                for (int y = 0; y < rows; y++) {
                    for (int x = 0; x < cols; x++) {
                        turned[x][rows - 1 - y] = upright[y][x]; // one clockwise quarter turn
                    }
                }
                upright = turned;
            }
            float[] m = PreviewOrientation.sensorToNatural(orientation, new float[16]);
            for (int y = 0; y < h; y++) {
                for (int x = 0; x < w; x++) {
                    float u = (x + 0.5f) / w;
                    float v = 1 - (y + 0.5f) / h; // v up
                    float un = m[0] * u + m[4] * v + m[12];
                    float vn = m[1] * u + m[5] * v + m[13];
                    int rows = upright.length;
                    int cols = upright[0].length;
                    int col = (int) Math.floor(un * cols);
                    int row = (int) Math.floor((1 - vn) * rows);
                    assertEquals(10 * y + x, upright[row][col], "orientation " + orientation + ", sensor pixel " + x + "," + y);
                }
            }
        }
        assertThrows(IllegalArgumentException.class, () -> PreviewOrientation.sensorToNatural(45, new float[16]));
    }

    @Test
    void theYPlaneIsCopiedWithItsStrides() {
        int w = 5, h = 3, rowStride = 12;
        ByteBuffer plane = ByteBuffer.allocate(rowStride * (h - 1) + 2 * (w - 1) + 1);
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                plane.put(y * rowStride + 2 * x, (byte) (10 * y + x));
            }
        }
        GrayImage g = new YPlane().copy(plane, rowStride, 2, w, h);
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                assertEquals(10 * y + x, g.get(x, y));
            }
        }
        ByteBuffer packed = ByteBuffer.allocate(rowStride * h);
        packed.put(rowStride + 4, (byte) 200);
        assertEquals(200, new YPlane().copy(packed, rowStride, 1, w, h).get(4, 1));
        assertThrows(IllegalArgumentException.class, () -> new YPlane().copy(packed, 3, 1, w, h));
    }

    @Test
    void theCatalogStartsWithTheDefaultCharacterAndCycles() {
        ModelCatalog c = new ModelCatalog(new String[] {"tentacle-wave.dae", "notes.txt", "humanoid-walk.dae"});
        assertEquals(List.of("humanoid-walk.dae", "tentacle-wave.dae"), c.names());
        assertEquals("tentacle-wave.dae", c.next());
        assertEquals("humanoid-walk.dae", c.next());
        assertThrows(IllegalArgumentException.class, () -> new ModelCatalog(new String[] {"a.txt"}));
    }

    @Test
    void theStatusLineSaysWhatIsGoingOn() {
        ArPose holding = new ArPose(TrackingState.HOLDING, ArPose.NONE.rotation(), ArPose.NONE.translation(), 3, 0,
                2.54, 1, 1);
        String s = StatusLine.format(29.6, holding, AnimationConfig.Settings.DEFAULT.withMethod(SkinningMethod.COR)
                .withFollowCamera(true), "clip walk -> run | root motion", "humanoid-moves.glb");
        assertEquals("30 fps | marker: holding id 3 (2.5 ms) | COR SLERP x1.00 | follow | clip walk -> run | root motion"
                + " | humanoid-moves.glb", s, "the clips before the model, which stays last");
        ArPose two = new ArPose(TrackingState.TRACKING, ArPose.NONE.rotation(), ArPose.NONE.translation(), 0, 2, 1.0,
                2, 2);
        assertEquals("30 fps | marker: tracking id 0, 2 in view (1.0 ms) | LBS SLERP x1.00 | a.dae",
                StatusLine.format(30, two, AnimationConfig.Settings.DEFAULT, "", "a.dae"), "the followed id and the count");
        ArPose otherInView = new ArPose(TrackingState.SEARCHING, ArPose.NONE.rotation(), ArPose.NONE.translation(),
                -1, 1, 1.0, 3, 3);
        assertEquals("30 fps | marker: searching, 1 in view (1.0 ms) | LBS SLERP x1.00 | a.dae",
                StatusLine.format(30, otherInView, AnimationConfig.Settings.DEFAULT, "", "a.dae"),
                "a marker of another id than the target: in view, not followed");
        assertEquals("0 fps | marker: waiting for the camera | LBS SLERP x1.00 | a.dae",
                StatusLine.format(0, null, AnimationConfig.Settings.DEFAULT, "", "a.dae"));
        assertEquals("line\ncamera gone\nmodel broken", StatusLine.withProblems("line", "", null, "camera gone",
                "model broken"), "each problem on its own line, empty ones left out");
        FpsCounter fps = new FpsCounter();
        for (int i = 0; i <= 60; i++) {
            fps.frame(i * 16_666_667L);
        }
        assertEquals(60, fps.fps(), 0.5);
    }
}
