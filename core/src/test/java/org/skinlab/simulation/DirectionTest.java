package org.skinlab.simulation;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;

import org.joml.Matrix4f;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.skinlab.importer.ModelImporter;
import org.skinlab.mixer.FadeCurve;
import org.skinlab.model.Model;
import org.skinlab.testing.TestPaths;

/**
 * Directing a playing mesh from other threads: changes run on the simulation thread between
 * steps, a bad change fails only its own future, and frames follow the blend.
 */
@Timeout(60)
class DirectionTest {
    private static Model model() throws Exception {
        return ModelImporter.read(TestPaths.root().resolve("core/src/test/resources/gltf/anim-interpolation.gltf"));
    }

    @Test
    void changesRunOnTheSimulationThreadAndABadOneFailsOnlyItsFuture() throws Exception {
        try (SkeletalAnimatedMesh mesh = SkeletalAnimatedMesh.of(model())) {
            mesh.setStepRate(500);
            assertTrue(mesh.start());
            String[] thread = new String[1];
            CompletableFuture<Void> fade = mesh.direct(m -> {
                thread[0] = Thread.currentThread().getName();
                m.base().crossFade("clip-b", 0.05, FadeCurve.SMOOTH, false);
            });
            fade.get(10, TimeUnit.SECONDS);
            assertNotEquals(Thread.currentThread().getName(), thread[0]);
            CompletableFuture<Void> bad = mesh.direct(m -> m.base().play("no such clip"));
            ExecutionException e = assertThrows(ExecutionException.class, () -> bad.get(10, TimeUnit.SECONDS));
            assertTrue(e.getCause().getMessage().contains("\"no such clip\""), e.getCause().getMessage());
            // The simulation goes on, and the fade has finished.
            long steps = mesh.stepCount();
            Thread.sleep(200);
            assertTrue(mesh.stepCount() > steps);
            Object[] weights = new Object[1];
            mesh.direct(m -> weights[0] = m.base().clipWeights()).get(10, TimeUnit.SECONDS);
            assertEquals(Map.of("clip-b", 1.0), weights[0]);
            mesh.throwIfFailed();
        }
    }

    @Test
    void byHandAStepAppliesTheChangesGivenSoFar() throws Exception {
        Model model = model();
        try (SkeletalAnimatedMesh mesh = new SkeletalAnimatedMesh(model, model.clips().get(0), new AnimationConfig())) {
            float[] before;
            try (Frame f = mesh.acquire()) {
                before = f.palette(0).matrices().clone();
            }
            CompletableFuture<Void> change = mesh.direct(m -> {
                m.base().setClipWeights(Map.of("clip-a", 0.5, "clip-b", 0.5));
                m.setRootMotion("clip-a", true);
            });
            assertFalse(change.isDone());
            mesh.step(0.25);
            assertTrue(change.isDone());
            try (Frame f = mesh.acquire()) {
                assertFalse(java.util.Arrays.equals(before, f.palette(0).matrices()));
                Matrix4f placement = f.placement(new Matrix4f());
                assertTrue(placement.isFinite());
            }
        }
    }

    @Test
    void theDirectorRunsEveryStepAfterTheQueuedChangesPublishedOrNot() throws Exception {
        Model model = model();
        AnimationConfig config = new AnimationConfig();
        try (SkeletalAnimatedMesh mesh = new SkeletalAnimatedMesh(model, model.clips().get(0), config)) {
            java.util.List<String> seen = new java.util.ArrayList<>();
            mesh.setDirector(m -> seen.add(m.base().heaviestClip()));
            mesh.direct(m -> m.base().play("clip-b"));
            mesh.step(0.1);
            config.stopMeshUpdates();
            long published = mesh.latestSequence();
            mesh.step(0.1);
            assertEquals(published, mesh.latestSequence(), "no frame with mesh updates stopped");
            mesh.setDirector(null);
            mesh.step(0.1);
            assertEquals(java.util.List.of("clip-b", "clip-b"), seen);
        }
    }
}
