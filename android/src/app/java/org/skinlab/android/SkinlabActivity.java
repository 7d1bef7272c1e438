package org.skinlab.android;

import java.io.File;
import java.io.IOException;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import android.Manifest;
import android.app.Activity;
import android.content.Intent;
import android.content.pm.PackageManager;
import android.content.res.Configuration;
import android.graphics.SurfaceTexture;
import android.hardware.camera2.CameraManager;
import android.hardware.display.DisplayManager;
import android.opengl.GLSurfaceView;
import android.os.Bundle;
import android.os.Handler;
import android.os.HandlerThread;
import android.os.Looper;
import android.view.Surface;
import android.view.View;

import org.skinlab.android.logic.AppActions;
import org.skinlab.android.logic.DrawnCopies;
import org.skinlab.android.logic.MarkerSize;
import org.skinlab.android.logic.MeasureProtocol;
import org.skinlab.android.logic.MixerControl;
import org.skinlab.android.logic.ModelLoader;
import org.skinlab.android.logic.ModelCatalog;
import org.skinlab.android.logic.PermissionFlow;
import org.skinlab.android.logic.SavedChoices;
import org.skinlab.android.logic.StatusLine;
import org.skinlab.ar.ArSession;
import org.skinlab.ar.CameraIntrinsics;
import org.skinlab.ar.FiducialTracker;
import org.skinlab.ar.MarkerScene;
import org.skinlab.ar.TrackerConfig;
import org.skinlab.simulation.AnimationConfig;
import org.skinlab.simulation.SkeletalAnimatedMesh;
import org.skinlab.skinning.CentresOfRotation;

/**
 * The AR app's one Activity: the camera image with the animated character standing on the printed
 * marker (docs/marker: ArUco MIP_36h12 id 0, 100 mm by default; a button steps through other
 * printed sizes), a status line, a button for every user function of the thesis
 * ({@link AppActions}; the views are {@link ArControls}), the mixer's cross-fade and root motion
 * ({@link MixerControl}), and "Measure" ({@link MeasureControl}): the bundled models timed on this
 * phone into {@code results-android.json}. The launch intent's extra {@value MeasureProtocol#EXTRA}
 * = "quick" makes that a quick measurement (seconds; not figures to quote).
 *
 * <p>Threads: the UI thread (this class; it never waits on another thread), the GL thread
 * ({@link ArRenderer}), the camera and tracking threads (made here, used by each
 * {@link CameraSource}), the simulation thread ({@link SkeletalAnimatedMesh}), one loader
 * thread for models, and a measurement's threads. onPause closes the camera, stops the simulation
 * and a measurement; onResume starts the first two again, the camera once the renderer's surface
 * is ready. While a measurement runs it holds the camera and the simulation off and the GL thread
 * draws its copies. onDestroy ends every thread it started.
 */
public final class SkinlabActivity extends Activity {
    private static final int CAMERA_REQUEST = 1;
    private static final int SAVE_REQUEST = 2;

    private final AnimationConfig config = new AnimationConfig(AnimationConfig.Settings.DEFAULT.withCpuSkinning(false));
    private final Handler ui = new Handler(Looper.getMainLooper());
    private final ModelLoader models = new ModelLoader(name -> getAssets().open("models/" + name), config,
            new BitmapDecoder(), model -> ui.post(() -> swapIn(model)));
    /** The measurement's GPU part: the GL thread draws the copies it asks for. */
    private final DrawnCopies drawnCopies = new DrawnCopies(DrawnCopies.NO_FRAME_SECONDS);
    private MeasureControl measure;
    /** The printed marker's size (docs/marker's 100 mm unless the user taps another). */
    private final MarkerSize markerSize = new MarkerSize(metres -> ui.post(this::onMarkerSize));
    /** The shown model's clips: the cross-fade and root motion buttons, the steering on the marker. */
    private final MixerControl mixer = new MixerControl(() -> new MarkerScene(markerSize.metres()));
    private PermissionFlow permission;
    private ModelCatalog catalog;
    private GLSurfaceView glView;
    private ArRenderer renderer;
    private ArControls controls;
    private HandlerThread cameraThread;
    private HandlerThread trackingThread;
    /** The open camera, or null; package-private: the tests feed camera frames through it. */
    CameraSource camera;
    /** The camera preview's texture in the renderer's current context, once its surface is ready. */
    private SurfaceTexture previewTexture;
    private boolean previewReady;
    private CameraIntrinsics intrinsics;
    private int sensorOrientation = 90;
    private volatile ArSession session;
    /** The shown model's simulation; package-private: the tests direct its mixer and read its frames. */
    volatile SkeletalAnimatedMesh mesh;
    /** What the camera or tracking last reported ("" when it works); kept apart from the model's. */
    private volatile String cameraProblem = "";
    private volatile boolean resumed;

