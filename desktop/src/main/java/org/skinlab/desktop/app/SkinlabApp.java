package org.skinlab.desktop.app;

import static org.lwjgl.glfw.GLFW.*;
import static org.lwjgl.opengl.GL33C.*;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.ByteBuffer;
import java.nio.file.Path;
import java.time.LocalDateTime;
import java.time.format.DateTimeFormatter;

import org.lwjgl.system.MemoryUtil;
import org.skinlab.desktop.ExitCodes;
import org.skinlab.desktop.render.DrawSettings;
import org.skinlab.desktop.render.GlDebugLog;
import org.skinlab.desktop.render.GlWindow;
import org.skinlab.desktop.render.Screenshot;
import org.skinlab.desktop.ui.ImGuiUi;
import org.skinlab.desktop.ui.UserInterface;
import org.skinlab.desktop.viewer.LoadedModel;
import org.skinlab.desktop.viewer.ModelLibrary;
import org.skinlab.desktop.viewer.Viewer;
import org.skinlab.desktop.viewer.ViewerAction;
import org.skinlab.animation.WrapMode;
import org.skinlab.simulation.AnimationConfig;
import org.skinlab.simulation.Frame;

/**
 * The viewer window: the render loop that ties the {@link Viewer} (model, switches, camera), the
 * {@link ScenePainter} (the scene on the GPU) and the {@link UserInterface} (toolbar) together, for a
 * person, a script or one headless picture. Each loop iteration acquires the newest simulation
 * {@link Frame} once and draws everything from it, so a split view, the instances and the numbers
 * always show the same time step.
 */
public final class SkinlabApp implements AutoCloseable {
    private static final float[] BACKGROUND = {0.17f, 0.18f, 0.21f};
    /** How long a picture waits for the auto difference scale's measure of the clip, at most. */
    private static final long AUTO_SCALE_SECONDS = 600;

    private final GlWindow window;
    private final PrintWriter out;
    private final PrintWriter err;
    private final AppOptions options;
    private final AnimationConfig config = new AnimationConfig();
    private final Viewer viewer;
    private final MutableSceneReadout info = new MutableSceneReadout();
    private final ScenePainter scene;
    private final WindowInput input;
    private final int[] size = new int[2];
    private UserInterface ui = UserInterface.NONE;
    private ScriptPlayer player;
    private final GlDebugLog debugLog;
    /** The AR mode's camera background and marker placement ({@code skinlab ar}), or null. */
    private final ArPresenter ar;
    private long frameNumber;
    private long lastNanos;
    private final long startNanos;

    private SkinlabApp(GlWindow window, AppOptions options, ArSetup arSetup, PrintWriter out, PrintWriter err) {
        this.window = window;
        this.out = out;
        this.err = err;
        this.options = options;
        config.setMethod(options.method());
        config.setInterpolation(options.interpolation());
        config.setCpuSkinning(!options.gpuSkinning());
        config.setBindPose(options.bindPose());
        if (options.time() != null) {
            config.stopAnimation();
        }
        viewer = new Viewer(ModelLibrary.find(), config, !options.headless());
        viewer.camera().setHomeYaw((float) Math.toRadians(options.yawDegrees()));
        viewer.camera().setHomePitch((float) Math.toRadians(options.pitchDegrees()));
        viewer.settings().setView(options.view());
        viewer.settings().setDifferenceScale(options.differenceScale());
        viewer.settings().setSplit(options.splitMethod() != null);
        debugLog = options.glDebug() ? GlDebugLog.install(window.capabilities()) : null;
        if (options.glDebug() && debugLog == null) {
            err.println("skinlab: --gl-debug: this OpenGL reports no debug messages (no OpenGL 4.3 or KHR_debug)");
        }
        ar = arSetup == null ? null : new ArPresenter(arSetup);
        scene = new ScenePainter(window, viewer, config, options.splitMethod(), info, ar);
        input = new WindowInput(window, viewer, this);
        info.viewer = viewer;
        if (!options.hideUi()) {
            // After the window's own callbacks: ImGui's backend chains to them.
            ui = new ImGuiUi(window, this::windowAction);
            input.setUi(ui);
        }
        startNanos = System.nanoTime();
    }

    /**
     * Runs the window (or, with a screenshot path, one off-screen frame) until it closes; returns
     * the exit status. Failures to open a window are one line on stderr.
     */
    public static int run(AppOptions options, PrintWriter out, PrintWriter err) {
        return run(options, null, out, err);
    }

