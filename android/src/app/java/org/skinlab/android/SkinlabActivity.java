package org.skinlab.android;

import java.io.File;
import java.io.IOException;
import java.io.InputStream;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;

import android.Manifest;
import android.app.Activity;
import android.content.pm.PackageManager;
import android.content.res.Configuration;
import android.graphics.Color;
import android.graphics.SurfaceTexture;
import android.hardware.display.DisplayManager;
import android.opengl.GLSurfaceView;
import android.os.Bundle;
import android.os.Handler;
import android.os.Looper;
import android.view.Gravity;
import android.view.Surface;
import android.view.View;
import android.widget.Button;
import android.widget.FrameLayout;
import android.widget.HorizontalScrollView;
import android.widget.LinearLayout;
import android.widget.TextView;

import org.skinlab.android.logic.AppActions;
import org.skinlab.android.logic.MarkerSize;
import org.skinlab.android.logic.ModelCatalog;
import org.skinlab.android.logic.PermissionFlow;
import org.skinlab.android.logic.StatusLine;
import org.skinlab.ar.ArPose;
import org.skinlab.ar.ArSession;
import org.skinlab.ar.CameraIntrinsics;
import org.skinlab.ar.FiducialTracker;
import org.skinlab.ar.MarkerScene;
import org.skinlab.ar.TrackerConfig;
import org.skinlab.collada.ColladaImporter;
import org.skinlab.model.Model;
import org.skinlab.simulation.AnimationConfig;
import org.skinlab.simulation.SkeletalAnimatedMesh;
import org.skinlab.skinning.CentersOfRotation;
import org.skinlab.skinning.SkinnedGeometry;

/**
 * The AR app's one Activity: the camera image with the animated character standing on the printed
 * marker (docs/marker: ArUco MIP_36h12 id 0, 100 mm by default; a button steps through other
 * printed sizes), a status line, and a button for every user
 * function of the thesis ({@link AppActions}). Threads: the UI thread (this class), the GL thread
 * ({@link ArRenderer}), the camera and tracking threads ({@link CameraSource}), the simulation
 * thread ({@link SkeletalAnimatedMesh}) and one loader thread for models. onPause closes the camera
 * and stops the simulation; onResume starts both again.
 */
public final class SkinlabActivity extends Activity {
    private static final int CAMERA_REQUEST = 1;

    private final PermissionFlow permission = new PermissionFlow();
    private final AnimationConfig config = new AnimationConfig(AnimationConfig.Settings.DEFAULT.withCpuSkinning(false));
    private final Handler ui = new Handler(Looper.getMainLooper());
    private final ExecutorService loader = Executors.newSingleThreadExecutor(r -> new Thread(r, "model-loader"));
    private final List<Button> buttons = new ArrayList<>();
    /** The printed marker's size (docs/marker's 100 mm unless the user taps another). */
    private final MarkerSize markerSize = new MarkerSize(metres -> ui.post(this::onMarkerSize));
    private List<AppActions.Action> actions;
    private ModelCatalog catalog;
    private GLSurfaceView glView;
    private ArRenderer renderer;
    private TextView status;
    private LinearLayout explanation;
    private TextView explanationText;
    private Button retry;
    private CameraSource camera;
    private SurfaceTexture previewTexture;
    private CameraIntrinsics intrinsics;
    private int sensorOrientation = 90;
    private volatile ArSession session;
    private volatile SkeletalAnimatedMesh mesh;
    private volatile String problem = "";
    private volatile boolean resumed;

    private final Runnable statusUpdate = new Runnable() {
        @Override
        public void run() {
            ArSession s = session;
            ArPose pose = s == null ? ArPose.NONE : s.current();
            String line = StatusLine.format(renderer.fps(), pose.state(), pose.trackerMillis(), config.settings(),
                    catalog.current());
            String gl = renderer.problem();
            String trouble = gl != null ? "OpenGL ES: " + gl : problem;
            status.setText(trouble.isEmpty() ? line : line + "\n" + trouble);
            for (int i = 0; i < buttons.size(); i++) {
                buttons.get(i).setText(actions.get(i).label().get());
            }
            ui.postDelayed(this, 250);
        }
    };

