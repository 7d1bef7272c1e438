package org.skinlab.simulation;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.function.Consumer;

import org.skinlab.mixer.Mixer;
import org.skinlab.model.AnimationClip;
import org.skinlab.model.Model;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinnedModel;

/**
 * A model playing one clip, simulated on its own thread (the thesis' {@code SkeletalAnimatedMesh},
 * section 5.6): it owns the mesh, the skeleton and the clip (through a {@link SkinnedModel}) and
 * reads its switches from an {@link AnimationConfig}. After {@link #start()} one daemon thread
 * steps at {@link #stepRate()} steps per second (paced by absolute deadlines: {@link PacedThread});
 * each step
 * <ol>
 * <li>advances the playback time by {@code dt * speed} when the animation runs, wrapped or held
 *     at the clip's ends as the wrap mode says;</li>
 * <li>when mesh updates run, poses the skeleton at that time with the configured interpolation,
 *     copies every geometry's joint palette (skinning matrices, dual quaternions, scale parts,
 *     bone rows)
 *     into a free buffer and, with CPU skinning on, skins every geometry with the configured
 *     method into it too, then publishes it as the latest {@link Frame}. A stopped animation is
 *     still re-posed every step, so switching the method or the interpolation shows at once; with
 *     mesh updates stopped nothing is posed or published and readers keep the last frame (the
 *     playback time still advances while the animation runs).</li>
 * </ol>
 * With CPU skinning off ({@link AnimationConfig#setCpuSkinning}) frames carry only the palette,
 * for a renderer that skins on the GPU ({@link Frame#hasSkinnedMesh()}), except for a method the
 * shaders have no code for ({@link org.skinlab.skinning.SkinningGlsl#hasCode}), which is skinned
 * here anyway so that every renderer can draw it; the switch takes effect at the next step, so
 * the frames say per step which kind they are.
 * {@link #step(double)} runs the same step on the caller's thread, for tests, the command line and
 * renderers that drive the simulation themselves.
 *
 * <p><b>Snapshots: a pool of leased buffers instead of the thesis' mutex.</b> The thesis guarded
 * one mesh with a mutex that the simulation held while skinning and the renderer while drawing,
 * so each side could stall the other for a whole skinning or upload. Here the simulation skins
 * into a buffer no reader holds and publishes it with one atomic store; a reader
 * {@link #acquire() acquires} the latest frame (counting itself in as a lease) and
 * {@link Frame#close() closes} it when done, and the simulation never writes a leased buffer
 * ({@link FramePool} has the protocol and why it is safe). A reader therefore never sees a frame
 * being written and never waits for the simulation, and the simulation never waits for a reader.
 * With one reader this is the classic triple buffer; more readers holding frames at once make
 * the pool grow, up to {@value #MAX_BUFFERS} buffers, after which a step skips publishing
 * (counted in {@link #droppedFrames()}) rather than block. Reads copy nothing and allocate
 * nothing, which matters to renderers that upload positions and normals every frame; any number
 * of threads may read. The price against a mutex-guarded double buffer is memory (three frames
 * instead of two) and the rule that a reader closes what it acquires.
 *
 * <p><b>Thread rules.</b> Every method may be called from any thread. {@link #start()},
 * {@link #stop()} and {@link #close()} are idempotent; stop and close return once the thread has
 * ended (unless called from the simulation thread itself, e.g. from the frame listener). Stepping
 * is serialised by one lock ({@link SimulationThread}), so a thread that is still finishing its
 * last step after a stop never overlaps a new one. {@link #step(double)} refuses while the thread
 * runs: two clocks driving one playback would make its time meaningless. Interrupting the
 * simulation thread stops it.
 *
 * <p><b>Failures.</b> Anything the simulation thread throws (a skinning bug, the frame listener,
 * which runs after the step lock is released) is kept in {@link #failure()}, the thread ends
 * cleanly, readers keep the last good frame, and {@link #start()} and {@link #step(double)} then
 * refuse with the failure as the cause, so it cannot vanish. {@link #throwIfFailed()} lets a
 * render loop surface it.
 *
 * <p>Who does what: this class keeps the playback clock and publishes each step's frame;
 * {@link FrameWriter} poses and skins into it, {@link FramePool} hands the buffers out, and
 * {@link SimulationThread} decides when steps run. In steady state a step allocates nothing.
 */
