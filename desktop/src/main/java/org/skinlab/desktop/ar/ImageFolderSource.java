package org.skinlab.desktop.ar;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;

import org.skinlab.ar.GrayImage;

/** The images of a folder in name order, decoded one at a time, looping. */
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
        GrayImage first = GrayImages.read(files.get(0));
        this.width = first.width();
        this.height = first.height();
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
    public GrayImage next() throws IOException {
        Path file = files.get(index);
        index = (index + 1) % files.size();
        GrayImage image = GrayImages.read(file);
        if (image.width() != width || image.height() != height) {
            throw new IllegalArgumentException(file + " is " + image.width() + "x" + image.height() + ", the folder's first image "
                    + width + "x" + height + ": one camera, one size");
        }
        return image;
    }

    @Override
    public void close() {
    }
}
