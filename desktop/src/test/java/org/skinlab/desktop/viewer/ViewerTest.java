package org.skinlab.desktop.viewer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.function.BooleanSupplier;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.skinlab.desktop.render.DrawSettings;
import org.skinlab.simulation.AnimationConfig;
import org.skinlab.skinning.SkinningMethod;

/** The viewer's actions and loading, without a window. */
class ViewerTest {
    private static Viewer viewer(boolean threaded) {
        return new Viewer(ModelLibrary.find(), new AnimationConfig(), threaded);
    }

    private static void await(Viewer v, BooleanSupplier done) throws InterruptedException {
        long deadline = System.nanoTime() + 60_000_000_000L;
        while (!done.getAsBoolean()) {
            assertTrue(System.nanoTime() < deadline, "timed out; status: " + v.statusMessage());
            Thread.sleep(10);
            v.update();
        }
    }

    @Test
    void nextMeshShowsTheNextBundledModel() throws Exception {
        try (Viewer v = viewer(true)) {
            assertNull(v.current());
            v.open(v.library().defaultModel());
            await(v, () -> v.current() != null);
            assertEquals(ModelLibrary.DEFAULT_ASSET, v.current().displayName());
            assertTrue(v.current().mesh().isRunning(), "the simulation runs once shown");
            LoadedModel first = v.current();
            v.perform(ViewerAction.NEXT_MESH);
            await(v, () -> v.current() != first);
            assertEquals(v.library().models().get(1), v.current().file());
            assertFalse(first.mesh().isRunning(), "the previous simulation stops");
            v.perform(ViewerAction.PREVIOUS_MESH);
            await(v, () -> v.current().file().equals(first.file()));
        }
    }

    @Test
    void quickPressesShowTheNewestRequest() throws Exception {
        try (Viewer v = viewer(false)) {
            v.openAndWait(v.library().defaultModel());
            for (int i = 0; i < 3; i++) {
                v.perform(ViewerAction.NEXT_MESH);
            }
            await(v, () -> !v.loading() && v.current().file().equals(v.library().models().get(3)));
            Thread.sleep(200);
            v.update();
            assertEquals(v.library().models().get(3), v.current().file(), "the third press's model stays");
        }
    }

    @Test
    void aBadFileKeepsThePreviousModelAndSaysWhy(@TempDir Path dir) throws Exception {
        Path bad = dir.resolve("broken.dae");
        Files.writeString(bad, "<COLLADA><library_geometries><geometry id=\"g\"><mesh>");
        try (Viewer v = viewer(false)) {
            assertEquals(null, v.openAndWait(v.library().defaultModel()));
            LoadedModel shown = v.current();
            String error = v.openAndWait(bad);
            assertNotNull(error);
            assertTrue(error.contains("broken.dae"), error);
            assertSame(shown, v.current());
            assertEquals(error, v.statusMessage());
            String missing = v.openAndWait(dir.resolve("nothing.dae"));
            assertTrue(missing.contains("nothing.dae") && missing.contains("not found"), missing);
            assertTrue(v.openAndWait(dir).contains("directory"));
            assertSame(shown, v.current());
        }
    }

    @Test
    void everyActionDoesSomethingOrIsTheWindows() throws Exception {
        try (Viewer v = viewer(false)) {
            v.openAndWait(v.library().defaultModel());
            AnimationConfig c = v.config();
            v.perform(ViewerAction.NEXT_METHOD);
            assertEquals(SkinningMethod.DQS, c.method());
            boolean running = c.isAnimationRunning();
            v.perform(ViewerAction.TOGGLE_ANIMATION);
            assertEquals(!running, c.isAnimationRunning());
            double speed = c.speed();
            v.perform(ViewerAction.FASTER);
            assertTrue(c.speed() > speed);
            boolean cpu = c.isCpuSkinning();
            v.perform(ViewerAction.TOGGLE_GPU_SKINNING);
            assertEquals(!cpu, c.isCpuSkinning());
            v.perform(ViewerAction.MORE_INSTANCES);
            assertEquals(2, v.settings().instances());
            v.perform(ViewerAction.VIEW_DIFFERENCE);
            assertEquals(DrawSettings.View.DIFFERENCE, v.settings().drawView());
            v.perform(ViewerAction.VIEW_CHECKER);
            assertEquals(DrawSettings.View.CHECKER, v.settings().drawView());
            v.perform(ViewerAction.TOGGLE_BIND_POSE);
            assertTrue(c.isBindPose());
            v.perform(ViewerAction.PREVIOUS_JOINT);
            assertEquals(v.jointCount() - 1, v.settings().selectedJoint());
            double before = v.current().mesh().playbackTime();
            v.perform(ViewerAction.STEP_FORWARD);
            assertEquals(before + Viewer.STEP_SECONDS, v.current().mesh().playbackTime(), 1e-9);
            v.perform(ViewerAction.TOGGLE_FOLLOW_CAMERA);
            assertTrue(c.isFollowCamera(), "follow the camera (AR mode)");
            v.perform(ViewerAction.QUIT);
            assertTrue(v.quitRequested());
            for (ViewerAction a : ViewerAction.values()) {
                if (a != ViewerAction.NEXT_MESH && a != ViewerAction.PREVIOUS_MESH && a != ViewerAction.NEXT_CLIP) {
                    v.perform(a);
                }
            }
        }
    }