public final class SkeletalAnimatedMesh implements AutoCloseable {
    /** Steps per second unless {@link #setStepRate} says otherwise: a display's refresh rate. */
    public static final double DEFAULT_STEP_RATE = 60.0;
    /** Slowest step rate {@link #setStepRate} accepts, in steps per second. */
    public static final double MIN_STEP_RATE = 1.0;
    /** Fastest step rate {@link #setStepRate} accepts, in steps per second. */
    public static final double MAX_STEP_RATE = 10_000.0;
    /**
     * The longest time one threaded step advances playback by (seconds): after a stall (a
     * debugger, a phone suspending the app) the animation resumes instead of jumping ahead.
     */
    public static final double MAX_STEP_SECONDS = 0.25;
    /** Most buffers the frame pool grows to when many readers hold frames at once. */
    public static final int MAX_BUFFERS = 8;

    private final Model model;
    private final AnimationClip clip;
    private final AnimationConfig config;
    private final SkinnedModel skinned;
    private final SimulationThread thread;

    // Simulation side: touched only inside a step or under SimulationThread.exclusively.
    private final Mixer mixer;
    /** Changes to the mixer from any thread, applied at the start of the next step. */
    private final ConcurrentLinkedQueue<Direction> directions = new ConcurrentLinkedQueue<>();
    /** Runs every step after the queued changes (a scene's steering), or null. */
    private volatile Consumer<Mixer> director;
    private final FrameWriter writer;
    private final FramePool pool;
    private double playback;
    private long sequence;

    // Shared with readers.
    private volatile double playbackTime;
    private volatile long publishedSequence;
    private volatile long steps;
    private volatile long droppedFrames;

    /**
     * The model's first clip (at rest if it has none), a fresh config, exact normals. Does all the
     * bind-time work, as the constructor: call it on a loader thread.
     *
     * @param model the model to animate; not null
     * @return a new mesh, not started, with frame 0 published
     */
    public static SkeletalAnimatedMesh of(Model model) {
        return of(model, new AnimationConfig());
    }

    /**
     * The model's first clip (at rest if it has none) under {@code config}, exact normals. Does all
     * the bind-time work, as the constructor: call it on a loader thread.
     *
     * @param model  the model to animate; not null
     * @param config the switches to follow; may be shared with other meshes; not null
     * @return a new mesh, not started, with frame 0 published
     */
    public static SkeletalAnimatedMesh of(Model model, AnimationConfig config) {
        return new SkeletalAnimatedMesh(model, model.clips().isEmpty() ? null : model.clips().get(0), config);
    }

    /**
     * The model playing the clip named {@code clipName}. Does all the bind-time work, as the
     * constructor: call it on a loader thread.
     *
     * @param model    the model to animate; not null
     * @param clipName the name of one of the model's clips ({@link AnimationClip#name()})
     * @param config   the switches to follow; may be shared with other meshes; not null
     * @return a new mesh, not started, with frame 0 published, exact normals
     * @throws IllegalArgumentException when the model has no such clip (the message lists those it has)
     */
    public static SkeletalAnimatedMesh of(Model model, String clipName, AnimationConfig config) {
        AnimationClip clip = model.clip(clipName).orElseThrow(() -> {
            List<String> names = new ArrayList<>();
            model.clips().forEach(c -> names.add(c.name()));
            return new IllegalArgumentException(model.source() + ": no animation clip \"" + clipName + "\" (clips: "
                    + (names.isEmpty() ? "none" : String.join(", ", names)) + ")");
        });
        return new SkeletalAnimatedMesh(model, clip, config);
    }

    /**
     * The model playing {@code clip} under {@code config}, with exact normals
     * ({@link NormalTransform#INVERSE_TRANSPOSE}). Does all the bind-time work, as
     * {@link #SkeletalAnimatedMesh(Model, AnimationClip, AnimationConfig, NormalTransform)} says:
     * build it on a loader thread, not a UI or GL thread.
     *
     * @param model  the model to animate; not null
     * @param clip   the clip to play, or null to keep the model at rest
     * @param config the switches to follow; may be shared with other meshes
     * @throws NullPointerException when {@code model} or {@code config} is null
     */
    public SkeletalAnimatedMesh(Model model, AnimationClip clip, AnimationConfig config) {
        this(model, clip, config, NormalTransform.INVERSE_TRANSPOSE);
    }

