package org.skinlab.android.logic;

import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.function.Consumer;
import java.util.function.Supplier;

import org.skinlab.ar.MarkerScene;
import org.skinlab.mixer.FadeCurve;
import org.skinlab.mixer.Layer;
import org.skinlab.mixer.Mixer;
import org.skinlab.scene.ModelFraming;
import org.skinlab.simulation.Frame;
import org.skinlab.simulation.SkeletalAnimatedMesh;

/**
 * The shown character's mixer as the app's buttons direct it: a synchronised cross-fade to the
 * model's next clip, and root motion for all its clips with {@link MarkerSteering} keeping the
 * walker on the marker. Every change goes to the simulation thread through {@link
 * SkeletalAnimatedMesh#direct}; at every step the mesh's director ({@link
 * SkeletalAnimatedMesh#setDirector}) reads back what the status line says (the clip playing, or
 * the fade and its two clips) and steers, whether or not the step publishes a frame.
 *
 * <p>Threads: {@link #show}, the two switches and the labels from the UI thread; the mixer is
 * touched only on the simulation thread, and what that thread publishes for the UI is one
 * volatile value each.
 */
public final class MixerControl {
    /** How long a cross-fade takes, in seconds of animation time. */
    public static final double FADE_SECONDS = 0.5;

    private final Supplier<MarkerScene> scene;
    private volatile Shown shown;
    private volatile boolean rootMotion;

    /** {@code scene} is how the app stands models on the marker (for the steering's area). */
    public MixerControl(Supplier<MarkerScene> scene) {
        this.scene = scene;
    }

    /**
     * Directs {@code mesh} from now on (call before starting it): reads its clips, turns root
     * motion on if the switch is on, and becomes its director.
     */
    public void show(SkeletalAnimatedMesh mesh) {
        Shown s = new Shown(mesh, scene.get());
        shown = s;
        boolean on = rootMotion;
        mesh.direct(m -> {
            s.clips = m.clipNames();
            if (on) {
                s.setRootMotion(m, true);
            }
        });
        mesh.setDirector(s.everyStep);
    }

    /** Whether the shown model has two clips or more to cross-fade between (false until they are read). */
    public boolean canCrossFade() {
        Shown s = shown;
        return s != null && s.clips != null && s.clips.size() > 1;
    }

    /** The cross-fade button's label: the clip it fades to, or why it cannot. */
    public String crossFadeLabel() {
        Shown s = shown;
        List<String> clips = s == null ? null : s.clips;
        if (clips == null || clips.size() > 1 && s.next == null) {
            return "Cross-fade";
        }
        if (clips.size() < 2) {
            return clips.isEmpty() ? "Cross-fade: no clips" : "Cross-fade: 1 clip";
        }
        return "Fade to " + s.next;
    }

    /**
     * Cross-fades the shown character to the clip after the one it plays or fades to (in {@code
     * Mixer.clipNames()} order, round again after the last), over {@link #FADE_SECONDS}, in step.
     *
     * @return completes once the fade has begun on the simulation thread (at once without a model)
     */
    public CompletableFuture<Void> crossFadeToNext() {
        Shown s = shown;
        return s == null ? CompletableFuture.completedFuture(null) : s.mesh.direct(s::crossFadeToNext);
    }

    /** The root motion button's label: the switch's state. */
    public String rootMotionLabel() {
        return rootMotion ? "Root motion: on" : "Root motion: off";
    }

    /**
     * Root motion on or off for all the shown model's clips (and the next models'); either way
     * the placement starts again from the marker's centre.
     *
     * @return completes once the switch has reached the simulation thread (at once without a model)
     */
    public CompletableFuture<Void> toggleRootMotion() {
        boolean on = !rootMotion;
        rootMotion = on;
        Shown s = shown;
        return s == null ? CompletableFuture.completedFuture(null) : s.mesh.direct(m -> s.setRootMotion(m, on));
    }

    /** The status line's part: "clip walk", "clip walk -> run" while fading, "| root motion"; "" before a model. */
    public String status() {
        Shown s = shown;
        String clip = s == null ? null : s.clipText;
        if (clip == null) {
            return "";
        }
        return rootMotion ? clip + " | root motion" : clip;
    }

    /** One model's direction: its clip state for the UI, and (simulation thread) the fade and the steering. */
    private static final class Shown {
        final SkeletalAnimatedMesh mesh;
        final MarkerScene scene;
        final Consumer<Mixer> everyStep = this::everyStep;
        // Published for the UI thread.
        volatile List<String> clips;
        volatile String clipText;
        volatile String next;
        // Simulation thread only.
        private String fadeFrom;
        private String fadeTo;
        private String shownPlaying;
        private String shownFadeTo;
        private MarkerSteering steering;

        Shown(SkeletalAnimatedMesh mesh, MarkerScene scene) {
            this.mesh = mesh;
            this.scene = scene;
        }

        /** Every step, on the simulation thread ({@link SkeletalAnimatedMesh#setDirector}): reads and steers. */
        void everyStep(Mixer m) {
            Layer base = m.base();
            if (fadeTo != null && !base.isFading()) {
                fadeTo = null;
            }
            String playing = base.heaviestClip();
            if (playing != shownPlaying || fadeTo != shownFadeTo || clipText == null) {
                shownPlaying = playing;
                shownFadeTo = fadeTo;
                clipText = fadeTo != null ? "clip " + fadeFrom + " -> " + fadeTo
                        : playing != null ? "clip " + playing : "no clip";
                next = following(m.clipNames(), fadeTo != null ? fadeTo : playing);
            }
            if (steering != null) {
                steering.steer(m);
            }
        }

        void crossFadeToNext(Mixer m) {
            String from = fadeTo != null ? fadeTo : m.base().heaviestClip();
            String to = following(m.clipNames(), from);
            if (to == null || to.equals(from)) {
                return; // one clip or none: nothing to fade to
            }
            m.base().crossFade(to, FADE_SECONDS, FadeCurve.SMOOTH, true);
            fadeFrom = from;
            fadeTo = to;
        }

        void setRootMotion(Mixer m, boolean on) {
            for (String c : m.clipNames()) {
                m.setRootMotion(c, on);
            }
            m.resetPlacement();
            steering = on ? new MarkerSteering(MarkerArea.of(mesh.model(), m.skeleton(), framing(),
                    scene, MarkerArea.RADIUS_OVER_MARKER)) : null;
        }

        /** How the renderer frames the model (its first frame there; the latest one here: the same stance). */
        private ModelFraming framing() {
            try (Frame f = mesh.acquire()) {
                return ModelFraming.of(mesh.model().asset(), mesh.geometries(), f);
            }
        }

        /** The clip after {@code clip} in {@code names}, round again (the first for null); null for no clips. */
        private static String following(List<String> names, String clip) {
            if (names.isEmpty()) {
                return null;
            }
            return names.get((names.indexOf(clip) + 1) % names.size());
        }
    }
}
