package org.skinlab.desktop.bench;

import static org.lwjgl.glfw.GLFW.glfwPollEvents;
import static org.lwjgl.glfw.GLFW.glfwSwapInterval;
import static org.lwjgl.opengl.GL33C.*;

import java.io.IOException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import java.util.function.DoubleConsumer;

import org.skinlab.ar.ArPose;
import org.skinlab.ar.ArSession;
import org.skinlab.ar.CameraIntrinsics;
import org.skinlab.ar.FiducialTracker;
import org.skinlab.ar.MarkerTracking;
import org.skinlab.ar.TrackerConfig;
import org.skinlab.desktop.ar.CameraImage;
import org.skinlab.desktop.ar.FrameSource;
import org.skinlab.desktop.render.ArView;
import org.skinlab.desktop.render.DrawSettings;
import org.skinlab.desktop.render.GlWindow;
import org.skinlab.desktop.render.ModelRenderer;
import org.skinlab.desktop.render.SkinningShader;
import org.skinlab.model.Model;
import org.skinlab.scene.ModelFraming;
import org.skinlab.simulation.AnimationConfig;
import org.skinlab.simulation.Frame;
import org.skinlab.simulation.SkeletalAnimatedMesh;
import org.skinlab.skinning.SkinningMethod;

/**
 * One AR frame, end to end, timed per stage ({@code skinlab bench ar-frame}, and {@code skinlab
 * eval}'s "ar-frame" section): the next camera frame decoded from its source (video or image
 * decoding, then its colour and luminance), tracked ({@link ArSession#onCameraFrame}), the clip
 * sampled and the skeleton posed into the joint palette, the mesh skinned on the CPU with the
 * chosen method (nothing there with GPU skinning, whose vertex shader skins inside the draw), and
 * drawn: the camera picture uploaded and drawn behind the model, the model's upload and draw
 * ({@link ArView}, {@link ModelRenderer}, as {@code skinlab ar} draws them), ended by
 * {@code glFinish} so that the time is the renderer's, not the driver's queue. Presenting the
 * picture (the buffer swap) is not timed.
 *
 * <p>Every stage is timed in every frame, all on this thread (in {@code skinlab ar} the feed thread
 * decodes and tracks, the simulation thread poses and skins, the window thread draws: the sum is
 * one frame's latency and its cost on one core). A run plays the first frames of the source,
 * reopened at its start, with a fresh tracking session and the clip from its start, so every run
 * decodes, tracks and poses the same frames; a stage's value in a run is its mean time per frame
 * (so a run's stages add up to its frame time exactly). Runs of several variants are interleaved
 * (run 1 of each, then run 2 of each, the order turned by one each run), so that a slow spell of a
 * shared machine falls on all of them. A warm-up of at least the given time, every variant in turn
 * (passes of up to 20 frames), comes first and is not counted.
 */
public final class ArFrameBench implements AutoCloseable {
    /** The time of one 60 Hz display frame, in milliseconds: the budget a frame's stages share. */
    public static final double FRAME_BUDGET_MS = 1000.0 / 60;
    /** Frames per variant in each pass of the warm-up, which repeats until its time is up. */
    private static final int WARMUP_FRAMES = 20;
    /** Playback time per frame (s): the animation advances as on a 60 Hz display. */
    private static final double STEP_SECONDS = 1.0 / 60;

    /** The stages of an AR frame, in the order a frame passes them. */
    public enum Stage {
        DECODE("decode"), TRACK("track"), POSE("pose"), SKIN("skin"), DRAW("draw");

        private final String key;

        Stage(String key) {
            this.key = key;
        }

        /** Its name in results and tables. */
        public String key() {
            return key;
        }
    }

    /** What is skinned and where: a method, on the CPU or in the vertex shader. */
    public record Variant(SkinningMethod method, boolean gpuSkinning) {
        /** E.g. "lbs-cpu", "dqs-gpu". */
        public String key() {
            return method.key() + (gpuSkinning ? "-gpu" : "-cpu");
        }
    }

    /** A time per frame in milliseconds: each run's value, their median, lowest and highest. */
    public record Timing(double[] runs, double median, double min, double max) {
        static Timing of(double[] runs) {
            double[] sorted = runs.clone();
            Arrays.sort(sorted);
            int n = sorted.length;
            double median = n % 2 == 1 ? sorted[n / 2] : (sorted[n / 2 - 1] + sorted[n / 2]) / 2;
            return new Timing(runs.clone(), median, sorted[0], sorted[n - 1]);
        }
    }

    /**
     * One variant's runs: each stage's timing, the frame's (each run's stages summed), and per run
     * the frames in which the marker was shown and the model drawn on it.
     */
    public record VariantResult(Variant variant, Map<Stage, Timing> stages, Timing frame, int[] modelFrames) {
        /** One stage's timing. */
        public Timing stage(Stage stage) {
            return stages.get(stage);
        }

