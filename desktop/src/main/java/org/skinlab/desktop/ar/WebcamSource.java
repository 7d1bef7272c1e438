package org.skinlab.desktop.ar;

import java.awt.Dimension;
import java.awt.image.BufferedImage;

import com.github.sarxos.webcam.Webcam;

/**
 * The default webcam at 640x480 (webcam-capture; on Linux its native grabber needs libv4l2, Debian's
 * {@code libv4l-0}); a clear error when there is none.
 */
public final class WebcamSource implements FrameSource {
    private final Webcam webcam;

    public WebcamSource() {
        if (linuxWithoutVideoDevices()) {
            // Checked first: webcam-capture's native grabber prints its own errors when it finds nothing.
            throw new IllegalStateException("no webcam found (no /dev/video* device): connect one, or use --images DIR "
                    + "or --video FILE");
        }
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

    private static boolean linuxWithoutVideoDevices() {
        if (!System.getProperty("os.name", "").toLowerCase(java.util.Locale.ROOT).contains("linux")) {
            return false;
        }
        String[] devices = new java.io.File("/dev").list((d, n) -> n.startsWith("video"));
        return devices == null || devices.length == 0;
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
    public int frameCount() {
        return 0;
    }

    @Override
    public void next(CameraImage into) {
        BufferedImage image = webcam.getImage();
        if (image == null) {
            throw new IllegalStateException("the webcam " + webcam.getName() + " delivered no image");
        }
        CameraImages.fill(image, into, "the webcam " + webcam.getName());
    }

    @Override
    public void close() {
        webcam.close();
    }
}
