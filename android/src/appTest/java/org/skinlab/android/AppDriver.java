package org.skinlab.android;

import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;
import static org.robolectric.Shadows.shadowOf;

import java.nio.ByteBuffer;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import java.util.stream.Collectors;

import android.Manifest;
import android.app.Activity;
import android.app.Application;
import android.content.Intent;
import android.content.pm.PackageManager;
import android.graphics.SurfaceTexture;
import android.hardware.camera2.CameraCharacteristics;
import android.hardware.camera2.CameraManager;
import android.os.Handler;
import android.os.HandlerThread;
import android.util.Size;
import android.view.View;
import android.view.ViewGroup;
import android.widget.Button;
import android.widget.TextView;

import org.robolectric.Robolectric;
import org.robolectric.RuntimeEnvironment;
import org.robolectric.android.controller.ActivityController;
import org.robolectric.shadows.ShadowActivity;
import org.robolectric.shadows.ShadowCameraCharacteristics;
import org.robolectric.shadows.ShadowLooper;
import org.robolectric.shadows.StreamConfigurationMapBuilder;
import org.skinlab.android.logic.IntrinsicsEstimate;
import org.skinlab.android.logic.PermissionFlow;
import org.skinlab.ar.CameraIntrinsics;
import org.skinlab.ar.GrayImage;
import org.skinlab.ar.MarkerDictionary;
import org.skinlab.ar.MarkerPattern;
import org.skinlab.internal.synthetic.PlacedMarker;
import org.skinlab.internal.synthetic.SceneOptions;
import org.skinlab.internal.synthetic.SyntheticCamera;

/**
 * Drives the real {@link SkinlabActivity} in Robolectric as a user and a phone would: the
 * lifecycle, the permission dialog's answers, taps on the buttons, the camera and its frames, and
 * reads what the user sees (the status line, the explanation). The camera and tracking threads and
 * the model loader are real threads: waits poll until a condition holds, meanwhile running the main
 * looper (and its clock: the status line refreshes every 250 ms).
 */
final class AppDriver {
    /** Long enough for the slowest step here (a model's CoR centres on a busy 2-core machine). */
    static final long TIMEOUT_MILLIS = 60_000;

    ActivityController<SkinlabActivity> controller;
    private SurfaceTexture texture;

    /** The application of the running test (made by Robolectric for each test, so looked up each time). */
    Application app() {
        return RuntimeEnvironment.getApplication();
    }

    CameraManager cameras() {
        return app().getSystemService(CameraManager.class);
    }

    /**
     * Ends the Activity if the test has not, and works around Robolectric 4.16 (the minSdk run):
     * after each test its camera shadow idles the looper of the last camera callback's Handler,
     * which fails once that looper has quit, as the app's camera thread does in onDestroy.
     */
    void finish() {
        if (controller != null && !activity().isDestroyed()) {
            controller.pause().stop().destroy();
        }
        try {
            java.lang.reflect.Field handler = org.robolectric.shadows.ShadowCameraManager.class
                    .getDeclaredField("lastCallbackHandler");
            handler.setAccessible(true);
            handler.set(null, null);
        } catch (NoSuchFieldException e) {
            // Robolectric 4.17 and later keep no such handler
        } catch (IllegalAccessException e) {
            throw new AssertionError(e);
        }
    }

    /** Starts the Activity (create, start, resume) with the camera permission granted or not. */
    AppDriver start(boolean cameraGranted) {
        return start(cameraGranted, null);
    }

    /** As {@link #start(boolean)}, launched by {@code intent} (its extras), or as the launcher does for null. */
    AppDriver start(boolean cameraGranted, Intent intent) {
        if (cameraGranted) {
            shadowOf(app()).grantPermissions(Manifest.permission.CAMERA);
        } else {
            shadowOf(app()).denyPermissions(Manifest.permission.CAMERA);
        }
        controller = Robolectric.buildActivity(SkinlabActivity.class, intent).setup();
        idle();
        return this;
    }

    SkinlabActivity activity() {
        return controller.get();
    }

