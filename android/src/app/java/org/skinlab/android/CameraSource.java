package org.skinlab.android;

import java.util.Arrays;
import java.util.List;
import java.util.concurrent.Semaphore;
import java.util.concurrent.TimeUnit;

import android.content.Context;
import android.graphics.ImageFormat;
import android.graphics.Rect;
import android.graphics.SurfaceTexture;
import android.hardware.camera2.CameraAccessException;
import android.hardware.camera2.CameraCaptureSession;
import android.hardware.camera2.CameraCharacteristics;
import android.hardware.camera2.CameraDevice;
import android.hardware.camera2.CameraManager;
import android.hardware.camera2.CaptureRequest;
import android.media.Image;
import android.media.ImageReader;
import android.os.Handler;
import android.os.HandlerThread;
import android.util.Size;
import android.util.SizeF;
import android.view.Surface;

import org.skinlab.android.logic.IntrinsicsEstimate;
import org.skinlab.android.logic.YPlane;
import org.skinlab.ar.ArSession;
import org.skinlab.ar.CameraIntrinsics;
import org.skinlab.ar.GrayImage;

/**
 * The back camera through Camera2: a preview stream into the renderer's SurfaceTexture (the video
 * background) and a 640x480 YUV stream whose luminance plane the tracking thread hands to the
 * {@link ArSession}. Opened by {@link #open}, released by {@link #close} (the Activity's onPause),
 * both from the UI thread; camera callbacks run on their own thread, tracking on another. While the
 * camera is opening, {@link #close} waits for it (the device arrives in a callback and must then be
 * closed), as Camera2's own samples do; a session configured after close is closed at once.
 */
final class CameraSource {
    /** The analysed stream; the preview has the same 4:3 aspect at twice the size. */
    static final int WIDTH = 640;
    static final int HEIGHT = 480;

    interface Listener {
        /** The camera is open: its intrinsics for the analysed stream and its orientation on the sensor. */
        void onOpened(CameraIntrinsics intrinsics, int sensorOrientation);

        /** The camera failed or was taken away; the message is for the status line. */
        void onError(String message);
    }

    private final CameraManager manager;
    private final Listener listener;
    /** Held from openCamera until the device (or its failure) arrives, so close never misses a device. */
    private final Semaphore opening = new Semaphore(1);
    private volatile boolean closed;
    private HandlerThread cameraThread;
    private HandlerThread trackingThread;
    private volatile CameraDevice device;
    private volatile CameraCaptureSession capture;
    private volatile ImageReader reader;
    private volatile Surface previewSurface;
    private final YPlane yPlane = new YPlane();
    private volatile ArSession session;

    CameraSource(Context context, Listener listener) {
        this.manager = (CameraManager) context.getSystemService(Context.CAMERA_SERVICE);
        this.listener = listener;
    }

    /** Frames go to this session from now on (set before or after open). */
    void setSession(ArSession session) {
        this.session = session;
    }

