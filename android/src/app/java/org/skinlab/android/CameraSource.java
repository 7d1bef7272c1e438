package org.skinlab.android;

import java.nio.ByteBuffer;
import java.util.Arrays;

import android.graphics.ImageFormat;
import android.graphics.Rect;
import android.graphics.SurfaceTexture;
import android.hardware.camera2.CameraAccessException;
import android.hardware.camera2.CameraCaptureSession;
import android.hardware.camera2.CameraCharacteristics;
import android.hardware.camera2.CameraDevice;
import android.hardware.camera2.CameraManager;
import android.hardware.camera2.CaptureRequest;
import android.hardware.camera2.params.StreamConfigurationMap;
import android.media.Image;
import android.media.ImageReader;
import android.os.Build;
import android.os.Handler;
import android.util.Size;
import android.util.SizeF;
import android.view.Surface;

import org.skinlab.android.logic.CameraReport;
import org.skinlab.android.logic.FocusMode;
import org.skinlab.android.logic.IntrinsicsEstimate;
import org.skinlab.android.logic.StatusLine;
import org.skinlab.android.logic.StreamSizes;
import org.skinlab.android.logic.YPlane;
import org.skinlab.ar.ArSession;
import org.skinlab.ar.CameraIntrinsics;
import org.skinlab.ar.GrayImage;

/**
 * The back camera through Camera2: a preview stream into the renderer's SurfaceTexture (the video
 * background) and a YUV stream of the same aspect ({@link StreamSizes}) whose luminance plane the
 * tracking thread hands to the {@link ArSession}.
 *
 * <p>Threads: {@link #open} and {@link #close} may be called from any thread (the Activity calls
 * them from the UI thread) and return at once; all camera work, and every Camera2 callback, runs
 * on the camera thread, one message after another, so that no state is shared between threads but
 * the session and the closed flag. Closing before the device has arrived is therefore simple: the
 * device is closed as soon as it arrives. Frames are analysed on the tracking thread, which also
 * closes the ImageReader, so that no frame is being read while its buffer goes away. Every failure
 * on either thread, whatever its type, goes to the listener as a message, never up the thread.
 */
final class CameraSource {
    /** What the Activity hears, on the camera or the tracking thread. */
    interface Listener {
        /** {@code source}'s camera is open: the analysed stream's intrinsics and the sensor's orientation. */
        void onOpened(CameraSource source, CameraIntrinsics intrinsics, int sensorOrientation);

        /** Something failed or was taken away; the message is for the status line. */
        void onProblem(String message);
    }

    /** Without a stream map (not a real Camera2 device): the sizes every camera has offered. */
    private static final StreamSizes FALLBACK_SIZES = new StreamSizes(640, 480, 1280, 960, true);

    private final CameraManager manager;
    private final Handler cameraThread;
    private final Handler trackingThread;
    private final Listener listener;
    private final YPlane yPlane = new YPlane();
    private volatile boolean closed;
    private volatile ArSession session;
    // Camera thread only.
    private CameraDevice device;
    private CameraCaptureSession capture;
    private ImageReader reader;
    private Surface previewSurface;
    private int focusMode = -1;
    /** Whether the requests turn the device's distortion correction off (IntrinsicsEstimate#correctionOff). */
    private boolean correctionOff;

    CameraSource(CameraManager manager, Handler cameraThread, Handler trackingThread, Listener listener) {
        this.manager = manager;
        this.cameraThread = cameraThread;
        this.trackingThread = trackingThread;
        this.listener = listener;
    }

    /** Frames go to this session from now on (set before or after open). */
    void setSession(ArSession session) {
        this.session = session;
    }

    /** Opens the back camera onto {@code preview}; the caller holds the CAMERA permission. */
    void open(SurfaceTexture preview) {
        cameraThread.post(() -> guarded("cannot open the camera", () -> openNow(preview)));
    }

    /**
     * Stops the streams and releases the camera; returns at once. The device is closed on the
     * camera thread (at once, or when it arrives), the ImageReader on the tracking thread.
     */
    void close() {
        closed = true;
        cameraThread.post(() -> guarded("closing the camera", this::closeNow));
    }

