package org.skinlab.desktop.ar;

import java.io.IOException;

import org.skinlab.ar.GrayImage;

/** Camera frames for {@code skinlab ar}: an image folder, a video file or a webcam. Used from one thread. */
public interface FrameSource extends AutoCloseable {
    /** What the status line calls it. */
    String name();

    int width();

    int height();

    /** How many frames per second it delivers (files: played at this rate; cameras: nominal). */
    double framesPerSecond();

    /** The next frame (files loop at their end); IOException or IllegalArgumentException naming the file when one cannot be read. */
    GrayImage next() throws IOException;

    @Override
    void close();
}