    @Override
    protected void onCreate(Bundle saved) {
        super.onCreate(saved);
        // CoR's centres are computed once per model and then read from the app's cache folder.
        CentersOfRotation.setCacheDirectory(new File(getCacheDir(), "centres").toPath());
        try {
            catalog = new ModelCatalog(getAssets().list("models"));
        } catch (IOException | IllegalArgumentException e) {
            throw new IllegalStateException("the APK carries no models: " + e.getMessage(), e);
        }
        FrameLayout root = new FrameLayout(this);
        glView = new GLSurfaceView(this);
        glView.setEGLContextClientVersion(3);
        glView.setPreserveEGLContextOnPause(true);
        renderer = new ArRenderer(config, texture -> ui.post(() -> onPreviewTexture(texture)));
        glView.setRenderer(renderer);
        glView.setRenderMode(GLSurfaceView.RENDERMODE_CONTINUOUSLY);
        root.addView(glView);

        status = new TextView(this);
        status.setTextColor(Color.WHITE);
        status.setBackgroundColor(0x88000000);
        status.setPadding(16, 8, 16, 8);
        root.addView(status, new FrameLayout.LayoutParams(FrameLayout.LayoutParams.MATCH_PARENT,
                FrameLayout.LayoutParams.WRAP_CONTENT, Gravity.TOP));

        LinearLayout row = new LinearLayout(this);
        row.setOrientation(LinearLayout.HORIZONTAL);
        actions = AppActions.of(config, this::nextModel, markerSize);
        for (AppActions.Action a : actions) {
            Button b = new Button(this);
            b.setAllCaps(false);
            b.setText(a.label().get());
            b.setOnClickListener(v -> {
                a.run().run();
                b.setText(a.label().get());
            });
            buttons.add(b);
            row.addView(b);
        }
        HorizontalScrollView scroll = new HorizontalScrollView(this);
        scroll.setBackgroundColor(0x66000000);
        scroll.addView(row);
        root.addView(scroll, new FrameLayout.LayoutParams(FrameLayout.LayoutParams.MATCH_PARENT,
                FrameLayout.LayoutParams.WRAP_CONTENT, Gravity.BOTTOM));

        explanation = new LinearLayout(this);
        explanation.setOrientation(LinearLayout.VERTICAL);
        explanation.setGravity(Gravity.CENTER);
        explanation.setBackgroundColor(0xEE202024);
        explanation.setPadding(48, 48, 48, 48);
        explanationText = new TextView(this);
        explanationText.setTextColor(Color.WHITE);
        explanationText.setText(PermissionFlow.EXPLANATION);
        explanation.addView(explanationText);
        retry = new Button(this);
        retry.setText("Allow the camera");
        retry.setOnClickListener(v -> {
            if (permission.onRetry()) {
                requestPermissions(new String[] {Manifest.permission.CAMERA}, CAMERA_REQUEST);
            }
            showScreen();
        });
        explanation.addView(retry);
        root.addView(explanation, new FrameLayout.LayoutParams(FrameLayout.LayoutParams.MATCH_PARENT,
                FrameLayout.LayoutParams.MATCH_PARENT));
        setContentView(root);
        load(catalog.current());
    }

    @Override
    protected void onResume() {
        super.onResume();
        resumed = true;
        glView.onResume();
        boolean granted = checkSelfPermission(Manifest.permission.CAMERA) == PackageManager.PERMISSION_GRANTED;
        if (permission.onResume(granted)) {
            requestPermissions(new String[] {Manifest.permission.CAMERA}, CAMERA_REQUEST);
        }
        showScreen();
        SkeletalAnimatedMesh m = mesh;
        if (m != null && !m.isClosed()) {
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
    protected void onDestroy() {
        loader.shutdownNow();
        SkeletalAnimatedMesh m = mesh;
        if (m != null) {
            m.close();
        }
        super.onDestroy();
    }

    @Override
    public void onRequestPermissionsResult(int requestCode, String[] permissions, int[] results) {
        if (requestCode != CAMERA_REQUEST) {
            return;
        }
        boolean granted = results.length > 0 && results[0] == PackageManager.PERMISSION_GRANTED;
        permission.onResult(granted, shouldShowRequestPermissionRationale(Manifest.permission.CAMERA));
        showScreen();
        maybeOpenCamera();
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

    private void showScreen() {
        PermissionFlow.Screen screen = permission.screen();
        boolean explain = screen == PermissionFlow.Screen.EXPLAIN_AND_RETRY
                || screen == PermissionFlow.Screen.EXPLAIN_SETTINGS;
        explanation.setVisibility(explain ? View.VISIBLE : View.GONE);
        retry.setVisibility(screen == PermissionFlow.Screen.EXPLAIN_AND_RETRY ? View.VISIBLE : View.GONE);
        explanationText.setText(screen == PermissionFlow.Screen.EXPLAIN_SETTINGS
                ? PermissionFlow.EXPLANATION + "\n\nAllow the camera for skinlab AR in Android's settings (Apps, "
                        + "skinlab AR, Permissions), then come back."
                : PermissionFlow.EXPLANATION);
    }

    /** On the UI thread: the renderer made (or remade, after a lost context) its preview texture. */
    private void onPreviewTexture(SurfaceTexture texture) {
        previewTexture = texture;
        if (camera != null) {
            closeCamera();
        }
        maybeOpenCamera();
    }

    private void maybeOpenCamera() {
        if (!resumed || camera != null || previewTexture == null || !permission.cameraAllowed()) {
            return;
        }
        camera = new CameraSource(this, new CameraSource.Listener() {
            @Override
            public void onOpened(CameraIntrinsics k, int orientation) {
                intrinsics = k;
                sensorOrientation = orientation;
                startSession();
                problem = "";
            }

            @Override
            public void onError(String message) {
                problem = message;
            }
        });
        camera.open(previewTexture);
    }

    /** A tracking session for the open camera and the marker size, handed to the camera and the renderer. */
    private void startSession() {
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

    private void nextModel() {
        load(catalog.next());
    }

    /**
     * Loads a bundled model on the loader thread, then swaps it in on the UI thread, where onPause
     * and onResume run: the new model's simulation runs only while the Activity is resumed.
     */
    private void load(String name) {
        loader.execute(() -> {
            SkeletalAnimatedMesh next;
            try (InputStream in = getAssets().open("models/" + name)) {
                Model model = ColladaImporter.read(in, name);
                next = SkeletalAnimatedMesh.of(model, config);
                // CoR's centres here, not on the GL thread when the model is first uploaded.
                for (SkinnedGeometry g : next.geometries()) {
                    if (g.isSkinned()) {
                        g.centersOfRotation();
                    }
                }
            } catch (Exception e) {
                problem = name + ": " + e.getMessage();
                return;
            }
            ui.post(() -> {
                if (isDestroyed()) {
                    next.close();
                    return;
                }
                SkeletalAnimatedMesh old = mesh;
                mesh = next;
                renderer.setMesh(next);
                if (resumed) {
                    next.start();
                }
                if (old != null) {
                    old.close();
                }
                problem = "";
            });
        });
    }
}
