package org.skinlab.desktop.ar;

import org.skinlab.ar.GrayImage;

/**
 * One camera frame in the two forms {@code skinlab ar} uses, both of the same instant: its colour,
 * which the window shows behind the model, and its luminance, which the tracker reads. A buffer:
 * a {@link FrameSource} fills it in place frame after frame (nothing allocated per frame), so it
 * belongs to one thread at a time; {@link ArFeed} hands it between its thread and the window's.
 */
public final class CameraImage {
    private final int width;
    private final int height;
    private final byte[] rgb;
    private final GrayImage gray;

    /** A black frame of {@code width x height}. */
    public CameraImage(int width, int height) {
        if (width <= 0 || height <= 0) {
            throw new IllegalArgumentException("bad camera image size: " + width + "x" + height);
        }
        this.width = width;
        this.height = height;
        this.rgb = new byte[3 * width * height];
        this.gray = GrayImage.blank(width, height);
    }

    public int width() {
        return width;
    }

    public int height() {
        return height;
    }

    /** The colour: R, G, B bytes (unsigned) per pixel, rows top first, no padding. */
    public byte[] rgb() {
        return rgb;
    }

    /** The luminance, as the tracker reads it (rows without padding). */
    public GrayImage gray() {
        return gray;
    }

    /** Throws unless this image is {@code width x height} (a source fills only images of its size). */
    void requireSize(int width, int height, String source) {
        if (this.width != width || this.height != height) {
            throw new IllegalArgumentException(source + " delivers " + width + "x" + height + " frames, not "
                    + this.width + "x" + this.height);
        }
    }
}
