package org.skinlab.android.logic;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.skinlab.simulation.AnimationConfig;
import org.skinlab.simulation.SkeletalAnimatedMesh;

/** The app's model loader: loads in order on its thread, skips what the user skipped, reports failures. */
class ModelLoaderTest {
    private static final Path MODELS = Path.of(System.getProperty("skinlab.root", "."), "assets", "characters");
    /** The APK's models/ folder as the appAssets task lays it out (gradle makes it before these tests). */
    private static final Path BUNDLED = Path.of(System.getProperty("skinlab.root", "."), "android", "build", "apk",
            "assets", "models");

    /**
     * The humanoid's .glb as the APK bundles it, listed by the app's catalog and loaded by its
     * loader from a source that opens "models/NAME" as the Activity's does: the walk animates.
     */
    @Test
    void loadsTheBundledGlbLikeAnyModel() throws Exception {
        String[] bundled = BUNDLED.toFile().list();
        assertTrue(bundled != null, "no " + BUNDLED + ": run through gradle, whose appAssets task makes it");
        ModelCatalog catalog = new ModelCatalog(bundled);
        assertTrue(catalog.names().contains("humanoid-walk.dae"), catalog.names()::toString);
        assertTrue(catalog.select("humanoid-walk.glb"), "the APK bundles the .glb: " + catalog.names());
        List<SkeletalAnimatedMesh> loaded = new CopyOnWriteArrayList<>();
        ModelLoader.Source source = name -> Files.newInputStream(BUNDLED.resolve(name));
        try (ModelLoader loader = new ModelLoader(source, new AnimationConfig(), new ImageIoDecoder(),
                l -> loaded.add(l.mesh()))) {
            loader.load(catalog.current());
            assertEquals("", awaitIdle(loader).problem());
        }
        assertEquals(1, loaded.size());
        try (SkeletalAnimatedMesh mesh = loaded.get(0)) {
            assertEquals(1, mesh.geometries().size());
            assertTrue(mesh.geometries().get(0).isSkinned());
            assertEquals(19, mesh.geometries().get(0).jointCount(), "the humanoid's joints");
            assertEquals(1.0, mesh.clip().duration(), 1e-6, "the walk cycle");
            float[] atStart = skinningAt(mesh, 0.0);
            float[] passing = skinningAt(mesh, 0.25);
            double moved = 0;
            for (int i = 0; i < atStart.length; i++) {
                moved = Math.max(moved, Math.abs(atStart[i] - passing[i]));
            }
            assertTrue(moved > 0.05, "the joints move between 0 s and 0.25 s: " + moved);
        }
    }

    private static float[] skinningAt(SkeletalAnimatedMesh mesh, double seconds) {
        mesh.seek(seconds);
        mesh.step(0.0);
        try (org.skinlab.simulation.Frame f = mesh.acquire()) {
            return f.palette(0).matrices().clone();
        }
    }

    @Test
    void loadsOneModelAfterAnotherSkippingTheOnesNoLongerWanted() throws Exception {
        CountDownLatch firstOpened = new CountDownLatch(1);
        CountDownLatch goOn = new CountDownLatch(1);
        List<String> opened = new CopyOnWriteArrayList<>();
        List<SkeletalAnimatedMesh> loaded = new CopyOnWriteArrayList<>();
        ModelLoader.Source source = name -> {
            opened.add(name);
            if (opened.size() == 1) {
                firstOpened.countDown();
                await(goOn);
            }
            return Files.newInputStream(MODELS.resolve("humanoid-walk.dae"));
        };
        try (ModelLoader loader = new ModelLoader(source, new AnimationConfig(), new ImageIoDecoder(),
                l -> loaded.add(l.mesh()))) {
            loader.load("first.dae");
            assertTrue(firstOpened.await(30, TimeUnit.SECONDS));
            loader.load("skipped.dae");
            loader.load("last.dae");
            assertTrue(loader.loading());
            goOn.countDown();
            long end = System.currentTimeMillis() + 60_000;
            while (loader.loading() && System.currentTimeMillis() < end) {
                Thread.sleep(10);
            }
            assertFalse(loader.loading());
            assertEquals(List.of("first.dae", "last.dae"), opened, "the one skipped past is not even opened");
            assertEquals(2, loaded.size());
            for (SkeletalAnimatedMesh m : loaded) {
                assertFalse(m.isRunning(), "handed over, not started: the app starts it while resumed");
                m.close();
            }
            assertEquals("", loader.problem());
        }
    }

    @Test
    void aModelThatFailsInAnyWayIsAProblemNamingItAndTheThreadGoesOn() throws Exception {
        List<SkeletalAnimatedMesh> loaded = new CopyOnWriteArrayList<>();
        ModelLoader.Source source = name -> {
            switch (name) {
                case "cut.dae":
                    return new ByteArrayInputStream("<COLLADA><library_geometries>".getBytes(StandardCharsets.UTF_8));
                case "huge.dae":
                    throw new OutOfMemoryError();
                case "gone.dae":
                    throw new IOException("no such asset");
                default:
                    return Files.newInputStream(MODELS.resolve(name));
            }
        };
        try (ModelLoader loader = new ModelLoader(source, new AnimationConfig(), new ImageIoDecoder(),
                l -> loaded.add(l.mesh()))) {
            for (String name : new String[] {"cut.dae", "huge.dae", "gone.dae"}) {
                loader.load(name);
                String problem = awaitIdle(loader).problem();
                assertTrue(problem.startsWith(name) || problem.contains(name), problem);
            }
            assertEquals("huge.dae: OutOfMemoryError", awaitProblem(loader, "huge.dae"));
            loader.load("humanoid-walk.dae");
            assertEquals("", awaitIdle(loader).problem(), "a model that loads clears the problem");
            assertEquals(1, loaded.size());
            loaded.get(0).close();
        }
    }

    private static String awaitProblem(ModelLoader loader, String name) throws InterruptedException {
        loader.load(name);
        return awaitIdle(loader).problem();
    }

    private static ModelLoader awaitIdle(ModelLoader loader) throws InterruptedException {
        long end = System.currentTimeMillis() + 60_000;
        while (loader.loading() && System.currentTimeMillis() < end) {
            Thread.sleep(10);
        }
        assertFalse(loader.loading(), "the loader finished");
        return loader;
    }

    private static void await(CountDownLatch latch) throws IOException {
        try {
            latch.await(30, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            throw new IOException(e);
        }
    }
}
