package org.skinlab.android.logic;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.skinlab.internal.bench.DeviceResults;
import org.skinlab.internal.bench.DeviceResultsJson;
import org.skinlab.internal.bench.DeviceResultsReader;
import org.skinlab.internal.bench.FrameTimes;
import org.skinlab.internal.bench.Rounds;
import org.skinlab.simulation.Frame;
import org.skinlab.simulation.SkeletalAnimatedMesh;
import org.skinlab.skinning.SkinningMethod;

/**
 * The app's measurement on the JVM, on the models the APK bundles: every model and method timed in
 * at least five rounds, the GPU part drawn by a stand-in GL thread (which steps and reads each
 * copy, as the app's does, and finishes frames as fast as it can), the file written where asked
 * and read back by the desktop's reader; without a GL thread the GPU part says why; a model that
 * does not load is named; a cancel stops it without a file. Times are not judged.
 */
class DeviceMeasurementTest {
    private static final Path BUNDLED = Path.of(System.getProperty("skinlab.root", "."), "android", "build", "apk",
            "assets", "models");
    /** Short runs: this checks what runs, not how fast. */
    private static final MeasureProtocol SHORT = new MeasureProtocol("test",
            new FrameTimes.Protocol(Rounds.MIN_RUNS, 0.01, 0.002, 0.003), 0.01, Rounds.MIN_RUNS, 1);
    private static final DeviceResults.App APP = new DeviceResults.App("org.skinlab.android", "0.1.0", 1);
    private static final DeviceResults.Device DEVICE = new DeviceResults.Device("maker", "model", "device", "14", 34,
            List.of("x86_64"), new DeviceResults.Cpu(2, null, null), 60);

    @TempDir
    Path folder;

    private static List<String> bundled() {
        String[] names = BUNDLED.toFile().list();
        assertTrue(names != null, "no " + BUNDLED + ": run through gradle, whose appAssets task makes it");
        return new ModelCatalog(names).names();
    }

    private static ModelLoader.Source source() {
        return name -> name.equals("broken.dae") ? new ByteArrayInputStream("<COLLADA".getBytes(StandardCharsets.UTF_8))
                : Files.newInputStream(BUNDLED.resolve(name));
    }

    private static void await(DeviceMeasurement m) throws InterruptedException {
        long end = System.nanoTime() + TimeUnit.MINUTES.toNanos(3);
        while (m.running()) {
            assertTrue(System.nanoTime() < end, "still measuring: " + m.status());
            Thread.sleep(20);
        }
    }

    @Test
    void everyBundledModelAndMethodIsTimedAndTheCopiesDrawn() throws Exception {
        List<String> models = bundled();
        DrawnCopies copies = new DrawnCopies(10);
        GlStandIn gl = new GlStandIn(copies);
        gl.start();
        DeviceMeasurement m = new DeviceMeasurement(source(), models, SHORT, copies, APP, () -> DEVICE,
                folder.toFile());
        try {
            m.start();
            await(m);
        } finally {
            gl.interrupt();
            gl.join();
        }
        File file = folder.resolve(DeviceResultsJson.FILE_NAME).toFile();
        assertEquals(file, m.written());
        assertTrue(m.status().startsWith("measure (test): wrote " + file.getPath()), m.status());
        DeviceResults r = DeviceResultsReader.read(Files.readAllBytes(file.toPath()), file.getName());
        assertEquals(APP, r.app());
        assertEquals(DEVICE.model(), r.device().model());
        assertEquals("stand-in renderer", r.gpu().renderer());
        assertEquals(models, r.models().stream().map(DeviceResults.ModelTimes::file).toList());
        assertTrue(r.skipped().isEmpty(), r.skipped().toString());
        for (DeviceResults.ModelTimes t : r.models()) {
            assertEquals(Arrays.asList(SkinningMethod.values()), t.methods().stream().map(FrameTimes.Result::method)
                    .toList());
            assertTrue(t.shape().joints() > 0 && t.shape().renderVertices() > 0, t.toString());
            for (FrameTimes.Result method : t.methods()) {
                assertEquals("scalar", method.kernel(), "core's scalar kernels, what ART runs");
                assertEquals(Rounds.MIN_RUNS, method.micros().count());
            }
        }
        DeviceResults.Drawn drawn = r.drawn();
        assertTrue(drawn.measured(), drawn.unavailable());
        assertEquals(models.get(0), drawn.file());
        assertEquals(MeasureProtocol.COPIES.size() * MeasureProtocol.DRAWN_METHODS.size(), drawn.points().size());
        List<Integer> copiesDrawn = new ArrayList<>();
        for (DeviceResults.DrawnPoint p : drawn.points()) {
            assertEquals(Rounds.MIN_RUNS, p.fps().count());
            assertTrue(p.frames() >= 5 * Rounds.MIN_RUNS, p.toString());
            copiesDrawn.add(p.copies());
        }
        assertEquals(gl.largest, 12, "the GL thread was handed 12 copies");
        assertTrue(copiesDrawn.containsAll(MeasureProtocol.COPIES));
        assertFalse(copies.measuring(), "the GL thread may release the copies' buffers");
    }

