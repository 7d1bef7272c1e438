package org.skinlab.simulation;

import java.util.Objects;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.UnaryOperator;

import org.skinlab.animation.RotationInterpolation;
import org.skinlab.animation.WrapMode;
import org.skinlab.skinning.SkinningMethod;

/**
 * The user-facing switches of the animation (the thesis' {@code AnimationConfig}, section 5.5):
 * start/stop the animation, start/stop mesh updates, the skinning method, the rotation
 * interpolation, the playback speed, the wrap mode at the clip's end, "follow the camera", and
 * whether the mesh is skinned on the CPU or only its joint palette published (GPU skinning).
 *
 * <p><b>Threads.</b> Every setter may be called from any thread at any moment (a UI thread, a
 * touch handler, a test hammering it). The state is one immutable {@link Settings} record behind
 * an {@link AtomicReference}: a setter swaps in a new record (compare-and-set, retried on a
 * race), a reader takes the current one with a single volatile read and no lock. The simulation
 * reads it once per step, so one step never mixes two states: a caller that changes method and
 * interpolation together through {@link #update} is seen with both changed or neither. Setters
 * allocate one small record; they are user actions, not per-frame work. Volatile fields per
 * switch would read as cheaply but could not offer that atomic multi-field change.
 *
 * <p>One config may drive several {@link SkeletalAnimatedMesh}es (the desktop scene's "all
 * meshes" switches); meshes only read it. No listeners: the simulation polls every step, which is
 * already more often than a user can press a button.
 */
public final class AnimationConfig {
    /** Slowest playback as a factor of real time (magnitude; reverse playback may be as slow). */
    public static final double MIN_SPEED = 0.05;
    /** Fastest playback as a factor of real time (magnitude). */
    public static final double MAX_SPEED = 20.0;
    /** What {@link #faster()} multiplies the speed by, {@link #slower()} divides: two presses double it. */
    public static final double SPEED_STEP = Math.sqrt(2.0);