        /** The stages' medians added up (the height of a stacked bar of the medians). */
        public double stageMediansMs() {
            double sum = 0;
            for (Stage s : Stage.values()) {
                sum += stages.get(s).median();
            }
            return sum;
        }
    }

    /** A whole measurement: what was played and drawn with, and each variant's runs. */
    public record Result(String source, int width, int height, int framesPerRun, int runs, double warmupSeconds,
            String renderer, String glVersion, boolean softwareRenderer, List<VariantResult> variants) {
    }

    /** Opens the frames to play, from their first, once per run. */
    @FunctionalInterface
    public interface Frames {
        FrameSource open() throws IOException;
    }

    private final GlWindow window;
    private final String sourceName;
    private final Frames frames;
    private final CameraIntrinsics camera;
    private final FiducialTracker tracker;
    private final Model model;
    private final int width;
    private final int height;
    private final SkinningShader shader;
    private final ArView view;
    private final CameraImage image;
    private final String renderer;
    private final String glVersion;

    private ArFrameBench(GlWindow window, String sourceName, Frames frames, CameraIntrinsics camera,
            TrackerConfig tracking, Model model, int width, int height) {
        this.window = window;
        this.sourceName = sourceName;
        this.frames = frames;
        this.camera = camera;
        this.model = model;
        this.width = width;
        this.height = height;
        glfwSwapInterval(0);
        this.tracker = new FiducialTracker(tracking, camera);
        this.shader = new SkinningShader();
        this.view = new ArView(camera, tracking.markerSizeMetres());
        this.image = new CameraImage(width, height);
        this.renderer = glGetString(GL_RENDERER);
        this.glVersion = glGetString(GL_VERSION);
    }

    /**
     * A bench over {@code frames} (named {@code sourceName} in the results) seen through
     * {@code camera} (of the frames' size), tracked with {@code tracking}, with {@code model}
     * standing on the marker, in an off-screen window of the frames' size (one screen pixel per
     * camera pixel) whose context is current on this thread. The tracker runs on this thread.
     *
     * @throws GlWindow.WindowUnavailableException without a display or OpenGL 3.3
     */
    public static ArFrameBench open(String sourceName, Frames frames, CameraIntrinsics camera, TrackerConfig tracking,
            Model model) throws IOException {
        int width;
        int height;
        try (FrameSource probe = frames.open()) {
            width = probe.width();
            height = probe.height();
        }
        if (camera.width() != width || camera.height() != height) {
            throw new IllegalArgumentException(sourceName + ": frames of " + width + "x" + height + " but a camera of "
                    + camera.width() + "x" + camera.height());
        }
        FiducialTracker.runOnCallingThread();
        GlWindow window = new GlWindow("skinlab bench ar-frame", width, height, false, false);
        try {
            return new ArFrameBench(window, sourceName, frames, camera, tracking, model, width, height);
        } catch (RuntimeException | Error e) {
            window.close();
            throw e;
        }
    }

    /** GL_RENDERER. */
    public String renderer() {
        return renderer;
    }

    /** One variant's model, its renderer and what it draws with. */
    private final class Player implements AutoCloseable {
        final Variant variant;
        final SkeletalAnimatedMesh mesh;
        final ModelRenderer modelRenderer;
        final ModelFraming framing;
        final DrawSettings draw = new DrawSettings();

        Player(Variant variant) {
            this.variant = variant;
            AnimationConfig config = new AnimationConfig();
            config.setMethod(variant.method());
            config.setCpuSkinning(!variant.gpuSkinning());
            mesh = new SkeletalAnimatedMesh(model, model.clips().isEmpty() ? null : model.clips().get(0), config);
            mesh.step(0);
            try (Frame f = mesh.acquire()) {
                framing = ModelFraming.of(model.asset(), mesh.geometries(), f);
            }
            modelRenderer = new ModelRenderer(shader, model, mesh.geometries(), img -> 0);
        }

        @Override
        public void close() {
            modelRenderer.close();
            mesh.close();
        }
    }

