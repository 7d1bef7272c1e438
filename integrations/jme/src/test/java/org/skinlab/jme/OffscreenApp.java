package org.skinlab.jme;

import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;

import com.jme3.app.SimpleApplication;
import com.jme3.asset.plugins.FileLocator;
import com.jme3.system.AppSettings;
import com.jme3.system.JmeContext;

/**
 * A jME application on an offscreen surface (LWJGL 3, OpenGL 3.3 core; a hidden GLFW window, so it
 * needs an X display: Xvfb in CI), for tests that drive it from their own thread with
 * {@link #call}. Starting it fails, with the renderer's error, when no context can be made:
 * a test run without a display fails rather than skips.
 */
final class OffscreenApp extends SimpleApplication {
    private final CountDownLatch started = new CountDownLatch(1);
    private final AtomicReference<Throwable> error = new AtomicReference<>();
    private final Path root;
    /** Frames updated and rendered so far; written by the render thread only. */
    private volatile long renderedFrames;

    private OffscreenApp(Path root) {
        super(new com.jme3.app.state.AppState[0]);
        this.root = root;
    }

    private static OffscreenApp shared;

    /**
     * The test JVM's one application, started on first use and left running: GLFW under Xvfb may
     * find no monitor when initialised again in the same process after a terminate.
     */
    static synchronized OffscreenApp shared() {
        if (shared == null) {
            shared = start(Paths.get("/"), 320, 240);
        }
        return shared;
    }

    /**
     * Starts an application whose asset manager also finds files under {@code root}.
     *
     * @throws IllegalStateException when it does not start within a minute, with the cause
     */
    static OffscreenApp start(Path root, int width, int height) {
        OffscreenApp app = new OffscreenApp(root);
        AppSettings settings = new AppSettings(true);
        settings.setRenderer(AppSettings.LWJGL_OPENGL33);
        settings.setResolution(width, height);
        settings.setSamples(0);
        settings.setAudioRenderer(null);
        app.setSettings(settings);
        app.setShowSettings(false);
        app.setPauseOnLostFocus(false);
        app.start(JmeContext.Type.OffscreenSurface);
        try {
            if (!app.started.await(60, TimeUnit.SECONDS) || app.error.get() != null) {
                app.stop();
                throw new IllegalStateException("jME's LWJGL 3 renderer did not start (is there an X display? "
                        + "run under xvfb-run -a)", app.error.get());
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException(e);
        }
        return app;
    }

    @Override
    public void simpleInitApp() {
        assetManager.registerLocator(root.toString(), FileLocator.class);
        SkinlabGltfExtension.register();
        started.countDown();
    }

    @Override
    public void handleError(String errorMessage, Throwable t) {
        error.compareAndSet(null, new IllegalStateException(errorMessage, t));
        started.countDown();
    }

    /** Runs {@code task} on the render thread at the start of a frame and returns its result. */
    <T> T call(Callable<T> task) {
        if (error.get() != null) {
            throw new IllegalStateException("the render thread failed earlier", error.get());
        }
        try {
            Object[] holder = enqueue(() -> new Object[] {task.call()}).get(120, TimeUnit.SECONDS);
            @SuppressWarnings("unchecked")
            T result = (T) holder[0];
            return result;
        } catch (Exception e) {
            Throwable cause = error.get() != null ? error.get() : e.getCause() != null ? e.getCause() : e;
            throw new IllegalStateException("on the render thread: " + cause, cause);
        }
    }

    /**
     * Waits until {@code n} more frames have been updated and rendered. Counted, not enqueued: jME
     * runs every task queued at the start of a frame in that frame, so tasks alone do not separate
     * frames.
     */
    void frames(int n) {
        long until = renderedFrames + n;
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(120);
        while (renderedFrames < until) {
            if (error.get() != null) {
                throw new IllegalStateException("the render thread failed", error.get());
            }
            if (System.nanoTime() > deadline) {
                throw new IllegalStateException("no frame rendered for two minutes");
            }
            try {
                Thread.sleep(2);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new IllegalStateException(e);
            }
        }
    }

    @Override
    public void update() {
        super.update();
        renderedFrames++;
    }
}