    /**
     * One consistent state of every switch.
     *
     * @param speed              playback speed as a factor of real time; negative plays backwards;
     *                           magnitude in [{@link #MIN_SPEED}, {@link #MAX_SPEED}]
     * @param method             how the mesh is skinned
     * @param interpolation      how key rotations are blended
     * @param animationRunning   whether playback time advances (the thesis' start/stop animation)
     * @param meshUpdatesRunning whether each step publishes a new frame (start/stop mesh updates);
     *                           with the animation stopped it still does, so a method switch shows
     * @param cpuSkinning        whether a published frame carries CPU-skinned positions and normals;
     *                           off, a step poses the skeleton and fills the frame's joint palette
     *                           only, for a renderer that skins on the GPU (palette-only mode)
     * @param followCamera       whether the presenter turns the model toward the camera (AR app)
     * @param wrapMode           what playback does at the clip's ends
     * @param bindPose           whether frames show the bind pose ({@code SkinnedModel.poseBind}:
     *                           every joint at its bind frame) instead of the clip at the playback
     *                           time, which keeps running underneath
     */
    public record Settings(double speed, SkinningMethod method, RotationInterpolation interpolation,
            boolean animationRunning, boolean meshUpdatesRunning, boolean cpuSkinning, boolean followCamera,
            WrapMode wrapMode, boolean bindPose) {
        /**
         * Speed 1, LBS, SLERP, animation and mesh updates running, skinned on the CPU, no camera
         * following, looping, the clip (not the bind pose) shown.
         */
        public static final Settings DEFAULT = new Settings(1.0, SkinningMethod.LBS, RotationInterpolation.SLERP,
                true, true, true, false, WrapMode.LOOP, false);

        /**
         * Checks the state; see the record's comment for what each switch means.
         *
         * @param speed              playback speed as a factor of real time, negative backwards; magnitude
         *                           in [{@link #MIN_SPEED}, {@link #MAX_SPEED}] (not clamped here:
         *                           {@link AnimationConfig#clampSpeed})
         * @param method             how the mesh is skinned; not null
         * @param interpolation      how key rotations are blended; not null
         * @param animationRunning   whether playback time advances
         * @param meshUpdatesRunning whether each step publishes a new frame
         * @param cpuSkinning        whether frames carry CPU-skinned positions and normals
         * @param followCamera       whether the presenter turns the model toward the camera
         * @param wrapMode           what playback does at the clip's ends; not null
         * @param bindPose           whether frames show the bind pose instead of the clip
         * @throws NullPointerException     when {@code method}, {@code interpolation} or {@code wrapMode} is null
         * @throws IllegalArgumentException when the speed's magnitude is outside
         *                                  [{@link #MIN_SPEED}, {@link #MAX_SPEED}], zero or NaN
         */
        public Settings {
            Objects.requireNonNull(method, "method");
            Objects.requireNonNull(interpolation, "interpolation");
            Objects.requireNonNull(wrapMode, "wrapMode");
            double magnitude = Math.abs(speed);
            if (!(magnitude >= MIN_SPEED && magnitude <= MAX_SPEED)) {
                throw new IllegalArgumentException("speed " + speed + " outside +-[" + MIN_SPEED + ", " + MAX_SPEED
                        + "] (use clampSpeed, or pause with animationRunning)");
            }
        }

        /**
         * These settings with another speed.
         *
         * @param speed the new speed as a factor of real time, negative backwards; magnitude in
         *              [{@link #MIN_SPEED}, {@link #MAX_SPEED}] (not clamped here:
         *              {@link AnimationConfig#clampSpeed})
         * @return a new record, every other switch as in this one
         * @throws IllegalArgumentException when the speed's magnitude is out of range, zero or NaN
         */
        public Settings withSpeed(double speed) {
            return new Settings(speed, method, interpolation, animationRunning, meshUpdatesRunning, cpuSkinning,
                    followCamera, wrapMode, bindPose);
        }

        /**
         * These settings with another skinning method.
         *
         * @param method the new method; not null
         * @return a new record, every other switch as in this one
         * @throws NullPointerException when {@code method} is null
         */
        public Settings withMethod(SkinningMethod method) {
            return new Settings(speed, method, interpolation, animationRunning, meshUpdatesRunning, cpuSkinning,
                    followCamera, wrapMode, bindPose);
        }

        /**
         * These settings with another rotation interpolation.
         *
         * @param interpolation the new interpolation; not null
         * @return a new record, every other switch as in this one
         * @throws NullPointerException when {@code interpolation} is null
         */
        public Settings withInterpolation(RotationInterpolation interpolation) {
            return new Settings(speed, method, interpolation, animationRunning, meshUpdatesRunning, cpuSkinning,
                    followCamera, wrapMode, bindPose);
        }

        /**
         * These settings with the animation started or stopped.
         *
         * @param animationRunning true to let playback time advance, false to hold it
         * @return a new record, every other switch as in this one
         */
        public Settings withAnimationRunning(boolean animationRunning) {
            return new Settings(speed, method, interpolation, animationRunning, meshUpdatesRunning, cpuSkinning,
                    followCamera, wrapMode, bindPose);
        }

        /**
         * These settings with mesh updates started or stopped.
         *
         * @param meshUpdatesRunning true to publish a frame every step, false to publish none
         * @return a new record, every other switch as in this one
         */
        public Settings withMeshUpdatesRunning(boolean meshUpdatesRunning) {
            return new Settings(speed, method, interpolation, animationRunning, meshUpdatesRunning, cpuSkinning,
                    followCamera, wrapMode, bindPose);
        }

        /**
         * These settings with CPU skinning on or off.
         *
         * @param cpuSkinning true to skin the mesh on the CPU, false for palette-only frames
         * @return a new record, every other switch as in this one
         */
        public Settings withCpuSkinning(boolean cpuSkinning) {
            return new Settings(speed, method, interpolation, animationRunning, meshUpdatesRunning, cpuSkinning,
                    followCamera, wrapMode, bindPose);
        }

        /**
         * These settings with camera following on or off.
         *
         * @param followCamera true to have the presenter turn the model toward the camera
         * @return a new record, every other switch as in this one
         */
        public Settings withFollowCamera(boolean followCamera) {
            return new Settings(speed, method, interpolation, animationRunning, meshUpdatesRunning, cpuSkinning,
                    followCamera, wrapMode, bindPose);
        }

        /**
         * These settings with another wrap mode.
         *
         * @param wrapMode what playback does at the clip's ends; not null
         * @return a new record, every other switch as in this one
         * @throws NullPointerException when {@code wrapMode} is null
         */
        public Settings withWrapMode(WrapMode wrapMode) {
            return new Settings(speed, method, interpolation, animationRunning, meshUpdatesRunning, cpuSkinning,
                    followCamera, wrapMode, bindPose);
        }

        /**
         * These settings showing the bind pose or the clip.
         *
         * @param bindPose true to show the bind pose, false to show the clip at the playback time
         * @return a new record, every other switch as in this one
         */
        public Settings withBindPose(boolean bindPose) {
            return new Settings(speed, method, interpolation, animationRunning, meshUpdatesRunning, cpuSkinning,
                    followCamera, wrapMode, bindPose);
        }
    }

    private final AtomicReference<Settings> settings;

    /** A config with {@link Settings#DEFAULT}. */
    public AnimationConfig() {
        this(Settings.DEFAULT);
    }

