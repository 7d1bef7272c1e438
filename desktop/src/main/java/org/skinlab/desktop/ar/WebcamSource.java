package org.skinlab.desktop.ar;

import java.awt.Dimension;
import java.awt.image.BufferedImage;

import com.github.sarxos.webcam.Webcam;

import org.skinlab.ar.GrayImage;

/** The default webcam at 640x480 (webcam-capture); a clear error when there is none. */
public final class WebcamSource implements FrameSource {
    private final Webcam webcam;

    public WebcamSource() {
        Webcam found;
        try {
            found = Webcam.getDefault(3000);
        } catch (Exception | LinkageError e) {
            throw new IllegalStateException("no webcam found (" + e.getMessage() + ")");
        }
        if (found == null) {
            throw new IllegalStateException("no webcam found: connect one, or use --images DIR or --video FILE");
        }
        webcam = found;
        webcam.setViewSize(new Dimension(640, 480));
        if (!webcam.open()) {
            throw new IllegalStateException("the webcam " + webcam.getName() + " does not open");
        }
    }

    @Override
    public String name() {
        return webcam.getName();
    }

    @Override
    public int width() {
        return webcam.getViewSize().width;
    }

    @Override
    public int height() {
        return webcam.getViewSize().height;
    }

    @Override
    public double framesPerSecond() {
        return 30;
    }

    @Override
    public GrayImage next() {
        BufferedImage image = webcam.getImage();
        if (image == null) {
            throw new IllegalStateException("the webcam " + webcam.getName() + " delivered no image");
        }
        return GrayImages.of(image);
    }

    @Override
    public void close() {
        webcam.close();
    }
}