    private void openNow(SurfaceTexture preview) throws CameraAccessException {
        if (closed) {
            return;
        }
        String id = backCamera();
        CameraCharacteristics c = manager.getCameraCharacteristics(id);
        StreamConfigurationMap map = c.get(CameraCharacteristics.SCALER_STREAM_CONFIGURATION_MAP);
        StreamSizes sizes = map == null ? FALLBACK_SIZES
                : StreamSizes.choose(pairs(map.getOutputSizes(ImageFormat.YUV_420_888)),
                        pairs(map.getOutputSizes(SurfaceTexture.class)));
        IntrinsicsEstimate estimate = IntrinsicsEstimate.of(geometry(c), sizes.trackingWidth(), sizes.trackingHeight());
        // The listener keeps one camera problem: both notes in one.
        String notes = StatusLine.joined(sizes.sameAspect() ? null : sizes.problem(), estimate.problem());
        if (notes != null) {
            report(notes);
        }
        CameraIntrinsics intrinsics = estimate.intrinsics();
        correctionOff = estimate.correctionOff();
        Integer orientation = c.get(CameraCharacteristics.SENSOR_ORIENTATION);
        focusMode = FocusMode.choose(c.get(CameraCharacteristics.CONTROL_AF_AVAILABLE_MODES));
        preview.setDefaultBufferSize(sizes.previewWidth(), sizes.previewHeight());
        previewSurface = new Surface(preview);
        reader = ImageReader.newInstance(sizes.trackingWidth(), sizes.trackingHeight(), ImageFormat.YUV_420_888, 2);
        reader.setOnImageAvailableListener(this::onImage, trackingThread);
        manager.openCamera(id, new CameraDevice.StateCallback() {
            @Override
            public void onOpened(CameraDevice camera) {
                guarded("cannot start the camera", () -> {
                    if (closed) {
                        camera.close();
                        return;
                    }
                    device = camera;
                    listener.onOpened(CameraSource.this, intrinsics, orientation == null ? 90 : orientation);
                    startCapture();
                });
            }

            @Override
            public void onDisconnected(CameraDevice camera) {
                guarded("camera disconnected", () -> {
                    lost(camera);
                    report("the camera was disconnected (another app may be using it)");
                });
            }

            @Override
            public void onError(CameraDevice camera, int error) {
                guarded("camera error", () -> {
                    lost(camera);
                    report("camera error " + error + " (" + describe(error) + ")");
                });
            }
        }, cameraThread);
    }

    /** A device that failed or went away: closed, and forgotten if it is ours. */
    private void lost(CameraDevice camera) {
        camera.close();
        if (device == camera) {
            device = null;
            capture = null;
        }
    }

    // createCaptureSession(List, ...) is deprecated from API 30 on; its successor needs API 28 (min is 26).
    @SuppressWarnings("deprecation")
    private void startCapture() throws CameraAccessException {
        device.createCaptureSession(Arrays.asList(previewSurface, reader.getSurface()),
                new CameraCaptureSession.StateCallback() {
                    @Override
                    public void onConfigured(CameraCaptureSession s) {
                        guarded("cannot start the camera", () -> repeat(s));
                    }

                    @Override
                    public void onConfigureFailed(CameraCaptureSession s) {
                        report("the camera refused the preview and tracking streams");
                    }
                }, cameraThread);
    }

    private void repeat(CameraCaptureSession s) throws CameraAccessException {
        if (closed || device == null) {
            s.close();
            return;
        }
        capture = s;
        CaptureRequest.Builder b = device.createCaptureRequest(CameraDevice.TEMPLATE_PREVIEW);
        b.addTarget(previewSurface);
        b.addTarget(reader.getSurface());
        if (focusMode >= 0) {
            b.set(CaptureRequest.CONTROL_AF_MODE, focusMode);
        }
        // The intrinsics carry the lens only if the streams are the raw optics (IntrinsicsEstimate).
        if (correctionOff && Build.VERSION.SDK_INT >= 28) {
            b.set(CaptureRequest.DISTORTION_CORRECTION_MODE, CaptureRequest.DISTORTION_CORRECTION_MODE_OFF);
        }
        s.setRepeatingRequest(b.build(), null, cameraThread);
    }

    private void closeNow() {
        try {
            if (capture != null) {
                capture.close();
            }
            if (device != null) {
                device.close();
            }
        } finally {
            capture = null;
            device = null;
            ImageReader r = reader;
            reader = null;
            if (r != null) {
                r.setOnImageAvailableListener(null, null);
                trackingThread.post(r::close); // after the frame being analysed, if any
            }
            if (previewSurface != null) {
                previewSurface.release();
                previewSurface = null;
            }
        }
    }

    /** On the tracking thread: the newest frame's luminance through {@link #track}; older frames are dropped. */
    private void onImage(ImageReader r) {
        guarded("reading a camera frame", () -> {
            Image image = r.acquireLatestImage();
            if (image == null) {
                return;
            }
            try {
                Image.Plane y = image.getPlanes()[0];
                track(y.getBuffer(), y.getRowStride(), y.getPixelStride(), image.getWidth(), image.getHeight(),
                        image.getTimestamp());
            } finally {
                image.close();
            }
        });
    }