    /**
     * The auto difference scale is the clip's largest LBS-DQS difference, measured off the
     * window's thread: on the twist cylinder 0.25 (1 - cos 86 deg) over its diagonal 2.1213
     * (LargestDifferenceTest has the derivation) at the clip's end; a fixed scale is what it says,
     * and a model shown later is measured anew.
     */
    @Test
    void theAutoDifferenceScaleIsTheClipsLargest() throws Exception {
        try (Viewer v = viewer(false)) {
            assertEquals(DrawSettings.DIFFERENCE_FULL, v.differenceFull(), 1e-9, "the default");
            v.settings().setDifferenceScale(DifferenceScale.percent(8));
            assertNull(v.openAndWait(asset("cylinders/cylinder-twist-high.dae")));
            assertEquals(0.08, v.differenceFull(), 1e-12);
            assertNull(v.clipLargestDifference(), "a fixed scale measures nothing");
            v.settings().setDifferenceScale(DifferenceScale.AUTO);
            v.awaitDifferenceScale(60);
            double byHand = 0.25 * (1 - Math.cos(Math.toRadians(86))) / Math.sqrt(0.5 * 0.5 + 0.5 * 0.5 + 2 * 2);
            assertEquals(byHand, v.differenceFull(), 0.01 * byHand);
            assertEquals(4f, v.clipLargestDifference().clipTime(), 1e-6f);
            // The walk: another model, another measure (its methods differ far less than the twist's).
            assertNull(v.openAndWait(asset("characters/humanoid-walk.dae")));
            v.awaitDifferenceScale(60);
            assertTrue(v.differenceFull() > 0 && v.differenceFull() < 0.5 * byHand, "walk: " + v.differenceFull());
        }
    }

    @Test
    void differenceScalesParseAsTheCommandLineWritesThem() {
        assertEquals(DifferenceScale.AUTO, DifferenceScale.parse(" Auto "));
        assertEquals(0.125, DifferenceScale.parse("12.5").fraction(), 1e-12);
        assertEquals(0.02, DifferenceScale.parse("2 %").fraction(), 1e-12);
        for (String bad : new String[] {"", "five", "0", "-3", "101", "NaN"}) {
            IllegalArgumentException e = org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class,
                    () -> DifferenceScale.parse(bad), bad);
            assertTrue(e.getMessage().contains("'" + bad + "'"), e.getMessage());
        }
        assertEquals(0.3, DifferenceScale.AUTO.fractionFor(0.3), 0);
        assertEquals(DrawSettings.DIFFERENCE_FULL, DifferenceScale.AUTO.fractionFor(Double.NaN), 1e-9,
                "while measuring: the default");
        assertEquals(DrawSettings.DIFFERENCE_FULL, DifferenceScale.AUTO.fractionFor(0), 1e-9, "methods that agree");
        assertEquals(0.08, DifferenceScale.percent(8).fractionFor(0.3), 1e-12);
    }

    private static Path asset(String relative) {
        return Path.of(System.getProperty("skinlab.root", "..")).resolve("assets").resolve(relative);
    }

    private static void assertNull(Object o, String message) {
        assertEquals(null, o, message);
    }

    private static void assertNull(Object o) {
        assertEquals(null, o);
    }
}