    /** Opens the back camera; the caller holds the CAMERA permission. */
    void open(SurfaceTexture preview) {
        cameraThread = new HandlerThread("camera");
        cameraThread.start();
        trackingThread = new HandlerThread("tracking");
        trackingThread.start();
        Handler cameraHandler = new Handler(cameraThread.getLooper());
        Handler trackingHandler = new Handler(trackingThread.getLooper());
        try {
            String id = backCamera();
            CameraCharacteristics c = manager.getCameraCharacteristics(id);
            Integer orientation = c.get(CameraCharacteristics.SENSOR_ORIENTATION);
            listener.onOpened(intrinsics(c), orientation == null ? 90 : orientation);
            preview.setDefaultBufferSize(2 * WIDTH, 2 * HEIGHT);
            previewSurface = new Surface(preview);
            reader = ImageReader.newInstance(WIDTH, HEIGHT, ImageFormat.YUV_420_888, 2);
            reader.setOnImageAvailableListener(this::track, trackingHandler);
            if (!opening.tryAcquire(2500, TimeUnit.MILLISECONDS)) {
                listener.onError("the camera is still being opened or closed");
                return;
            }
            manager.openCamera(id, new CameraDevice.StateCallback() {
                @Override
                public void onOpened(CameraDevice camera) {
                    if (closed) {
                        camera.close();
                    } else {
                        device = camera;
                        startCapture(cameraHandler);
                    }
                    opening.release();
                }

                @Override
                public void onDisconnected(CameraDevice camera) {
                    camera.close();
                    device = null;
                    opening.release();
                    listener.onError("camera disconnected");
                }

                @Override
                public void onError(CameraDevice camera, int error) {
                    camera.close();
                    device = null;
                    opening.release();
                    listener.onError("camera error " + error);
                }
            }, cameraHandler);
        } catch (CameraAccessException | SecurityException | IllegalStateException e) {
            opening.release();
            listener.onError("cannot open the camera: " + e.getMessage());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /**
     * Stops the streams and releases the camera and both threads: the device once it has arrived,
     * the tracking thread before the reader whose images it reads.
     */
    void close() {
        closed = true;
        boolean held = false;
        try {
            held = opening.tryAcquire(2500, TimeUnit.MILLISECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        try {
            CameraCaptureSession c = capture;
            capture = null;
            if (c != null) {
                c.close();
            }
            CameraDevice d = device;
            device = null;
            if (d != null) {
                d.close();
            }
        } finally {
            if (held) {
                opening.release();
            }
        }
        quit(trackingThread);
        trackingThread = null;
        ImageReader r = reader;
        reader = null;
        if (r != null) {
            r.close();
        }
        quit(cameraThread);
        cameraThread = null;
        Surface p = previewSurface;
        previewSurface = null;
        if (p != null) {
            p.release();
        }
    }

    private static void quit(HandlerThread t) {
        if (t == null) {
            return;
        }
        t.quitSafely();
        try {
            t.join(2000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    // createCaptureSession(List, ...) is deprecated from API 30 on; its successor needs API 28 (min is 26).
    @SuppressWarnings("deprecation")
    private void startCapture(Handler handler) {
        CameraDevice d = device;
        ImageReader r = reader;
        if (d == null || r == null || previewSurface == null) {
            return;
        }
        try {
            List<Surface> targets = Arrays.asList(previewSurface, r.getSurface());
            d.createCaptureSession(targets, new CameraCaptureSession.StateCallback() {
                @Override
                public void onConfigured(CameraCaptureSession s) {
                    CameraDevice d = device;
                    ImageReader r = reader;
                    Surface p = previewSurface;
                    if (closed || d == null || r == null || p == null) {
                        s.close();
                        return;
                    }
                    capture = s;
                    try {
                        CaptureRequest.Builder b = d.createCaptureRequest(CameraDevice.TEMPLATE_PREVIEW);
                        b.addTarget(p);
                        b.addTarget(r.getSurface());
                        b.set(CaptureRequest.CONTROL_AF_MODE, CaptureRequest.CONTROL_AF_MODE_CONTINUOUS_VIDEO);
                        s.setRepeatingRequest(b.build(), null, handler);
                    } catch (CameraAccessException | IllegalStateException e) {
                        listener.onError("cannot start the camera: " + e.getMessage());
                    }
                }

                @Override
                public void onConfigureFailed(CameraCaptureSession s) {
                    listener.onError("the camera refused the preview and tracking streams");
                }
            }, handler);
        } catch (CameraAccessException | IllegalStateException e) {
            listener.onError("cannot start the camera: " + e.getMessage());
        }
    }

    /** On the tracking thread: the newest frame's Y plane through the session; older frames are dropped. */
    private void track(ImageReader r) {
        Image image = r.acquireLatestImage();
        if (image == null) {
            return;
        }
        try {
            ArSession s = session;
            if (s != null) {
                Image.Plane y = image.getPlanes()[0];
                GrayImage gray = yPlane.copy(y.getBuffer(), y.getRowStride(), y.getPixelStride(), image.getWidth(),
                        image.getHeight());
                s.onCameraFrame(gray, image.getTimestamp());
            }
        } finally {
            image.close();
        }
    }

    private String backCamera() throws CameraAccessException {
        String[] ids = manager.getCameraIdList();
        for (String id : ids) {
            Integer facing = manager.getCameraCharacteristics(id).get(CameraCharacteristics.LENS_FACING);
            if (facing != null && facing == CameraCharacteristics.LENS_FACING_BACK) {
                return id;
            }
        }
        if (ids.length == 0) {
            throw new IllegalStateException("this device has no camera");
        }
        return ids[0];
    }

    private static CameraIntrinsics intrinsics(CameraCharacteristics c) {
        float[] calibration = c.get(CameraCharacteristics.LENS_INTRINSIC_CALIBRATION);
        Rect active = c.get(CameraCharacteristics.SENSOR_INFO_ACTIVE_ARRAY_SIZE);
        Rect preCorrection = c.get(CameraCharacteristics.SENSOR_INFO_PRE_CORRECTION_ACTIVE_ARRAY_SIZE);
        float[] focal = c.get(CameraCharacteristics.LENS_INFO_AVAILABLE_FOCAL_LENGTHS);
        SizeF physical = c.get(CameraCharacteristics.SENSOR_INFO_PHYSICAL_SIZE);
        Size pixelArray = c.get(CameraCharacteristics.SENSOR_INFO_PIXEL_ARRAY_SIZE);
        if (active == null) {
            return IntrinsicsEstimate.estimate(null, 0, 0, Double.NaN, Double.NaN, WIDTH, HEIGHT);
        }
        if (calibration != null && calibration.length >= 4 && preCorrection != null) {
            // The calibration's principal point is in the pre-correction array: move it into the active one.
            calibration = calibration.clone();
            calibration[2] -= active.left - preCorrection.left;
            calibration[3] -= active.top - preCorrection.top;
        }
        // The physical size is the whole pixel array's; the active array is part of it, at the same pitch.
        double activeWidthMm = physical == null || pixelArray == null || pixelArray.getWidth() <= 0 ? Double.NaN
                : physical.getWidth() * active.width() / pixelArray.getWidth();
        return IntrinsicsEstimate.estimate(calibration, active.width(), active.height(),
                focal == null || focal.length == 0 ? Double.NaN : focal[0], activeWidthMm, WIDTH, HEIGHT);
    }
}