    /**
     * A back camera as Camera2 lists it: 4:3 and 16:9 YUV and preview sizes, continuous video
     * autofocus, the sensor turned 90 degrees (most phones). Returned for a test to add keys
     * (before the camera opens).
     */
    CameraCharacteristics addBackCamera(String id) {
        CameraCharacteristics c = ShadowCameraCharacteristics.newCameraCharacteristics();
        shadowOf(c).set(CameraCharacteristics.LENS_FACING, CameraCharacteristics.LENS_FACING_BACK);
        shadowOf(c).set(CameraCharacteristics.SENSOR_ORIENTATION, 90);
        shadowOf(c).set(CameraCharacteristics.CONTROL_AF_AVAILABLE_MODES, new int[] {0, 1, 3, 4});
        StreamConfigurationMapBuilder map = StreamConfigurationMapBuilder.newBuilder();
        for (Size s : new Size[] {new Size(1920, 1080), new Size(1280, 720), new Size(640, 480), new Size(320, 240)}) {
            map.addOutputSize(android.graphics.ImageFormat.YUV_420_888, s);
        }
        for (Size s : new Size[] {new Size(1920, 1080), new Size(1440, 1080), new Size(1280, 960)}) {
            map.addOutputSize(android.graphics.ImageFormat.PRIVATE, s);
        }
        shadowOf(c).set(CameraCharacteristics.SCALER_STREAM_CONFIGURATION_MAP, map.build());
        shadowOf(cameras()).addCamera(id, c);
        return c;
    }

    /**
     * What the renderer does on GLSurfaceView's thread once a new GL context's surface is ready (a
     * new preview texture), which Robolectric's GL thread never does.
     */
    SurfaceTexture surfaceReady() {
        texture = new SurfaceTexture(0);
        activity().onSurfaceReady(texture);
        idle();
        return texture;
    }

    /** The same after a resume that kept the GL context: the surface is ready with the same texture. */
    void surfaceReadyAgain() {
        activity().onSurfaceReady(texture);
        idle();
    }

    /**
     * The user's answer in the system dialog, delivered as Android delivers it: as the result of
     * the dialog's activity, which the framework turns into onRequestPermissionsResult (and which
     * ends the request it keeps open meanwhile). No results at all is a cancelled dialog.
     */
    void answerPermission(int[] results) {
        ShadowActivity.IntentForResult dialog = shadowOf(activity()).getNextStartedActivityForResult();
        assertTrue("a permission dialog is open", dialog != null);
        if (results.length > 0 && results[0] == PackageManager.PERMISSION_GRANTED) {
            shadowOf(app()).grantPermissions(Manifest.permission.CAMERA);
        }
        Intent answer = null;
        if (results.length > 0) {
            // PackageManager.EXTRA_REQUEST_PERMISSIONS_NAMES and _RESULTS (system API).
            answer = new Intent().putExtra("android.content.pm.extra.REQUEST_PERMISSIONS_NAMES",
                    new String[] {Manifest.permission.CAMERA})
                    .putExtra("android.content.pm.extra.REQUEST_PERMISSIONS_RESULTS", results);
        }
        shadowOf(activity()).receiveResult(dialog.intent, results.length > 0 ? Activity.RESULT_OK
                : Activity.RESULT_CANCELED, answer);
        idle();
    }

    ShadowActivity.PermissionsRequest lastRequest() {
        return shadowOf(activity()).getLastRequestedPermission();
    }

    /** Runs the main looper's due work, then 300 ms of its clock (one status line refresh). */
    void idle() {
        ShadowLooper.idleMainLooper();
        ShadowLooper.idleMainLooper(300, TimeUnit.MILLISECONDS);
    }

    /** The status line as shown now. */
    String status() {
        idle();
        for (TextView t : views(TextView.class)) {
            if (!(t instanceof Button) && t.getText().toString().contains(" fps | marker: ")) {
                return t.getText().toString();
            }
        }
        fail("no status line on screen");
        return null;
    }

    /** Waits until the status line satisfies {@code test}; returns it. */
    String awaitStatus(String what, java.util.function.Predicate<String> test) {
        String[] last = {""};
        await(what, () -> test.test(last[0] = status()));
        return last[0];
    }

    /** Polls {@code condition}, running the main looper meanwhile, until it holds or the time is up. */
    void await(String what, BooleanSupplier condition) {
        long end = System.currentTimeMillis() + TIMEOUT_MILLIS;
        while (!condition.getAsBoolean()) {
            if (System.currentTimeMillis() > end) {
                fail("timed out waiting for " + what + "; status line: " + statusOrNone());
            }
            idle();
            try {
                Thread.sleep(10);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                fail("interrupted");
            }
        }
    }

    private String statusOrNone() {
        for (TextView t : views(TextView.class)) {
            if (t.getText().toString().contains(" fps | ")) {
                return t.getText().toString();
            }
        }
        return "(none)";
    }