    /**
     * As {@link #run(AppOptions, PrintWriter, PrintWriter)}, in AR mode when {@code ar} is given:
     * the camera feed as background and the model on the marker ({@code skinlab ar}); the window
     * owns the feed from here on and closes it.
     */
    public static int run(AppOptions options, ArSetup ar, PrintWriter out, PrintWriter err) {
        UiScript script = null;
        if (options.script() != null) {
            try {
                script = UiScript.read(options.script());
            } catch (IOException e) {
                err.println("skinlab: cannot read the script " + options.script() + ": " + e.getMessage());
                return ExitCodes.INTERNAL;
            } catch (IllegalArgumentException e) {
                err.println("skinlab: " + e.getMessage());
                return ExitCodes.INTERNAL;
            }
        }
        GlWindow window;
        try {
            window = new GlWindow("skinlab", options.width(), options.height(), !options.headless(), options.glDebug());
        } catch (GlWindow.WindowUnavailableException e) {
            err.println("skinlab: " + e.getMessage());
            if (ar != null) {
                ar.feed().close();
            }
            return ExitCodes.UNAVAILABLE;
        }
        try (window; SkinlabApp app = new SkinlabApp(window, options, ar, out, err)) {
            if (script != null) {
                app.player = new ScriptPlayer(script, window, app, app.viewer, app.ui);
            }
            int status = options.headless() ? app.screenshotOnce() : app.loop();
            return app.reportGlErrors() ? ExitCodes.INTERNAL : status;
        }
    }

    // ------------------------------------------------------------------------------ headless

    private int screenshotOnce() {
        Path file = options.file() != null ? options.file() : viewer.library().defaultModel();
        String error = viewer.openAndWait(file);
        if (error != null) {
            err.println("skinlab: " + error);
            return ExitCodes.INVALID_FILE;
        }
        LoadedModel model = viewer.current();
        if (options.view() == DrawSettings.View.DIFFERENCE) {
            viewer.awaitDifferenceScale(AUTO_SCALE_SECONDS);
        }
        String noFrame = ar == null ? null : ar.awaitCameraFrame();
        if (noFrame != null) {
            err.println("skinlab: " + noFrame);
            return ExitCodes.INTERNAL;
        }
        // A still picture of a time at or past the clip's end shows the end, not the loop's start.
        config.setWrapMode(WrapMode.CLAMP);
        model.mesh().seek(options.time() == null ? 0.0 : options.time());
        model.mesh().step(0.0);
        // ImGui lays its windows out over the first frames: draw a few before the picture.
        int frames = options.hideUi() ? 1 : 5;
        for (int i = 0; i < frames; i++) {
            renderFrame(i == frames - 1);
        }
        return ExitCodes.OK;
    }

    // ---------------------------------------------------------------------------- interactive

    private int loop() {
        // Stand-in until the interface exists: the scene alone.
        viewer.open(options.file() != null ? options.file() : viewer.library().defaultModel());
        lastNanos = System.nanoTime();
        int status = ExitCodes.OK;
        AllocationMeter allocations = new AllocationMeter();
        while (!window.shouldClose() && !viewer.quitRequested()) {
            // The second half of a bounded run: the window, the model and the JIT have settled.
            if (options.exitAfterFrames() > 0 && frameNumber == options.exitAfterFrames() / 2) {
                allocations.start(frameNumber);
            }
            glfwPollEvents();
            if (player != null) {
                player.beforeFrame();
                if (player.failure() != null) {
                    err.println("skinlab: script failed: " + player.failure());
                    status = ExitCodes.INTERNAL;
                    break;
                }
            }
            boolean last = options.exitAfterFrames() > 0 && frameNumber + 1 >= options.exitAfterFrames();
            boolean drew = renderFrame(false);
            if (last) {
                if (!drew || !sceneHasPixels()) {
                    err.println("skinlab: nothing was drawn in " + options.exitAfterFrames() + " frames");
                    status = ExitCodes.INTERNAL;
                }
                break;
            }
        }
        if (options.exitAfterFrames() > 0 || player != null) {
            out.printf(java.util.Locale.ROOT, "skinlab: %d frames, %.0f fps (mean), model %s%s%n", frameNumber,
                    info.stats.fps.mean(), scene.shown() == null ? "none" : scene.shown().displayName(),
                    allocations.describe(frameNumber));
        }
        return status;
    }

