package org.skinlab.desktop.ar;

import java.util.Objects;
import java.util.concurrent.atomic.AtomicReference;

import org.skinlab.ar.ArPose;
import org.skinlab.ar.ArSession;

/**
 * The camera side of {@code skinlab ar}, on its own thread: takes frames from a {@link FrameSource}
 * at its rate, tracks each one's luminance through the {@link ArSession}, and publishes its colour
 * with the pose found in it as one {@link Shot}, so the window never pairs a picture with another
 * frame's pose. Stops cleanly on {@link #close()}.
 *
 * <p><b>Three images, no copies.</b> The feed fills {@link CameraImage}s in place, and a triple
 * buffer hands them over: one is being filled, one waits as the newest shot, one is the window's.
 * Publishing swaps the filled one for the waiting one ({@code getAndSet}); the window's
 * {@link #newest} swaps its own for the waiting one when that is newer. Each image is thus held by
 * exactly one side at any time: the feed never writes a picture the window is uploading, neither
 * side waits for the other, and nothing is allocated per frame but the shot and the pose. One
 * window thread takes shots (a second is refused, as {@link ArSession} refuses a second feeder).
 */
public final class ArFeed implements AutoCloseable {
    /**
     * One camera frame and the pose tracked in it, numbered from 1. Its image is lent to the thread
     * that took the shot from {@link #newest} until that thread's next call, which may give it back
     * to the feed.
     */
    public record Shot(CameraImage image, ArPose pose, long number) {
    }

    private final FrameSource source;
    private final ArSession session;
    private final Thread thread;
    /** The newest shot, or a numbered-0 placeholder before the first: the triple buffer's middle. */
    private final AtomicReference<Shot> waiting;
    private final AtomicReference<Thread> taker = new AtomicReference<>();
    /** The feed thread's image to fill. */
    private CameraImage filling;
    /** The taking thread's shot (number 0 before its first). */
    private Shot taken;
    private volatile long published;
    private volatile boolean running = true;
    private volatile String failure;

    public ArFeed(FrameSource source, ArSession session) {
        this.source = Objects.requireNonNull(source);
        this.session = Objects.requireNonNull(session);
        filling = new CameraImage(source.width(), source.height());
        waiting = new AtomicReference<>(new Shot(new CameraImage(source.width(), source.height()), ArPose.NONE, 0));
        taken = new Shot(new CameraImage(source.width(), source.height()), ArPose.NONE, 0);
        thread = new Thread(this::run, "ar-feed");
        thread.setDaemon(true);
        thread.start();
    }

    /**
     * The newest tracked frame, or null before the first; from one thread only (the window's). A
     * newer frame than the last one returned is taken in exchange for that one, whose image the
     * caller must not read any more; otherwise the last one comes back.
     *
     * @throws IllegalStateException when called from a second thread
     */
    public Shot newest() {
        Thread me = Thread.currentThread();
        Thread owner = taker.compareAndSet(null, me) ? me : taker.get();
        if (owner != me) {
            throw new IllegalStateException("camera shots taken on " + me.getName() + " while " + owner.getName()
                    + " takes them");
        }
        // Only this thread puts older shots into the middle, so one that is newer here stays newer.
        if (waiting.get().number() > taken.number()) {
            taken = waiting.getAndSet(taken);
        }
        return taken.number() == 0 ? null : taken;
    }

    /** Why the feed stopped (an unreadable frame), or null while it runs. */
    public String failure() {
        return failure;
    }

    /** Waits until a frame is published (or the feed failed); false on timeout. Any thread. */
    public boolean awaitFirst(long millis) throws InterruptedException {
        long end = System.nanoTime() + millis * 1_000_000L;
        while (published == 0 && failure == null && System.nanoTime() < end) {
            Thread.sleep(2);
        }
        return published > 0;
    }

    private void run() {
        long period = (long) (1e9 / source.framesPerSecond());
        long next = System.nanoTime();
        long n = 0;
        try {
            while (running) {
                source.next(filling);
                long now = System.nanoTime();
                Shot shot = new Shot(filling, session.onCameraFrame(filling.gray(), now), ++n);
                filling = waiting.getAndSet(shot).image();
                published = n;
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