    /** The button whose label starts with {@code label}. */
    Button button(String label) {
        for (Button b : views(Button.class)) {
            if (b.getText().toString().startsWith(label)) {
                return b;
            }
        }
        fail("no button \"" + label + "\" among " + views(Button.class).stream().map(b -> b.getText().toString())
                .collect(Collectors.toList()));
        return null;
    }

    /** Waits until a button's label starts with {@code label} (labels follow the app's state at each refresh); returns it. */
    Button awaitButton(String label) {
        Button[] found = {null};
        await("a button \"" + label + "\"", () -> {
            for (Button b : views(Button.class)) {
                if (b.getText().toString().startsWith(label)) {
                    found[0] = b;
                    return true;
                }
            }
            return false;
        });
        return found[0];
    }

    /** Taps the button whose label starts with {@code label}, as a user does. */
    void tap(String label) {
        assertTrue(label + " tappable", button(label).performClick());
        idle();
    }

    /** Whether the permission explanation covers the screen. */
    boolean explanationShown() {
        for (TextView t : views(TextView.class)) {
            if (t.getText().toString().startsWith(PermissionFlow.EXPLANATION)) {
                return ((View) t.getParent()).getVisibility() == View.VISIBLE;
            }
        }
        return false;
    }

    /** The explanation's text. */
    String explanation() {
        for (TextView t : views(TextView.class)) {
            if (t.getText().toString().startsWith(PermissionFlow.EXPLANATION)) {
                return t.getText().toString();
            }
        }
        return "";
    }

    <T extends View> List<T> views(Class<T> type) {
        List<T> found = new ArrayList<>();
        collect(activity().getWindow().getDecorView(), type, found);
        return found;
    }

    private static <T extends View> void collect(View v, Class<T> type, List<T> found) {
        if (type.isInstance(v)) {
            found.add(type.cast(v));
        }
        if (v instanceof ViewGroup) {
            ViewGroup g = (ViewGroup) v;
            for (int i = 0; i < g.getChildCount(); i++) {
                collect(g.getChildAt(i), type, found);
            }
        }
    }

    /**
     * A camera frame of the printed marker (id 0 of the app's dictionary, 100 mm, half a metre in
     * front of the camera, slightly turned), 640x480 as the camera streams it, fed through the
     * camera source's frame entry on the tracking thread, where the ImageReader's frames arrive.
     */
    void feedMarkerFrame(long timestampNanos) throws InterruptedException {
        CameraIntrinsics k = CameraIntrinsics.fromHorizontalFov(640, 480, IntrinsicsEstimate.FALLBACK_FOV_DEGREES);
        GrayImage image = new SyntheticCamera(k).render(List.of(PlacedMarker.of(
                MarkerPattern.of(MarkerDictionary.DEFAULT, 0), 0.1, PlacedMarker.facingCamera(20, 10, 15),
                new double[] {0.01, 0.02, 0.5})), SceneOptions.camera(7));
        feed(ByteBuffer.wrap(image.pixels()), image.rowStride(), 1, image.width(), image.height(), timestampNanos);
    }

    /** One luminance plane through the camera source, on the tracking thread; waits until it was tracked. */
    void feed(ByteBuffer plane, int rowStride, int pixelStride, int width, int height, long timestampNanos)
            throws InterruptedException {
        CameraSource source = activity().camera;
        assertTrue("the camera is open", source != null);
        CountDownLatch done = new CountDownLatch(1);
        new Handler(thread("tracking").getLooper()).post(() -> {
            try {
                source.track(plane, rowStride, pixelStride, width, height, timestampNanos);
            } finally {
                done.countDown();
            }
        });
        assertTrue("the tracking thread took the frame", done.await(TIMEOUT_MILLIS, TimeUnit.MILLISECONDS));
        idle();
    }

    /** A live thread of the app by name (the camera's or the tracking HandlerThread). */
    static HandlerThread thread(String name) {
        for (Thread t : Thread.getAllStackTraces().keySet()) {
            if (t.getName().equals(name) && t instanceof HandlerThread && t.isAlive()) {
                return (HandlerThread) t;
            }
        }
        fail("no live thread " + name);
        return null;
    }

    /** The live threads the app starts (camera, tracking, model loader, simulation, measuring, saving). */
    static Set<Thread> appThreads() {
        return Thread.getAllStackTraces().keySet().stream().filter(Thread::isAlive)
                .filter(t -> t.getName().equals("camera") || t.getName().equals("tracking")
                        || t.getName().equals("model-loader") || t.getName().startsWith("skinlab-simulation")
                        || t.getName().equals("measure") || t.getName().equals("save-results"))
                .collect(Collectors.toSet());
    }
}
