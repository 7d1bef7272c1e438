package org.skinlab.android.logic;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;

/**
 * The GPU part's handshake: the measuring thread waits while a stand-in GL thread draws, the
 * frames per second are the frames after the warm-up over the time they took (clock values given
 * by hand: the counting is checked exactly), a GL thread that draws nothing or cannot draw ends
 * the wait with the reason, an interrupt withdraws the request.
 */
class DrawnCopiesTest {
    /** Waits for the measuring thread's request, as the GL thread finds it at its next frame. */
    private static DrawnCopies.Request awaitRequest(DrawnCopies copies) throws InterruptedException {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        while (copies.current() == null) {
            assertTrue(System.nanoTime() < end, "no request");
            Thread.sleep(1);
        }
        return copies.current();
    }

    @Test
    void theRateIsTheFramesAfterTheWarmUpOverTheirTime() throws Exception {
        DrawnCopies copies = new DrawnCopies(10);
        CompletableFuture<DrawnCopies.Run> run = CompletableFuture.supplyAsync(() -> draw(copies, 3, 0.1));
        DrawnCopies.Request r = awaitRequest(copies);
        assertTrue(r.copies().isEmpty());
        long t = 1_000_000_000L;
        // 3 warm-up frames 50 ms apart (not counted), then frames 10 ms apart: the timing starts when
        // the third ends; 0.1 s later 10 frames have finished.
        for (int i = 0; i < 3; i++) {
            copies.drawn(r, t += 50_000_000L);
        }
        for (int i = 0; i < 9; i++) {
            copies.drawn(r, t += 10_000_000L);
            assertSame(r, copies.current(), "still drawn after " + (i + 1) + " timed frames");
        }
        copies.drawn(r, t += 10_000_000L);
        DrawnCopies.Run result = run.get(10, TimeUnit.SECONDS);
        assertEquals(10, result.frames());
        assertEquals(0.1, result.seconds(), 1e-9);
        assertEquals(100, result.fps(), 1e-6);
        assertNull(copies.current(), "done: the GL thread draws what it otherwise does");
    }

    @Test
    void atLeastFiveFramesAreTimedHoweverLongTheyTake() throws Exception {
        DrawnCopies copies = new DrawnCopies(10);
        CompletableFuture<DrawnCopies.Run> run = CompletableFuture.supplyAsync(() -> draw(copies, 0, 0.001));
        DrawnCopies.Request r = awaitRequest(copies);
        long t = 0;
        for (int i = 0; i < 5; i++) {
            copies.drawn(r, t += 400_000_000L);
        }
        assertFalse(run.isDone(), "the first frame only starts the clock without warm-up frames");
        copies.drawn(r, t += 400_000_000L);
        assertEquals(5, run.get(10, TimeUnit.SECONDS).frames());
        assertEquals(2.5, run.get().fps(), 1e-9);
    }

    @Test
    void noFrameForTheWaitEndsItSayingWhy() {
        DrawnCopies copies = new DrawnCopies(0.2);
        long start = System.nanoTime();
        DrawnCopies.Undrawable e = assertThrows(DrawnCopies.Undrawable.class, () -> copies.draw(List.of(), 2, 0.1));
        assertTrue((System.nanoTime() - start) / 1e9 < 5, "gave up within the wait");
        assertTrue(e.getMessage().contains("drew no frame in 0.2 s"), e.getMessage());
        assertNull(copies.current(), "the request is withdrawn");
        assertFalse(copies.gpu().known());
        assertTrue(copies.gpu().unavailable().contains("no GL context"), copies.gpu().unavailable());
        copies.glStrings("Mali-G78", "ARM", "OpenGL ES 3.2");
        assertEquals("Mali-G78", copies.gpu().renderer());
    }

    @Test
    void aGlThreadThatCannotDrawSaysWhy() throws Exception {
        DrawnCopies copies = new DrawnCopies(10);
        CompletableFuture<DrawnCopies.Run> run = CompletableFuture.supplyAsync(() -> draw(copies, 2, 0.1));
        copies.undrawable(awaitRequest(copies), "the GL driver refused the app's shaders: 0:1 error");
        ExecutionException e = assertThrows(ExecutionException.class, () -> run.get(10, TimeUnit.SECONDS));
        assertTrue(e.getCause().getMessage().contains("refused the app's shaders"), e.getCause().toString());
    }

    @Test
    void anInterruptWithdrawsTheRequest() throws Exception {
        DrawnCopies copies = new DrawnCopies(60);
        Thread[] measuring = new Thread[1];
        CompletableFuture<Throwable> thrown = CompletableFuture.supplyAsync(() -> {
            measuring[0] = Thread.currentThread();
            try {
                copies.draw(List.of(), 2, 10);
                return null;
            } catch (Exception e) {
                return e;
            }
        });
        awaitRequest(copies);
        measuring[0].interrupt();
        assertTrue(thrown.get(10, TimeUnit.SECONDS) instanceof InterruptedException);
        assertNull(copies.current());
    }

    @Test
    void theGlThreadKeepsTheCopiesBuffersWhileAMeasurementRuns() {
        DrawnCopies copies = new DrawnCopies(1);
        assertFalse(copies.measuring());
        copies.begin();
        assertTrue(copies.measuring());
        copies.end();
        assertFalse(copies.measuring());
    }

    private static DrawnCopies.Run draw(DrawnCopies copies, int warmupFrames, double seconds) {
        try {
            return copies.draw(List.of(), warmupFrames, seconds);
        } catch (Exception e) {
            throw new IllegalStateException(e.getMessage(), e);
        }
    }
}