    /**
     * On the tracking thread: one frame's luminance plane (Y of YUV_420_888, strides as the camera
     * wrote them), copied out and tracked in the current session. Every camera frame arrives here.
     */
    void track(ByteBuffer plane, int rowStride, int pixelStride, int width, int height, long timestampNanos) {
        guarded("tracking", () -> {
            ArSession s = session;
            if (s != null && !closed) {
                GrayImage gray = yPlane.copy(plane, rowStride, pixelStride, width, height);
                s.onCameraFrame(gray, timestampNanos);
            }
        });
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

    private static int[][] pairs(Size[] sizes) {
        if (sizes == null) {
            return new int[0][];
        }
        int[][] pairs = new int[sizes.length][];
        for (int i = 0; i < sizes.length; i++) {
            pairs[i] = new int[] {sizes[i].getWidth(), sizes[i].getHeight()};
        }
        return pairs;
    }

    /**
     * The camera's geometry as Camera2 reports it, every key read only at the API levels that have
     * it; what it means is {@link IntrinsicsEstimate}'s to decide.
     */
    // LENS_RADIAL_DISTORTION is deprecated from API 28 on, where LENS_DISTORTION is read instead.
    @SuppressWarnings("deprecation")
    static CameraReport geometry(CameraCharacteristics c) {
        float[] lens = null;
        float[] radial = null;
        int[] modes = null;
        if (Build.VERSION.SDK_INT >= 28) {
            lens = c.get(CameraCharacteristics.LENS_DISTORTION);
            modes = c.get(CameraCharacteristics.DISTORTION_CORRECTION_AVAILABLE_MODES);
        } else {
            radial = c.get(CameraCharacteristics.LENS_RADIAL_DISTORTION);
        }
        Rect active = c.get(CameraCharacteristics.SENSOR_INFO_ACTIVE_ARRAY_SIZE);
        float[] focal = c.get(CameraCharacteristics.LENS_INFO_AVAILABLE_FOCAL_LENGTHS);
        SizeF physical = c.get(CameraCharacteristics.SENSOR_INFO_PHYSICAL_SIZE);
        Size pixelArray = c.get(CameraCharacteristics.SENSOR_INFO_PIXEL_ARRAY_SIZE);
        // The physical size is the whole pixel array's; the active array is part of it, at the same pitch.
        double activeWidthMm = active == null || physical == null || pixelArray == null || pixelArray.getWidth() <= 0
                ? Double.NaN : physical.getWidth() * active.width() / pixelArray.getWidth();
        return new CameraReport(Build.VERSION.SDK_INT,
                rect(c.get(CameraCharacteristics.SENSOR_INFO_PRE_CORRECTION_ACTIVE_ARRAY_SIZE)), rect(active),
                c.get(CameraCharacteristics.LENS_INTRINSIC_CALIBRATION), lens, radial, modes,
                focal == null || focal.length == 0 ? Double.NaN : focal[0], activeWidthMm);
    }

    private static int[] rect(Rect r) {
        return r == null ? null : new int[] {r.left, r.top, r.right, r.bottom};
    }

    private static String describe(int error) {
        switch (error) {
            case CameraDevice.StateCallback.ERROR_CAMERA_IN_USE:
                return "in use by another app";
            case CameraDevice.StateCallback.ERROR_MAX_CAMERAS_IN_USE:
                return "too many cameras open";
            case CameraDevice.StateCallback.ERROR_CAMERA_DISABLED:
                return "disabled by a device policy";
            case CameraDevice.StateCallback.ERROR_CAMERA_DEVICE:
                return "the camera device failed";
            case CameraDevice.StateCallback.ERROR_CAMERA_SERVICE:
                return "the camera service failed";
            default:
                return "unknown";
        }
    }

    /** Tells the listener, unless this source is closed: its problems are then nobody's. */
    private void report(String problem) {
        if (!closed) {
            listener.onProblem(problem);
        }
    }

    /** A step that may fail in any way. */
    private interface Step {
        void run() throws Exception;
    }

    /**
     * Runs a step on a camera or tracking thread, reporting whatever it throws: an exception there
     * would end the thread, and on a phone the app.
     */
    private void guarded(String what, Step step) {
        try {
            step.run();
        } catch (Throwable e) { // errors too: a NoSuchMethodError or an OutOfMemoryError must not end the app
            report(what + ": " + (e.getMessage() != null ? e.getMessage() : e.getClass().getSimpleName()));
        }
    }
}