    /**
     * The model playing {@code clip} under {@code config}. The constructor does all the bind-time
     * work, through a {@link SkinnedModel} bound for every
     * {@link org.skinlab.skinning.SkinningMethod}: each geometry's layout, bones and CoR's centres
     * of rotation, and every method's skinner, so that switching the method later never stalls a
     * step. That work grows with the model (its vertices, influences and joints), so build the mesh on
     * a loader thread, not a UI or GL thread. It then publishes frame 0 at the clip's start, as
     * the config's switches say (even with mesh updates stopped), so {@link #acquire()} always has
     * a frame; the simulation thread is not started ({@link #start()}).
     *
     * @param model   the model to animate; not null
     * @param clip    the clip to play (one of the model's {@link Model#clips()}), or null to keep
     *                the model at rest
     * @param config  the switches to follow; may be shared with other meshes; not null
     * @param normals how frames' normals are made: {@link NormalTransform#INVERSE_TRANSPOSE} or
     *                {@link NormalTransform#BLENDED_MATRIX}; frames carry normals for rendering and
     *                the switches may pick any method, so {@link NormalTransform#NONE} is refused
     *                (skin positions only with a {@link org.skinlab.skinning.SkinnedModel} or a skinner)
     * @throws IllegalArgumentException for {@link NormalTransform#NONE}
     * @throws NullPointerException     when {@code model}, {@code config} or {@code normals} is null
     */
    public SkeletalAnimatedMesh(Model model, AnimationClip clip, AnimationConfig config, NormalTransform normals) {
        if (normals == NormalTransform.NONE) {
            throw new IllegalArgumentException("SkeletalAnimatedMesh: frames carry normals and any method may be"
                    + " switched on, so NormalTransform.NONE (positions only, lbs and dqs) is not taken here");
        }
        this.model = Objects.requireNonNull(model, "model");
        this.clip = clip;
        this.config = Objects.requireNonNull(config, "config");
        this.skinned = new SkinnedModel(model, clip, Objects.requireNonNull(normals, "normals"));
        this.mixer = new Mixer(model, skinned.skeleton());
        if (clip != null) {
            mixer.base().play(clip.name());
        }
        this.writer = new FrameWriter(skinned, mixer);
        this.pool = writer.newPool(MAX_BUFFERS);
        this.thread = new SimulationThread(describe(), this::advance);
        // Frame 0: the clip's start, so acquire() always has something to give, whatever the
        // switches say (no listener can be set yet).
        thread.exclusively(() -> publish(config.settings()));
    }

    /**
     * The model this mesh animates.
     *
     * @return the model given to the constructor
     */
    public Model model() {
        return model;
    }

    /**
     * The clip being played, or null when the model stays at rest.
     *
     * @return the clip given to the constructor, or null
     */
    public AnimationClip clip() {
        return clip;
    }

    /**
     * The switches this mesh follows, read once per step.
     *
     * @return the config given to the constructor, possibly shared with other meshes
     */
    public AnimationConfig config() {
        return config;
    }

    /**
     * The geometries in frame order (immutable runtime data: bind-shape arrays, influences,
     * the mapping from points to the mesh's vertices and positions).
     *
     * @return an unmodifiable list, index {@code g} the geometry of every frame's {@code palette(g)},
     *         {@code positions(g)} and {@code normals(g)}
     */
    public List<SkinnedGeometry> geometries() {
        return skinned.geometries();
    }

    /**
     * The clip's length in seconds (0 at rest, without a clip).
     *
     * @return the duration in seconds, 0 or more
     */
    public double clipDuration() {
        return clip == null ? 0.0 : clip.duration();
    }

    /**
     * Directs the character: {@code change} runs on the simulation thread at the start of the next
     * step (before the clock advances), so no frame shows half a change and the caller never
     * waits for a step. Changes run in the order given. A change that throws (an unknown clip, a
     * NaN weight) changes nothing more and completes the returned future with its exception;
     * the simulation goes on. By hand, {@link #step(double)} applies the changes given so far.
     *
     * @param change what to do to the mixer (whose base layer plays the constructor's clip)
     * @return completes once the change has run, exceptionally when it threw
     */
    public CompletableFuture<Void> direct(Consumer<Mixer> change) {
        Direction d = new Direction(Objects.requireNonNull(change, "change"));
        directions.add(d);
        return d.done;
    }

