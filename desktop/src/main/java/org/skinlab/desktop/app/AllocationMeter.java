package org.skinlab.desktop.app;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.Locale;

/**
 * Bytes the window's thread allocates per frame, from the JVM's per-thread counter (HotSpot's
 * {@code com.sun.management.ThreadMXBean}); reported when a bounded run ends, so a regression
 * in the render loop's "allocates nothing" shows up in every CI log.
 */
final class AllocationMeter {
    private final com.sun.management.ThreadMXBean threads;
    private final long thread = Thread.currentThread().getId();
    private long startBytes = -1;
    private long startFrame;

    AllocationMeter() {
        ThreadMXBean bean = ManagementFactory.getThreadMXBean();
        threads = bean instanceof com.sun.management.ThreadMXBean ? (com.sun.management.ThreadMXBean) bean : null;
    }

    void start(long frame) {
        if (threads != null && threads.isThreadAllocatedMemorySupported()) {
            startFrame = frame;
            startBytes = threads.getThreadAllocatedBytes(thread);
        }
    }

    /** ", N bytes allocated per frame over the last M frames", or "" when not measured. */
    String describe(long frame) {
        if (startBytes < 0 || frame <= startFrame) {
            return "";
        }
        long bytes = threads.getThreadAllocatedBytes(thread) - startBytes;
        return String.format(Locale.ROOT, ", %.0f bytes allocated per frame by the render loop over the last %d frames",
                (double) bytes / (frame - startFrame), frame - startFrame);
    }
}
