package org.skinlab.desktop.ar;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;

/** The images of a folder in name order, decoded one at a time, looping; colour as the files hold it. */
public final class ImageFolderSource implements FrameSource {
    private final Path dir;
    private final List<Path> files;
    private final double fps;
    private final int width;
    private final int height;
    private int index;

    public ImageFolderSource(Path dir, double fps) throws IOException {
        this.dir = dir;
        this.files = GrayImages.list(dir);
        this.fps = fps;
        BufferedImage first = GrayImages.decode(files.get(0));
        this.width = first.getWidth();
        this.height = first.getHeight();
    }

    @Override
    public String name() {
        return dir.getFileName() + " (" + files.size() + " images)";
    }

    @Override
    public int width() {
        return width;
    }

    @Override
    public int height() {
        return height;
    }

    @Override
    public double framesPerSecond() {
        return fps;
    }

    @Override
    public int frameCount() {
        return files.size();
    }

    @Override
    public void next(CameraImage into) {
        Path file = files.get(index);
        index = (index + 1) % files.size();
        BufferedImage image = GrayImages.decode(file);
        if (image.getWidth() != width || image.getHeight() != height) {
            throw new IllegalArgumentException(file + " is " + image.getWidth() + "x" + image.getHeight()
                    + ", the folder's first image " + width + "x" + height + ": one camera, one size");
        }
        CameraImages.fill(image, into, file.toString());
    }

    @Override
    public void close() {
    }
}