    /**
     * Sets a change that runs on the simulation thread at every step, after the changes queued by
     * {@link #direct} and before the clock advances, whether or not the step publishes a frame: a
     * scene's steering (turning a root-motion walker back towards a marker), or reading the
     * mixer's state for a status line. It must not allocate per step if the steps are to allocate
     * nothing; a director that throws fails the simulation like a failing step.
     *
     * @param director the change to run every step, or null for none
     */
    public void setDirector(Consumer<Mixer> director) {
        this.director = director;
    }

    private record Direction(Consumer<Mixer> change, CompletableFuture<Void> done) {
        Direction(Consumer<Mixer> change) {
            this(change, new CompletableFuture<>());
        }
    }

    // ------------------------------------------------------------------------------- readers

    /**
     * The latest published frame, lent until its {@link Frame#close()}. Never null: a mesh
     * publishes frame 0 when it is built. Lock-free (it retries only if a frame is published
     * between its two reads) and allocation-free; any thread, any number of readers.
     *
     * @return the latest frame, leased to the caller, who must close it exactly once
     */
    public Frame acquire() {
        return pool.acquire();
    }

    /**
     * The sequence number of the latest published frame.
     *
     * @return the latest {@link Frame#sequence()}: 0 after construction, one more per published step
     */
    public long latestSequence() {
        return publishedSequence;
    }

    /**
     * Playback time (seconds since the clip's start) after the latest step, published or not.
     *
     * @return the playback time in seconds, wrapped or held as the wrap mode says (0 at rest)
     */
    public double playbackTime() {
        return playbackTime;
    }

    /**
     * Steps taken so far (threaded and by hand), whether or not they published a frame.
     *
     * @return the step count; frame 0, published by the constructor, is not a step
     */
    public long stepCount() {
        return steps;
    }

    /**
     * Steps that skinned nothing because every buffer was leased to readers (see the class comment).
     *
     * @return the number of steps that published no frame for want of a free buffer
     */
    public long droppedFrames() {
        return droppedFrames;
    }

    /**
     * What ended the simulation thread, or null.
     *
     * @return what the simulation thread (a step, or the frame listener run on it) threw first, or
     *         null while nothing has
     */
    public Throwable failure() {
        return thread.failure();
    }

    /** Throws if the simulation thread has failed, with the failure as cause. */
    public void throwIfFailed() {
        thread.throwIfFailed();
    }

    // ---------------------------------------------------------------------------- settings

    /**
     * Steps per second the simulation thread takes ({@link #DEFAULT_STEP_RATE} until
     * {@link #setStepRate} is called).
     *
     * @return the step rate, as the thread paces it (a whole number of nanoseconds per step, so it
     *         may differ from the rate set in its last digits)
     */
    public double stepRate() {
        return thread.stepRate();
    }

    /**
     * Steps per second of the simulation thread, in [{@link #MIN_STEP_RATE}, {@link #MAX_STEP_RATE}];
     * any thread, any time; the running thread uses it from its next step on.
     *
     * @param stepsPerSecond the rate, in [{@link #MIN_STEP_RATE}, {@link #MAX_STEP_RATE}]
     * @throws IllegalArgumentException when the rate is outside that range or NaN
     */
    public void setStepRate(double stepsPerSecond) {
        thread.setStepRate(stepsPerSecond);
    }

    /**
     * Called after every published frame, on the thread that stepped, once the step has let go
     * of the step lock (e.g. to ask a render view for a redraw: Android's
     * {@code GLSurfaceView.requestRender()}). It should be quick, since the simulation thread
     * takes its next step only after it returns, but a slow one holds no lock: readers and hand
     * steps on other threads go on (a {@link #stop()} from another thread does wait for it, as it
     * waits for the thread to end). By the time it runs a newer frame may already be published:
     * it should {@link #acquire()} the latest rather than assume which.
     * What it throws on the simulation thread ends that thread as a {@link #failure()}; on a
     * hand step it propagates to the caller of {@link #step(double)}, the frame already
     * published. Null for none.
     *
     * @param listener the callback, or null for none; replaces the one set before
     */
    public void setFrameListener(Runnable listener) {
        thread.setFrameListener(listener);
    }

    // ---------------------------------------------------------------------------- lifecycle

