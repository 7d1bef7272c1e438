package org.skinlab.desktop.ui;

/**
 * The part of the window the scene is drawn in: what the interface's panels leave free, in
 * framebuffer pixels with OpenGL's origin at the bottom left (so it can go straight to
 * {@code glViewport}). One instance, refilled every frame.
 */
public final class SceneArea {
    private int x;
    private int y;
    private int width;
    private int height;

    public void set(int x, int y, int width, int height) {
        this.x = x;
        this.y = y;
        this.width = Math.max(1, width);
        this.height = Math.max(1, height);
    }

    /** Pixels left of the area. */
    public int x() {
        return x;
    }

    /** Pixels below the area. */
    public int y() {
        return y;
    }

    public int width() {
        return width;
    }

    public int height() {
        return height;
    }
}
