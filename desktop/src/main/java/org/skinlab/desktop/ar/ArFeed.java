package org.skinlab.desktop.ar;

import java.util.Objects;

import org.skinlab.ar.ArPose;
import org.skinlab.ar.ArSession;
import org.skinlab.ar.GrayImage;

/**
 * The camera side of {@code skinlab ar}, on its own thread: takes frames from a {@link FrameSource}
 * at its rate, tracks each through the {@link ArSession}, and publishes the image with the pose
 * found in it as one {@link Shot} (a volatile reference: the window thread never pairs an image
 * with another frame's pose). Stops cleanly on {@link #close()}.
 */
public final class ArFeed implements AutoCloseable {
    /** One camera frame and the pose tracked in it. */
    public record Shot(GrayImage image, ArPose pose, long number) {
    }

    private final FrameSource source;
    private final ArSession session;
    private final Thread thread;
    private volatile boolean running = true;
    private volatile Shot latest;
    private volatile String failure;

    public ArFeed(FrameSource source, ArSession session) {
        this.source = Objects.requireNonNull(source);
        this.session = Objects.requireNonNull(session);
        thread = new Thread(this::run, "ar-feed");
        thread.setDaemon(true);
        thread.start();
    }

    /** The latest tracked frame, or null before the first. */
    public Shot latest() {
        return latest;
    }

    /** Why the feed stopped (an unreadable frame), or null while it runs. */
    public String failure() {
        return failure;
    }

    /** Waits until a frame is published (or the feed failed); false on timeout. */
    public boolean awaitFirst(long millis) throws InterruptedException {
        long end = System.nanoTime() + millis * 1_000_000L;
        while (latest == null && failure == null && System.nanoTime() < end) {
            Thread.sleep(2);
        }
        return latest != null;
    }

    private void run() {
        long period = (long) (1e9 / source.framesPerSecond());
        long next = System.nanoTime();
        long n = 0;
        try {
            while (running) {
                GrayImage image = source.next();
                long now = System.nanoTime();
                latest = new Shot(image, session.onCameraFrame(image, now), ++n);
                next += period;
                long wait = next - System.nanoTime();
                if (wait > 0) {
                    Thread.sleep(wait / 1_000_000L, (int) (wait % 1_000_000L));
                } else {
                    next = System.nanoTime();
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (Exception | OutOfMemoryError e) {
            // Shown in the status line; the window keeps running on the last frame.
            failure = e.getMessage() != null ? e.getMessage() : String.valueOf(e);
        }
    }

    @Override
    public void close() {
        running = false;
        thread.interrupt();
        try {
            thread.join(2000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        source.close();
    }
}
