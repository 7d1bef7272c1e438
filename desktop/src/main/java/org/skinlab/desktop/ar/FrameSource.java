package org.skinlab.desktop.ar;

import java.io.IOException;

/**
 * Camera frames for {@code skinlab ar}: an image folder, a video file or a webcam. Each frame comes
 * as a {@link CameraImage}, its colour and its luminance filled from the same picture. Used from
 * one thread.
 */
public interface FrameSource extends AutoCloseable {
    /** What the status line calls it. */
    String name();

    int width();

    int height();

    /** How many frames per second it delivers (files: played at this rate; cameras: nominal). */
    double framesPerSecond();

    /** The frames before it loops (a file's), or 0 for a camera's endless stream. */
    int frameCount();

    /**
     * Fills {@code into} (of this source's size) with the next frame (files loop at their end);
     * IOException or IllegalArgumentException naming the file when one cannot be read.
     */
    void next(CameraImage into) throws IOException;

    @Override
    void close();
}