    /**
     * A config starting in the given state.
     *
     * @param initial the first state; not null
     * @throws NullPointerException when {@code initial} is null
     */
    public AnimationConfig(Settings initial) {
        settings = new AtomicReference<>(Objects.requireNonNull(initial, "initial"));
    }

    /**
     * The current state: one volatile read, no lock, no allocation.
     *
     * @return the current settings, never null; an immutable snapshot that later changes leave alone
     */
    public Settings settings() {
        return settings.get();
    }

    /**
     * Applies {@code change} atomically (retried if another thread changed the settings
     * meanwhile, so {@code change} must have no side effects) and returns the new state. The way
     * to change several switches so that no step sees only some of them changed.
     *
     * @param change maps the current settings to the new ones; may be called more than once, must
     *               not return null
     * @return the settings this call set
     * @throws NullPointerException     when {@code change} returns null
     * @throws IllegalArgumentException as {@link Settings}' constructor, when {@code change} builds an invalid state
     */
    public Settings update(UnaryOperator<Settings> change) {
        return settings.updateAndGet(s -> Objects.requireNonNull(change.apply(s), "change returned null"));
    }

    /**
     * A speed brought into range: its magnitude clamped to [{@link #MIN_SPEED}, {@link #MAX_SPEED}],
     * its sign kept (negative plays backwards: handy to scrub a twist back and forth). Zero and NaN
     * are refused: zero would be a second, silent way to pause, and NaN would poison the clock.
     *
     * @param speed a playback speed as a factor of real time, negative backwards; infinities are
     *              clamped like any other value
     * @return the speed with its magnitude in [{@link #MIN_SPEED}, {@link #MAX_SPEED}] and its sign kept
     * @throws IllegalArgumentException when {@code speed} is zero or NaN
     */
    public static double clampSpeed(double speed) {
        if (Double.isNaN(speed) || speed == 0) {
            throw new IllegalArgumentException("speed " + speed + " is not a playback speed (pause with stopAnimation)");
        }
        double magnitude = Math.max(MIN_SPEED, Math.min(MAX_SPEED, Math.abs(speed)));
        return Math.copySign(magnitude, speed);
    }

    /**
     * The playback speed.
     *
     * @return the speed as a factor of real time, negative backwards; magnitude in
     *         [{@link #MIN_SPEED}, {@link #MAX_SPEED}]
     */
    public double speed() {
        return settings().speed();
    }

    /**
     * Sets the speed, clamped as {@link #clampSpeed} says; returns the speed set.
     *
     * @param speed the wanted speed as a factor of real time, negative backwards; any value but zero and NaN
     * @return the speed set, after clamping
     * @throws IllegalArgumentException when {@code speed} is zero or NaN
     */
    public double setSpeed(double speed) {
        double clamped = clampSpeed(speed);
        update(s -> s.withSpeed(clamped));
        return clamped;
    }

    /**
     * Speed times {@link #SPEED_STEP} (clamped); returns the new speed.
     *
     * @return the speed this call set (its sign kept; backwards playback gets faster backwards)
     */
    public double faster() {
        return update(s -> s.withSpeed(clampSpeed(s.speed() * SPEED_STEP))).speed();
    }

    /**
     * Speed divided by {@link #SPEED_STEP} (clamped); returns the new speed.
     *
     * @return the speed this call set (its sign kept)
     */
    public double slower() {
        return update(s -> s.withSpeed(clampSpeed(s.speed() / SPEED_STEP))).speed();
    }

    /**
     * The skinning method steps use.
     *
     * @return the current method, never null
     */
    public SkinningMethod method() {
        return settings().method();
    }

    /**
     * Switches the skinning method; takes effect from the next step.
     *
     * @param method the method to skin with (or, with CPU skinning off, for a GPU renderer to apply); not null
     * @throws NullPointerException when {@code method} is null
     */
    public void setMethod(SkinningMethod method) {
        Objects.requireNonNull(method, "method");
        update(s -> s.withMethod(method));
    }

    /**
     * Switches to the next method in {@link SkinningMethod}'s declaration order, from the last
     * back to the first; returns it.
     *
     * @return the method switched to
     */
    public SkinningMethod nextMethod() {
        SkinningMethod[] all = SkinningMethod.values();
        return update(s -> s.withMethod(all[(s.method().ordinal() + 1) % all.length])).method();
    }

    /**
     * The interpolation steps blend key rotations with.
     *
     * @return the current interpolation, never null
     */
    public RotationInterpolation interpolation() {
        return settings().interpolation();
    }

    /**
     * Switches the rotation interpolation; takes effect from the next step.
     *
     * @param interpolation how key rotations are blended; not null
     * @throws NullPointerException when {@code interpolation} is null
     */
    public void setInterpolation(RotationInterpolation interpolation) {
        Objects.requireNonNull(interpolation, "interpolation");
        update(s -> s.withInterpolation(interpolation));
    }