    /** Prints what the debug context reported; true when there were errors. */
    private boolean reportGlErrors() {
        if (debugLog == null) {
            return false;
        }
        int n = debugLog.errorCount();
        for (String m : debugLog.messages()) {
            err.println("skinlab: GL error: " + m);
        }
        if (n > 0) {
            err.println("skinlab: " + n + " OpenGL error" + (n == 1 ? "" : "s") + " reported by the driver");
        } else {
            out.println("skinlab: no OpenGL errors reported (debug context)");
        }
        return n > 0;
    }

    /** A file dropped on the window (or by a script): opened, or its error shown. */
    void dropped(Path file) {
        viewer.open(file);
    }

    /**
     * Draws one frame: scene, then interface; writes the screenshot file when asked. Returns
     * whether a model frame was drawn.
     */
    private boolean renderFrame(boolean screenshot) {
        long now = System.nanoTime();
        info.frameMillis = (now - lastNanos) / 1e6;
        lastNanos = now;
        viewer.update();
        window.framebufferSize(size);
        info.width = size[0];
        info.height = size[1];
        glViewport(0, 0, size[0], size[1]);
        glClearColor(BACKGROUND[0], BACKGROUND[1], BACKGROUND[2], 1f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        ui.layOut(size[0], size[1], info.area);
        boolean drew = scene.paint(size[0], size[1], info.area);
        info.drewMesh = drew;
        frameNumber++;
        sample(drew);
        ui.render(info);
        if (screenshot) {
            writeScreenshot(options.screenshot());
        }
        window.swapBuffers();
        return drew;
    }

    /** Adds this frame's numbers to the live plots. */
    private void sample(boolean drew) {
        if (!drew || frameNumber < 2) {
            return;
        }
        float t = (float) ((System.nanoTime() - startNanos) / 1e9);
        float ms = (float) info.frameMillis;
        info.stats.frameMillis.add(t, ms);
        info.stats.fps.add(t, ms > 0 ? 1000f / ms : Float.NaN);
        if (info.gpuSkinned) {
            info.stats.skinningMillis.clear();
            info.stats.verticesPerSecond.add(t, ms > 0 ? info.vertices * (float) scene.instances() / ms / 1e3f : Float.NaN);
        } else {
            info.stats.skinningMillis.add(t, (float) (info.skinningNanos / 1e6));
            // The simulation skins one copy per step, whatever the instances drawn.
            info.stats.verticesPerSecond.add(t, (float) (info.vertices * scene.shown().mesh().stepRate() / 1e6));
        }
        info.stats.lbsVolume.add(t, (float) info.lbsVolume);
        info.stats.dqsVolume.add(t, (float) info.dqsVolume);
    }

    /** Whether the scene area holds any pixel other than the background. */
    private boolean sceneHasPixels() {
        int w = size[0];
        int h = size[1];
        ByteBuffer rgba = Screenshot.read(0, 0, w, h);
        try {
            return Screenshot.countPixelsDifferentFrom(rgba, w, h, BACKGROUND[0], BACKGROUND[1], BACKGROUND[2], 2) > 0;
        } finally {
            MemoryUtil.memFree(rgba);
        }
    }

    void writeScreenshot(Path file) {
        try {
            Screenshot.write(file, size[0], size[1]);
            viewer.setStatus("screenshot written: " + file);
        } catch (IOException e) {
            viewer.setStatus(e.getMessage());
        }
    }

    /** The window-side actions: those that need the window, a dialog or the file system. */
    void windowAction(ViewerAction action) {
        switch (action) {
            case SCREENSHOT:
                writeScreenshot(Path.of("skinlab-" + LocalDateTime.now().format(DateTimeFormatter.ofPattern(
                        "yyyyMMdd-HHmmss")) + ".png"));
                break;
            case OPEN_FILE:
                Path chosen = FileDialog.chooseModel();
                if (chosen != null) {
                    viewer.open(chosen);
                }
                break;
            case QUIT:
                window.requestClose();
                break;
            default:
                viewer.perform(action);
                break;
        }
    }

    @Override
    public void close() {
        scene.close();
        ui.close();
        viewer.close();
        input.close();
        if (debugLog != null) {
            debugLog.close();
        }
    }
}