    /**
     * Starts the simulation thread (a daemon named {@code skinlab-simulation-N}).
     *
     * @return true if this call started it, false if it was already running
     * @throws IllegalStateException after {@link #close()}, or after the thread failed
     */
    public boolean start() {
        return thread.start();
    }

    /**
     * Whether the simulation thread runs (started, not stopped, not ended by failure or interrupt).
     *
     * @return true while the thread runs
     */
    public boolean isRunning() {
        return thread.isRunning();
    }

    /**
     * Stops the simulation thread and waits for it to end (not when called from that thread).
     * Does nothing before {@link #start()} or when already stopped; the published frame stays.
     *
     * @return true if this call asked a running thread to stop
     */
    public boolean stop() {
        return thread.stop();
    }

    /** Stops the thread (as {@link #stop()}) for good: start and step refuse afterwards. Idempotent. */
    @Override
    public void close() {
        thread.close();
    }

    /**
     * Whether {@link #close()} has been called: start and step then refuse.
     *
     * @return true once closed
     */
    public boolean isClosed() {
        return thread.isClosed();
    }

    // ---------------------------------------------------------------------------- simulation

    /**
     * One simulation step on the caller's thread: advance playback by {@code dtSeconds} times the
     * speed (when the animation runs), then skin and publish (when mesh updates run).
     *
     * @param dtSeconds real time to advance by, in seconds (the playback moves by this times the
     *                  speed); finite and 0 or more: 0 re-poses and, while mesh updates run, republishes
     *                  at the same time
     * @throws IllegalArgumentException for a negative, infinite or NaN step
     * @throws IllegalStateException    while the simulation thread runs, after close, after a failure
     */
    public void step(double dtSeconds) {
        if (!(dtSeconds >= 0) || Double.isInfinite(dtSeconds)) {
            throw new IllegalArgumentException("step of " + dtSeconds + " s (need a finite time >= 0)");
        }
        thread.stepByHand(dtSeconds);
    }

    /**
     * Moves the playback to {@code seconds} after the clip's start (wrapped into the clip, or held
     * at its ends, as the wrap mode says). Allowed while the simulation thread runs: its next step
     * poses there, and since a stopped animation is re-posed every step, a paused timeline
     * scrubber shows each position at once. By hand, {@code seek(t)} then {@code step(0)}
     * publishes the frame at {@code t}.
     *
     * @param seconds the playback time to go to, in seconds after the clip's start; any finite value
     *                (when looping, a negative one counts back from the clip's end)
     * @throws IllegalArgumentException for a NaN or infinite time
     */
    public void seek(double seconds) {
        if (Double.isNaN(seconds) || Double.isInfinite(seconds)) {
            throw new IllegalArgumentException("seek to " + seconds + " s (need a finite time)");
        }
        thread.exclusively(() -> {
            mixer.base().setWrapMode(config.settings().wrapMode());
            mixer.base().setTime(seconds);
            playback = mixer.base().time();
            playbackTime = playback;
        });
    }

    /** One step (the caller holds the step lock): the clock, then the frame. True when it published one. */
    private boolean advance(double dt) {
        AnimationConfig.Settings s = config.settings();
        for (Direction d = directions.poll(); d != null; d = directions.poll()) {
            try {
                d.change.accept(mixer);
                d.done.complete(null);
            } catch (RuntimeException e) {
                d.done.completeExceptionally(e);
            }
        }
        Consumer<Mixer> d = director;
        if (d != null) {
            d.accept(mixer);
        }
        mixer.base().setWrapMode(s.wrapMode());
        if (s.animationRunning()) {
            mixer.advance(dt * s.speed());
        }
        playback = mixer.base().time();
        playbackTime = playback;
        steps++;
        return s.meshUpdatesRunning() && publish(s);
    }

    /**
     * Fills a free buffer with this step's frame and publishes it (the caller holds the step
     * lock). False when every buffer was held (dropped).
     */
    private boolean publish(AnimationConfig.Settings s) {
        Frame f = pool.claim();
        if (f == null) {
            droppedFrames++;
            return false;
        }
        long seq = sequence++;
        writer.write(f, playback, s, seq);
        pool.publish(f);
        publishedSequence = seq;
        return true;
    }

    private String describe() {
        return "SkeletalAnimatedMesh[" + model.source() + (clip == null ? ", at rest" : ", clip " + clip.name()) + "]";
    }

    @Override
    public String toString() {
        return describe();
    }
}