    private final Runnable statusUpdate = new Runnable() {
        @Override
        public void run() {
            ArSession s = session;
            String model = models.loading() ? catalog.current() + " (loading)" : catalog.current();
            String line = StatusLine.format(renderer.fps(), s == null ? null : s.current(), config.settings(),
                    mixer.status(), model);
            String gl = renderer.problem();
            String[] measured = measure.statusLines();
            controls.refresh(StatusLine.withProblems(line, gl == null ? "" : "OpenGL ES: " + gl, cameraProblem,
                    models.problem(), measured[0], measured[1]));
            measure.poll();
            ui.postDelayed(this, 250);
        }
    };

    @Override
    protected void onCreate(Bundle saved) {
        super.onCreate(saved);
        // CoR's centres are computed once per model and then read from the app's cache folder.
        CentresOfRotation.setCacheDirectory(new File(getCacheDir(), "centres").toPath());
        try {
            catalog = new ModelCatalog(getAssets().list("models"));
        } catch (IOException | IllegalArgumentException e) {
            throw new IllegalStateException("the APK carries no models: " + e.getMessage(), e);
        }
        SavedChoices choices = SavedChoices.fromMap(savedMap(saved), config.settings());
        config.update(s -> choices.settings().withCpuSkinning(false));
        catalog.select(choices.model());
        markerSize.select(choices.markerMillimetres());
        permission = PermissionFlow.restore(choices.permission());
        measure = new MeasureControl(this, SAVE_REQUEST, catalog.names(),
                MeasureProtocol.named(getIntent().getStringExtra(MeasureProtocol.EXTRA)), drawnCopies,
                this::holdForMeasurement, this::releaseAfterMeasurement);
        cameraThread = new HandlerThread("camera");
        cameraThread.start();
        trackingThread = new HandlerThread("tracking");
        trackingThread.start();
        setContentView(layout());
        models.load(catalog.current());
    }

    private View layout() {
        glView = new GLSurfaceView(this);
        glView.setEGLContextClientVersion(3);
        glView.setPreserveEGLContextOnPause(true);
        renderer = new ArRenderer(config, texture -> ui.post(() -> onSurfaceReady(texture)), drawnCopies);
        glView.setRenderer(renderer);
        glView.setRenderMode(GLSurfaceView.RENDERMODE_CONTINUOUSLY);
        List<AppActions.Action> actions = AppActions.of(config, this::nextModel, mixer, markerSize, measure);
        controls = new ArControls(this, glView, actions, () -> {
            if (permission.onRetry()) {
                requestCamera();
            }
            showScreen();
        });
        return controls.root;
    }

    @Override
    protected void onResume() {
        super.onResume();
        resumed = true;
        glView.onResume();
        if (permission.onResume(holdsCamera())) {
            requestCamera();
        }
        showScreen();
        SkeletalAnimatedMesh m = mesh;
        if (m != null && !m.isClosed() && !measure.holding()) {
            m.start();
        }
        maybeOpenCamera();
        getSystemService(DisplayManager.class).registerDisplayListener(displayTurns, ui);
        renderer.setImageRotation(imageRotation());
        ui.post(statusUpdate);
    }

