package org.skinlab.android.logic;

import java.util.List;
import java.util.Locale;
import java.util.function.BooleanSupplier;
import java.util.function.Supplier;

import org.skinlab.simulation.AnimationConfig;

/**
 * The on-screen buttons of the AR app, one per {@link AnimationConfig} function of the thesis plus
 * the mesh switch, the mixer's cross-fade and root motion ({@link MixerControl}), the marker's size
 * and the measurement ({@link DeviceMeasurement}): each has a label that shows the current state
 * and an action. The Activity only lays them out and calls
 * {@link Action#run()} on a tap (from the UI thread; AnimationConfig may be changed from any thread).
 */
public final class AppActions {
    /** One button; {@code enabled} says whether it can be tapped now (its label then says why not). */
    public record Action(String id, Supplier<String> label, Runnable run, BooleanSupplier enabled) {
        /** A button that can always be tapped. */
        public Action(String id, Supplier<String> label, Runnable run) {
            this(id, label, run, () -> true);
        }
    }

    /** The measurement's buttons: start or stop it, and save a copy of its file where the user chooses. */
    public interface Measuring {
        boolean running();

        /** Starts a measurement, or stops the one running. */
        void toggle();

        /** Asks where to save a copy of the last measurement's file. */
        void saveCopy();
    }

    private AppActions() {
    }

    /**
     * The buttons over {@code config}; {@code nextMesh} switches to the next bundled model,
     * {@code mixer} directs the shown model's clips, {@code marker} is the printed marker's size
     * (measured by the user: the poses scale with it), {@code measuring} the measurement.
     */
    public static List<Action> of(AnimationConfig config, Runnable nextMesh, MixerControl mixer, MarkerSize marker,
            Measuring measuring) {
        return List.of(
                new Action("mesh-updates", () -> config.isMeshUpdatesRunning() ? "Stop mesh" : "Start mesh",
                        () -> config.setMeshUpdatesRunning(!config.isMeshUpdatesRunning())),
                new Action("animation", () -> config.isAnimationRunning() ? "Stop anim" : "Start anim",
                        () -> config.setAnimationRunning(!config.isAnimationRunning())),
                new Action("follow-camera", () -> config.isFollowCamera() ? "Follow: on" : "Follow: off",
                        () -> config.setFollowCamera(!config.isFollowCamera())),
                new Action("method", () -> config.method().key().toUpperCase(Locale.ROOT),
                        config::nextMethod),
                new Action("interpolation", () -> config.interpolation().name(), config::nextInterpolation),
                new Action("slower", () -> "Slower", config::slower),
                new Action("faster", () -> "Faster", config::faster),
                new Action("next-mesh", () -> "Next mesh", nextMesh),
                new Action("cross-fade", mixer::crossFadeLabel, mixer::crossFadeToNext, mixer::canCrossFade),
                new Action("root-motion", mixer::rootMotionLabel, mixer::toggleRootMotion),
                new Action("marker-size", marker::label, marker::next),
                new Action("measure", () -> measuring.running() ? "Stop measuring" : "Measure", measuring::toggle),
                new Action("save-results", () -> "Save results", measuring::saveCopy));
    }
}