    /**
     * Warms up for at least {@code warmupSeconds} (each variant in turn), then times {@code runs}
     * runs of {@code framesPerRun} frames of each variant, interleaved; {@code progress} hears the
     * fraction done after each run.
     */
    public Result run(List<Variant> variants, int runs, int framesPerRun, double warmupSeconds,
            DoubleConsumer progress) throws IOException {
        if (variants.isEmpty() || runs < 1 || framesPerRun < 1) {
            throw new IllegalArgumentException("need a variant, a run and a frame: " + variants + ", " + runs + ", "
                    + framesPerRun);
        }
        List<Player> players = new ArrayList<>();
        try {
            for (Variant v : variants) {
                players.add(new Player(v));
            }
            long warmEnd = System.nanoTime() + (long) (warmupSeconds * 1e9);
            do {
                for (Player p : players) {
                    play(p, Math.min(framesPerRun, WARMUP_FRAMES), null, null);
                }
            } while (System.nanoTime() < warmEnd);

            int n = players.size();
            double[][][] values = new double[n][Stage.values().length][runs];
            int[][] modelFrames = new int[n][runs];
            for (int r = 0; r < runs; r++) {
                for (int k = 0; k < n; k++) {
                    int i = (k + r) % n;
                    long[] nanos = new long[Stage.values().length];
                    int[] shown = new int[1];
                    int played = play(players.get(i), framesPerRun, nanos, shown);
                    for (Stage s : Stage.values()) {
                        values[i][s.ordinal()][r] = nanos[s.ordinal()] / 1e6 / played;
                    }
                    modelFrames[i][r] = shown[0];
                    progress.accept((r * n + k + 1.0) / (runs * n));
                }
            }
            List<VariantResult> results = new ArrayList<>();
            for (int i = 0; i < n; i++) {
                Map<Stage, Timing> stages = new EnumMap<>(Stage.class);
                double[] frame = new double[runs];
                for (Stage s : Stage.values()) {
                    stages.put(s, Timing.of(values[i][s.ordinal()]));
                    for (int r = 0; r < runs; r++) {
                        frame[r] += values[i][s.ordinal()][r];
                    }
                }
                results.add(new VariantResult(variants.get(i), Collections.unmodifiableMap(stages), Timing.of(frame),
                        modelFrames[i]));
            }
            return new Result(sourceName, width, height, framesPerRun, runs, warmupSeconds, renderer, glVersion,
                    RenderBench.isSoftware(renderer), List.copyOf(results));
        } finally {
            players.forEach(Player::close);
        }
    }

    /**
     * Plays the source's first {@code count} frames (looping at its end, as {@code skinlab ar}
     * does) with a fresh tracking session and the clip from its start; with {@code nanos} non-null, adds
     * each stage's time to {@code nanos[stage]} and the frames with the model drawn to
     * {@code shown[0]}. Returns the frames played.
     */
    private int play(Player p, int count, long[] nanos, int[] shown) throws IOException {
        tracker.reset();
        ArSession session = new ArSession(tracker::track, new MarkerTracking(tracker.config().targetId(),
                MarkerTracking.DEFAULT_HOLD_NANOS));
        p.mesh.seek(0);
        try (FrameSource source = frames.open()) {
            glViewport(0, 0, width, height);
            for (int i = 0; i < count; i++) {
                long t0 = System.nanoTime();
                source.next(image);
                long t1 = System.nanoTime();
                ArPose pose = session.onCameraFrame(image.gray(), t1);
                long t2 = System.nanoTime();
                p.mesh.step(STEP_SECONDS);
                long t3 = System.nanoTime();
                boolean drawn = draw(p, pose);
                long t4 = System.nanoTime();
                if (nanos != null) {
                    long skin;
                    try (Frame f = p.mesh.acquire()) {
                        skin = f.meshSkinningNanos();
                    }
                    nanos[Stage.DECODE.ordinal()] += t1 - t0;
                    nanos[Stage.TRACK.ordinal()] += t2 - t1;
                    nanos[Stage.POSE.ordinal()] += t3 - t2 - skin;
                    nanos[Stage.SKIN.ordinal()] += skin;
                    nanos[Stage.DRAW.ordinal()] += t4 - t3;
                    shown[0] += drawn ? 1 : 0;
                }
                window.swapBuffers();
                glfwPollEvents();
            }
        }
        return count;
    }

    /**
     * The AR picture of one frame as {@code skinlab ar} draws it: the camera's colour behind, the
     * model on the marker when the pose shows it; finished. True when the model was drawn.
     */
    private boolean draw(Player p, ArPose pose) {
        glClearColor(0f, 0f, 0f, 1f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        view.upload(image.width(), image.height(), image.rgb());
        view.drawBackground(width, height);
        boolean drawn = false;
        try (Frame frame = p.mesh.acquire()) {
            p.modelRenderer.upload(frame);
            if (view.placeModel(pose, p.framing, false, p.draw, width, height)) {
                glEnable(GL_DEPTH_TEST);
                glEnable(GL_BLEND);
                glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
                p.draw.gpuSkinning = !frame.hasSkinnedMesh();
                p.draw.method = frame.method();
                p.modelRenderer.draw(p.draw);
                drawn = true;
            }
        }
        glFinish();
        return drawn;
    }

    @Override
    public void close() {
        try {
            view.close();
            shader.close();
        } finally {
            window.close();
        }
    }
}