    @Override
    protected void onPause() {
        resumed = false;
        measure.stop();
        // The GL context may be lost while paused: the camera waits for the renderer's next surface.
        previewReady = false;
        ui.removeCallbacks(statusUpdate);
        getSystemService(DisplayManager.class).unregisterDisplayListener(displayTurns);
        closeCamera();
        SkeletalAnimatedMesh m = mesh;
        if (m != null) {
            m.stop();
        }
        glView.onPause();
        super.onPause();
    }

    @Override
    protected void onSaveInstanceState(Bundle out) {
        super.onSaveInstanceState(out);
        new SavedChoices(config.settings(), catalog.current(), markerSize.millimetres(), permission.savedState())
                .toMap().forEach(out::putString);
    }

    @Override
    protected void onDestroy() {
        closeCamera();
        models.close();
        measure.close();
        SkeletalAnimatedMesh m = mesh;
        if (m != null) {
            m.close();
        }
        SurfaceTexture texture = previewTexture;
        previewTexture = null;
        new Handler(cameraThread.getLooper()).post(() -> {
            if (texture != null) {
                texture.release();
            }
        });
        // Both end after the work already posted to them: the camera's close, the reader's.
        cameraThread.quitSafely();
        trackingThread.quitSafely();
        super.onDestroy();
    }

    @Override
    public void onRequestPermissionsResult(int requestCode, String[] permissions, int[] results) {
        if (requestCode != CAMERA_REQUEST) {
            return;
        }
        PermissionFlow.Answer answer = PermissionFlow.Answer.of(results, holdsCamera());
        if (permission.onResult(answer, shouldShowRequestPermissionRationale(Manifest.permission.CAMERA))) {
            requestCamera();
        }
        showScreen();
        maybeOpenCamera();
    }

    @Override
    protected void onActivityResult(int requestCode, int resultCode, Intent data) {
        if (!measure.onActivityResult(requestCode, resultCode, data)) {
            super.onActivityResult(requestCode, resultCode, data);
        }
    }

    @Override
    public void onConfigurationChanged(Configuration newConfig) {
        super.onConfigurationChanged(newConfig);
        renderer.setImageRotation(imageRotation());
    }

    /** A half turn (landscape to reverse landscape) changes no configuration: the display says so. */
    private final DisplayManager.DisplayListener displayTurns = new DisplayManager.DisplayListener() {
        @Override
        public void onDisplayChanged(int displayId) {
            renderer.setImageRotation(imageRotation());
        }

        @Override
        public void onDisplayAdded(int displayId) {
        }

        @Override
        public void onDisplayRemoved(int displayId) {
        }
    };

    private boolean holdsCamera() {
        return checkSelfPermission(Manifest.permission.CAMERA) == PackageManager.PERMISSION_GRANTED;
    }

    private void requestCamera() {
        requestPermissions(new String[] {Manifest.permission.CAMERA}, CAMERA_REQUEST);
    }

    private void showScreen() {
        controls.show(permission.screen());
    }

    /**
     * On the UI thread: the renderer's surface is ready with this preview texture. A texture other
     * than the one the camera streams into means a new GL context: the camera moves to the new one,
     * and the old one is released once the camera has let go of it (on the camera thread, after the
     * close).
     */
    void onSurfaceReady(SurfaceTexture texture) {
        if (isDestroyed()) {
            texture.release(); // the GL thread's last word, after onDestroy ended the camera thread
            return;
        }
        if (texture != previewTexture) {
            SurfaceTexture old = previewTexture;
            previewTexture = texture;
            closeCamera();
            if (old != null) {
                new Handler(cameraThread.getLooper()).post(old::release);
            }
        }
        previewReady = true;
        maybeOpenCamera();
    }

    private void maybeOpenCamera() {
        if (!resumed || camera != null || !previewReady || !permission.cameraAllowed() || isDestroyed()
                || measure.holding()) {
            return;
        }
        cameraProblem = "";
        CameraSource source = new CameraSource((CameraManager) getSystemService(CAMERA_SERVICE),
                new Handler(cameraThread.getLooper()), new Handler(trackingThread.getLooper()),
                new CameraSource.Listener() {
                    @Override
                    public void onOpened(CameraSource opened, CameraIntrinsics k, int orientation) {
                        ui.post(() -> onCameraOpened(opened, k, orientation));
                    }

                    @Override
                    public void onProblem(String message) {
                        cameraProblem = message;
                    }
                });
        camera = source;
        source.open(previewTexture);
    }

