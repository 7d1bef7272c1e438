package org.skinlab.android.logic;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.CompletableFuture;

import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;
import org.skinlab.ar.MarkerScene;
import org.skinlab.importer.ModelImporter;
import org.skinlab.mixer.Mixer;
import org.skinlab.model.Model;
import org.skinlab.simulation.Frame;
import org.skinlab.simulation.SkeletalAnimatedMesh;

/**
 * The cross-fade and root motion buttons' logic on a mesh stepped by hand, as the simulation
 * thread steps it: what the status line and the labels say, what the mixer then does.
 */
class MixerControlTest {
    private static final Path CHARACTERS = Path.of(System.getProperty("skinlab.root", "."), "assets", "characters");
    private static final double STEP = 1 / 60.0;

    @Test
    void crossFadesThroughTheClipsInOrderAndSaysSo() throws Exception {
        MixerControl control = new MixerControl(() -> new MarkerScene(0.1));
        try (SkeletalAnimatedMesh mesh = SkeletalAnimatedMesh.of(read("humanoid-moves.glb"))) {
            control.show(mesh);
            assertEquals("", control.status(), "nothing known before the first step");
            assertFalse(control.canCrossFade());
            steps(mesh, 2);
            assertTrue(control.canCrossFade());
            assertEquals("clip idle", control.status(), "the mesh plays the model's first clip");
            assertEquals("Fade to lean", control.crossFadeLabel(), "the next in the model's order");

            CompletableFuture<Void> fade = control.crossFadeToNext();
            steps(mesh, 2);
            assertTrue(fade.isDone() && !fade.isCompletedExceptionally());
            assertEquals("clip idle -> lean", control.status());
            assertEquals("Fade to run", control.crossFadeLabel(), "a tap during the fade goes on from its target");
            assertTrue(holds(mesh, m -> m.base().isFading()));
            steps(mesh, (int) Math.ceil(MixerControl.FADE_SECONDS / STEP) + 2);
            assertFalse(holds(mesh, m -> m.base().isFading()));
            assertEquals("clip lean", control.status());

            for (String next : new String[] {"run", "walk", "wave", "idle"}) {
                control.crossFadeToNext();
                steps(mesh, 2);
                assertTrue(control.status().endsWith("-> " + next), control.status());
                steps(mesh, 40);
                assertEquals("clip " + next, control.status(), "round again after the last");
                assertEquals(1.0, ask(mesh, m -> m.base().clipWeights().get(next)), 1e-9, "the fade has ended");
            }
        }
    }

    @Test
    void aModelWithOneClipHasNothingToFadeTo() throws Exception {
        MixerControl control = new MixerControl(() -> new MarkerScene(0.1));
        try (SkeletalAnimatedMesh mesh = SkeletalAnimatedMesh.of(read("humanoid-walk.dae"))) {
            control.show(mesh);
            steps(mesh, 2);
            assertFalse(control.canCrossFade());
            assertEquals("Cross-fade: 1 clip", control.crossFadeLabel());
            control.crossFadeToNext();
            steps(mesh, 2);
            assertFalse(holds(mesh, m -> m.base().isFading()), "a tap there changes nothing");
            assertEquals("clip default", control.status());
        }
    }

    /**
     * Root motion on: the walk moves the frames' placement, the steering keeps it on the marker
     * for a minute; off: the placement is back at the centre. A model shown later gets the switch.
     */
    @Test
    void rootMotionWalksTheFramesAndTheSteeringKeepsThemOnTheMarker() throws Exception {
        MixerControl control = new MixerControl(() -> new MarkerScene(0.1));
        Model model = read("humanoid-moves.glb");
        try (SkeletalAnimatedMesh mesh = SkeletalAnimatedMesh.of(model)) {
            control.show(mesh);
            steps(mesh, 2);
            control.crossFadeToNext(); // lean
            control.crossFadeToNext(); // run: the second tap goes on from the first's target
            control.crossFadeToNext(); // walk
            steps(mesh, 60);
            assertEquals("clip walk", control.status());
            CompletableFuture<Void> on = control.toggleRootMotion();
            steps(mesh, 1);
            assertTrue(on.isDone());
            assertEquals("clip walk | root motion", control.status());
            assertTrue(holds(mesh, m -> m.rootMotion("walk") && m.rootMotion("idle")), "every clip");

            double radius = 0.4 * 1.805 / 1.5; // MarkerSteeringTest: the humanoid's circle
            double farthest = 0;
            Vector3f first = placed(mesh);
            for (int second = 0; second < 60; second++) {
                steps(mesh, 60);
                Vector3f p = placed(mesh);
                farthest = Math.max(farthest, Math.hypot(p.x, p.z));
            }
            assertTrue(first.length() < 0.05, "from the centre: " + first);
            assertTrue(farthest > 0.3, "the frames walk: " + farthest);
            assertTrue(farthest <= radius + 0.002, "on the marker: " + farthest + " within " + radius);

            control.toggleRootMotion();
            steps(mesh, 2);
            assertEquals(0, placed(mesh).length(), 1e-6, "back at the centre");
            assertEquals("clip walk", control.status());
        }
        control.toggleRootMotion();
        try (SkeletalAnimatedMesh next = SkeletalAnimatedMesh.of(model)) {
            control.show(next);
            steps(next, 2);
            assertTrue(holds(next, m -> m.rootMotion("walk")), "the switch holds for the next model");
        }
    }

    /** Where the latest frame's placement puts the model's origin (in the model's space, Y up here). */
    private static Vector3f placed(SkeletalAnimatedMesh mesh) {
        try (Frame f = mesh.acquire()) {
            return f.placement(new Matrix4f()).transformPosition(new Vector3f());
        }
    }

    private static boolean holds(SkeletalAnimatedMesh mesh, java.util.function.Predicate<Mixer> question) {
        return ask(mesh, question::test);
    }

    /** The answer to {@code question}, asked on the simulation's next (zero-length) step. */
    private static <T> T ask(SkeletalAnimatedMesh mesh, java.util.function.Function<Mixer, T> question) {
        Object[] answer = new Object[1];
        CompletableFuture<Void> asked = mesh.direct(m -> answer[0] = question.apply(m));
        mesh.step(0);
        assertTrue(asked.isDone());
        @SuppressWarnings("unchecked")
        T t = (T) answer[0];
        return t;
    }

    private static void steps(SkeletalAnimatedMesh mesh, int n) {
        for (int i = 0; i < n; i++) {
            mesh.step(STEP);
        }
    }

    private static Model read(String name) throws Exception {
        try (InputStream in = Files.newInputStream(CHARACTERS.resolve(name))) {
            return ModelImporter.read(in, name, null);
        }
    }
}