    @Test
    void withoutAGlThreadTheGpuPartSaysWhyAndABrokenModelIsNamed() throws Exception {
        List<String> models = List.of("broken.dae", bundled().get(0));
        DeviceMeasurement m = new DeviceMeasurement(source(), models, SHORT, new DrawnCopies(0.3), APP, () -> DEVICE,
                folder.toFile());
        m.start();
        await(m);
        DeviceResults r = DeviceResultsReader.read(Files.readAllBytes(m.written().toPath()), "file");
        assertEquals(1, r.models().size());
        assertEquals(1, r.skipped().size());
        assertEquals("broken.dae", r.skipped().get(0).file());
        assertTrue(r.skipped().get(0).reason().startsWith("broken.dae"), r.skipped().get(0).reason());
        assertFalse(r.drawn().measured());
        assertTrue(r.drawn().unavailable().contains("drew no frame"), r.drawn().unavailable());
        assertFalse(r.gpu().known());
    }

    @Test
    void aCancelStopsItWithoutAFile() throws Exception {
        MeasureProtocol slow = new MeasureProtocol("slow", new FrameTimes.Protocol(Rounds.MIN_RUNS, 0.5, 0.5, 0.5),
                0.5, Rounds.MIN_RUNS, 1);
        DeviceMeasurement m = new DeviceMeasurement(source(), bundled(), slow, new DrawnCopies(10), APP,
                () -> DEVICE, folder.toFile());
        m.start();
        long end = System.nanoTime() + TimeUnit.MINUTES.toNanos(1);
        while (!m.status().contains("CPU")) {
            assertTrue(System.nanoTime() < end, m.status());
            Thread.sleep(5);
        }
        assertTrue(m.status().matches("measure \\(slow\\): CPU, .*, about \\d+ (s|min) left"), m.status());
        m.cancel();
        long cancelled = System.nanoTime();
        await(m);
        assertTrue((System.nanoTime() - cancelled) / 1e9 < 5, "stopped after the run in progress");
        assertEquals("measure (slow): stopped", m.status());
        assertNull(m.written());
        assertFalse(Files.exists(folder.resolve(DeviceResultsJson.FILE_NAME)));
    }

    /** A GL thread that draws each request's copies as fast as it can: steps each and reads its frame. */
    private static final class GlStandIn extends Thread {
        private final DrawnCopies copies;
        volatile int largest;

        GlStandIn(DrawnCopies copies) {
            super("gl-stand-in");
            this.copies = copies;
            copies.glStrings("stand-in renderer", "stand-in vendor", "OpenGL ES 3.0 stand-in");
        }

        @Override
        public void run() {
            while (!isInterrupted()) {
                DrawnCopies.Request r = copies.current();
                if (r == null) {
                    Thread.onSpinWait();
                    continue;
                }
                for (SkeletalAnimatedMesh m : r.copies()) {
                    m.step(1.0 / 60);
                    try (Frame f = m.acquire()) {
                        assertFalse(f.hasSkinnedMesh(), "palette only: the GPU skins");
                    }
                }
                largest = Math.max(largest, r.copies().size());
                copies.drawn(r, System.nanoTime());
            }
        }
    }
}