    /** On the UI thread: a camera is open; if it is still the current one, tracking starts with its intrinsics. */
    private void onCameraOpened(CameraSource opened, CameraIntrinsics k, int orientation) {
        if (camera != opened) {
            return; // closed meanwhile (and perhaps another opened)
        }
        intrinsics = k;
        sensorOrientation = orientation;
        startSession();
    }

    /** A tracking session for the open camera and the marker size, handed to the camera and the renderer. */
    private void startSession() {
        FiducialTracker.runOnCallingThread();
        ArSession s = ArSession.of(new FiducialTracker(TrackerConfig.defaults(markerSize.metres()), intrinsics));
        session = s;
        camera.setSession(s);
        renderer.setMarkerScene(new MarkerScene(markerSize.metres()));
        renderer.setSession(s, intrinsics, imageRotation(), sensorOrientation);
    }

    /** On the UI thread: another marker size; the tracking starts over with it. */
    private void onMarkerSize() {
        if (camera != null && intrinsics != null) {
            startSession();
        } else {
            renderer.setMarkerScene(new MarkerScene(markerSize.metres()));
        }
    }

    private void closeCamera() {
        if (camera != null) {
            camera.close();
            camera = null;
            intrinsics = null;
            session = null;
            // No stale pose drawn over the next camera's first frames.
            renderer.setSession(null, null, imageRotation(), sensorOrientation);
        }
    }

    /**
     * How the camera image must be turned, counter-clockwise on screen (ArCamera's sense), to stand
     * upright: the back camera's sensor is mounted {@code sensorOrientation} degrees clockwise from
     * the device's natural orientation, and the display is turned by its rotation.
     */
    @SuppressWarnings("deprecation")
    private int imageRotation() {
        int display;
        switch (getWindowManager().getDefaultDisplay().getRotation()) {
            case Surface.ROTATION_90:
                display = 90;
                break;
            case Surface.ROTATION_180:
                display = 180;
                break;
            case Surface.ROTATION_270:
                display = 270;
                break;
            default:
                display = 0;
                break;
        }
        int clockwise = Math.floorMod(sensorOrientation - display, 360);
        return Math.floorMod(-clockwise, 360);
    }

    /** A measurement starts: the camera and the simulation take no time from it. */
    private void holdForMeasurement() {
        closeCamera();
        SkeletalAnimatedMesh m = mesh;
        if (m != null) {
            m.stop();
        }
    }

    /** The measurement ended: the camera and the simulation come back (if the Activity is in front). */
    private void releaseAfterMeasurement() {
        SkeletalAnimatedMesh m = mesh;
        if (resumed && m != null && !m.isClosed()) {
            m.start();
        }
        maybeOpenCamera();
    }

    private void nextModel() {
        models.load(catalog.next());
    }

    /**
     * On the UI thread, where onPause and onResume run: a loaded model replaces the shown one, so
     * that its simulation runs only while the Activity is resumed.
     */
    private void swapIn(ModelLoader.Loaded model) {
        SkeletalAnimatedMesh next = model.mesh();
        if (isDestroyed()) {
            next.close();
            return;
        }
        SkeletalAnimatedMesh old = mesh;
        mesh = next;
        mixer.show(next);
        renderer.setModel(model);
        if (resumed && !measure.holding()) {
            next.start();
        }
        if (old != null) {
            old.close();
        }
    }

    private static Map<String, String> savedMap(Bundle saved) {
        Map<String, String> map = new HashMap<>();
        if (saved != null) {
            for (String key : SavedChoices.KEYS) {
                String value = saved.getString(key);
                if (value != null) {
                    map.put(key, value);
                }
            }
        }
        return map;
    }
}