    /**
     * Switches to the next interpolation in {@link RotationInterpolation}'s declaration order,
     * from the last back to the first; returns it.
     *
     * @return the interpolation switched to
     */
    public RotationInterpolation nextInterpolation() {
        RotationInterpolation[] all = RotationInterpolation.values();
        return update(s -> s.withInterpolation(all[(s.interpolation().ordinal() + 1) % all.length]))
                .interpolation();
    }

    /**
     * Whether playback time advances ({@link #startAnimation()}, {@link #stopAnimation()}).
     *
     * @return true while the animation runs
     */
    public boolean isAnimationRunning() {
        return settings().animationRunning();
    }

    /** Playback time advances again. */
    public void startAnimation() {
        setAnimationRunning(true);
    }

    /** Playback time stands still; every step still re-poses (and re-skins) while mesh updates run. */
    public void stopAnimation() {
        setAnimationRunning(false);
    }

    /**
     * Starts or stops the animation, as {@link #startAnimation()} and {@link #stopAnimation()}.
     *
     * @param running true to let playback time advance, false to hold it
     */
    public void setAnimationRunning(boolean running) {
        update(s -> s.withAnimationRunning(running));
    }

    /**
     * Whether steps publish frames ({@link #startMeshUpdates()}, {@link #stopMeshUpdates()}).
     *
     * @return true while mesh updates run
     */
    public boolean isMeshUpdatesRunning() {
        return settings().meshUpdatesRunning();
    }

    /** Every step publishes a frame again. */
    public void startMeshUpdates() {
        setMeshUpdatesRunning(true);
    }

    /**
     * Nothing is published, whether skinned on the CPU or not: readers keep getting the last
     * published frame, mesh and palette alike.
     */
    public void stopMeshUpdates() {
        setMeshUpdatesRunning(false);
    }

    /**
     * Starts or stops mesh updates, as {@link #startMeshUpdates()} and {@link #stopMeshUpdates()}.
     *
     * @param running true to publish a frame every step, false to publish none
     */
    public void setMeshUpdatesRunning(boolean running) {
        update(s -> s.withMeshUpdatesRunning(running));
    }

    /**
     * Whether steps skin the mesh on the CPU ({@link #setCpuSkinning}).
     *
     * @return true when frames carry skinned positions and normals, false for palette-only frames
     */
    public boolean isCpuSkinning() {
        return settings().cpuSkinning();
    }

    /**
     * Whether steps skin the mesh on the CPU (the default) or only pose the skeleton and publish
     * its joint palette, for a renderer that skins on the GPU ({@link Frame#hasSkinnedMesh()}).
     * Takes effect from the next step; every frame carries the palette either way.
     *
     * @param cpuSkinning true to skin on the CPU, false to publish the palette only (a method the
     *                    shaders have no code for is still skinned on the CPU)
     */
    public void setCpuSkinning(boolean cpuSkinning) {
        update(s -> s.withCpuSkinning(cpuSkinning));
    }

    /**
     * Whether the presenter turns the model toward the camera ({@link #setFollowCamera}).
     *
     * @return true when camera following is on
     */
    public boolean isFollowCamera() {
        return settings().followCamera();
    }

    /**
     * Whether the presenter (the AR scene) turns the model toward the camera; a plain flag here.
     *
     * @param follow true to turn the model toward the camera, false to leave it as placed
     */
    public void setFollowCamera(boolean follow) {
        update(s -> s.withFollowCamera(follow));
    }

    /**
     * What playback does at the clip's ends.
     *
     * @return the current wrap mode, never null
     */
    public WrapMode wrapMode() {
        return settings().wrapMode();
    }

    /**
     * Sets what playback does at the clip's ends; takes effect from the next step (or seek).
     *
     * @param mode the wrap mode; not null
     * @throws NullPointerException when {@code mode} is null
     */
    public void setWrapMode(WrapMode mode) {
        Objects.requireNonNull(mode, "mode");
        update(s -> s.withWrapMode(mode));
    }

    /**
     * Whether steps show the bind pose instead of the clip ({@link #setBindPose}).
     *
     * @return true when frames show the bind pose
     */
    public boolean isBindPose() {
        return settings().bindPose();
    }

    /**
     * Whether steps pose the model in its bind pose (every joint at its bind frame: the skins'
     * rest shapes) instead of the clip; the playback time goes on as before. Takes effect from the
     * next step.
     *
     * @param bindPose true to show the bind pose, false to show the clip at the playback time
     */
    public void setBindPose(boolean bindPose) {
        update(s -> s.withBindPose(bindPose));
    }

    @Override
    public String toString() {
        return "AnimationConfig" + settings();
    }
}
