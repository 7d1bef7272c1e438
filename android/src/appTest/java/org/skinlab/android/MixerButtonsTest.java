package org.skinlab.android;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.util.concurrent.TimeUnit;
import java.util.function.Function;

import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.junit.After;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.robolectric.RobolectricTestRunner;
import org.robolectric.annotation.Config;
import org.skinlab.internal.scene.DefaultAsset;
import org.skinlab.mixer.Mixer;
import org.skinlab.simulation.Frame;
import org.skinlab.simulation.SkeletalAnimatedMesh;

/**
 * The mixer's buttons on the real Activity, at minSdk and targetSdk: the cross-fade button greyed
 * out for the default walker (one clip) and fading the five-clip humanoid through its clips, in
 * step, with the status line naming them; the root motion switch walking the frames' placement
 * across the marker and back to its centre when switched off. The mixer is asked on its own
 * (simulation) thread, through {@code direct} futures.
 */
@RunWith(RobolectricTestRunner.class)
@Config(minSdk = 26, shadows = ShadowPermissionRequestState.class)
public class MixerButtonsTest {
    private static final String MOVER = "humanoid-moves.dae";
    private final AppDriver app = new AppDriver();

    @After
    public void finish() {
        app.finish();
    }

    @Test
    public void theCrossFadeButtonFadesToTheNextClipAndTheStatusLineNamesThem() throws Exception {
        app.start(true);
        app.awaitStatus("the default model's clip", s -> s.contains("| clip default | " + DefaultAsset.fileName()));
        assertFalse("one clip: nothing to fade to", app.button("Cross-fade: 1 clip").isEnabled());

        showMover();
        app.awaitStatus("the mover's first clip", s -> s.contains("| clip idle | " + MOVER));
        assertTrue(app.button("Fade to lean").isEnabled());
        app.awaitButton("Fade to lean");
        app.tap("Fade to lean");
        app.awaitStatus("the fade", s -> s.contains("| clip idle -> lean | "));
        assertTrue("fading, in step", ask(m -> m.base().isFading()));
        app.awaitStatus("the fade's end", s -> s.contains("| clip lean | "));
        assertEquals(1.0, ask(m -> m.base().clipWeights().get("lean")), 1e-9);
        assertFalse(ask(m -> m.base().isFading()));
        app.awaitButton("Fade to run");
        app.tap("Fade to run");
        app.awaitStatus("the next clip", s -> s.contains("| clip run | "));
        assertEquals("run", ask(m -> m.base().heaviestClip()));
    }

    @Test
    public void rootMotionWalksTheCharacterAcrossTheMarkerAndSwitchedOffBringsItBack() throws Exception {
        app.start(true);
        showMover();
        app.awaitStatus("the mover's first clip", s -> s.contains("| clip idle | "));
        app.awaitButton("Fade to lean");
        app.tap("Fade to lean");
        app.awaitButton("Fade to run");
        app.tap("Fade to run");
        app.awaitButton("Fade to walk");
        app.tap("Fade to walk");
        app.awaitStatus("walking", s -> s.contains("| clip walk | "));
        assertFalse(ask(m -> m.rootMotion("walk")));

        app.tap("Root motion: off");
        app.awaitStatus("root motion said", s -> s.contains("| clip walk | root motion | " + MOVER));
        assertTrue("every clip", ask(m -> m.rootMotion("walk") && m.rootMotion("run") && m.rootMotion("idle")));
        Vector3f first = placed();
        app.await("the frames' placement moving", () -> placed().distance(first) > 0.1);
        double[] p = ask(m -> m.placementPosition(new double[4]));
        assertTrue("within the marker's circle (0.48 m for this walker): " + p[0] + ", " + p[1],
                Math.hypot(p[0], p[1]) < 0.49);

        app.tap("Root motion: on");
        app.awaitStatus("root motion off", s -> s.contains("| clip walk | " + MOVER));
        app.await("the placement back at the centre", () -> placed().length() < 1e-6);
        assertFalse(ask(m -> m.rootMotion("walk")));
    }

    /** Next mesh until the five-clip humanoid is shown (the catalog's second model). */
    private void showMover() {
        for (int taps = 0; !app.status().endsWith(MOVER); taps++) {
            assertTrue("the APK bundles " + MOVER, taps < 10);
            app.tap("Next mesh");
            app.awaitStatus("a model loaded", s -> !s.contains("(loading)"));
        }
    }

    private SkeletalAnimatedMesh mesh() {
        return app.activity().mesh;
    }

    /** Where the latest frame's placement puts the model's origin. */
    private Vector3f placed() {
        try (Frame f = mesh().acquire()) {
            return f.placement(new Matrix4f()).transformPosition(new Vector3f());
        }
    }

    /** The answer to {@code question}, asked on the simulation thread at its next step. */
    private <T> T ask(Function<Mixer, T> question) throws Exception {
        Object[] answer = new Object[1];
        mesh().direct(m -> answer[0] = question.apply(m)).get(AppDriver.TIMEOUT_MILLIS, TimeUnit.MILLISECONDS);
        @SuppressWarnings("unchecked")
        T t = (T) answer[0];
        return t;
    }
}
