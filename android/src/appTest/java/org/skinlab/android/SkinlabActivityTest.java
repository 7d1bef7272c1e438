package org.skinlab.android;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertNotSame;
import static org.junit.Assert.assertNull;
import static org.junit.Assert.assertSame;
import static org.junit.Assert.assertTrue;
import static org.robolectric.Shadows.shadowOf;

import java.util.HashSet;
import java.util.Set;

import android.Manifest;
import android.content.pm.PackageManager;
import android.content.res.Configuration;
import android.os.Build;

import org.junit.After;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.robolectric.RobolectricTestRunner;
import org.robolectric.annotation.Config;
import org.robolectric.shadows.ShadowActivity;
import org.skinlab.internal.scene.DefaultAsset;

/**
 * The real Activity on the framework's classes (Robolectric), at minSdk and targetSdk: the camera
 * permission's paths, the lifecycle, every button, model loading and the status line. The camera
 * itself is in {@link CameraSourceTest}.
 */
@RunWith(RobolectricTestRunner.class)
@Config(minSdk = 26, shadows = ShadowPermissionRequestState.class)
public class SkinlabActivityTest {
    private final AppDriver app = new AppDriver();
    private final Set<Thread> before = new HashSet<>(AppDriver.appThreads());

    @After
    public void finish() {
        app.finish();
    }

    @Test
    public void firstLaunchAsksForTheCameraThenExplainsARefusal() {
        app.start(false);
        ShadowActivity.PermissionsRequest asked = app.lastRequest();
        assertNotNull("asked at first launch", asked);
        assertEquals(Manifest.permission.CAMERA, asked.requestedPermissions[0]);
        assertFalse("nothing to explain while the dialog is up", app.explanationShown());

        shadowOf(app.app().getPackageManager()).setShouldShowRequestPermissionRationale(Manifest.permission.CAMERA, true);
        app.answerPermission(new int[] {PackageManager.PERMISSION_DENIED});
        assertTrue(app.explanationShown());
        assertTrue("the retry button is there", app.button("Allow the camera").isShown());

        app.tap("Allow the camera");
        assertNotSame("asked again", asked, app.lastRequest());
        shadowOf(app.app().getPackageManager()).setShouldShowRequestPermissionRationale(Manifest.permission.CAMERA, false);
        app.answerPermission(new int[] {PackageManager.PERMISSION_DENIED});
        assertTrue("don't ask again: the way to the settings", app.explanation().contains("Android's settings"));
        assertFalse("no retry Android would ignore", app.button("Allow the camera").isShown());

        // Allowed in the settings meanwhile, then back to the app.
        shadowOf(app.app()).grantPermissions(Manifest.permission.CAMERA);
        app.controller.pause().resume();
        app.idle();
        assertFalse(app.explanationShown());
    }

    @Test
    public void aGrantInTheDialogStartsTheCameraWithoutAskingAgain() {
        app.addBackCamera("0");
        app.start(false);
        app.surfaceReady();
        assertNull("no camera without the permission", app.activity().camera);
        app.answerPermission(new int[] {PackageManager.PERMISSION_GRANTED});
        assertFalse(app.explanationShown());
        assertNotNull("the camera opens once granted", app.activity().camera);
        ShadowActivity.PermissionsRequest asked = app.lastRequest();
        app.controller.pause().resume();
        assertSame("held: not asked again", asked, app.lastRequest());
    }

    @Test
    public void aCancelledRequestIsAskedAgainOnceNotTakenAsARefusal() {
        app.start(false);
        ShadowActivity.PermissionsRequest first = app.lastRequest();
        app.answerPermission(new int[0]);
        assertNotSame("a cancelled request is asked again", first, app.lastRequest());
        assertFalse("and not explained as a refusal", app.explanationShown());
        app.answerPermission(new int[0]);
        assertTrue("cancelled twice: the user may ask", app.explanationShown());
        assertFalse("never the settings hint for a cancel", app.explanation().contains("settings"));
    }

    @Test
    public void aCancelledRequestWithThePermissionHeldOpensTheCamera() {
        app.addBackCamera("0");
        app.start(false);
        app.surfaceReady();
        shadowOf(app.app()).grantPermissions(Manifest.permission.CAMERA); // granted meanwhile (settings)
        app.answerPermission(new int[0]);
        assertFalse(app.explanationShown());
        assertNotNull(app.activity().camera);
    }

    @Test
    public void aResumeWhileTheDialogIsUpDoesNotAskAgain() {
        app.start(false);
        ShadowActivity.PermissionsRequest asked = app.lastRequest();
        // Android's dialog is another activity: ours pauses under it and resumes when it goes.
        app.controller.pause().resume();
        assertSame("one request at a time (a second would be cancelled)", asked, app.lastRequest());
    }

    @Test
    public void everyButtonDoesItsFunctionAndTheStatusLineSaysSo() {
        app.start(true);
        String status = app.status();
        assertTrue(status, status.contains("| LBS SLERP x1.00 |"));
        assertTrue(status, status.endsWith(DefaultAsset.fileName()) || status.contains(DefaultAsset.fileName() + " (loading)"));

        app.tap("Stop mesh");
        assertNotNull("mesh updates stop", app.button("Start mesh"));
        app.tap("Start mesh");
        app.tap("Stop anim");
        assertNotNull(app.button("Start anim"));
        app.tap("Start anim");
        app.tap("Follow: off");
        assertTrue(app.status().contains("| follow"));
        // The method button offers all seven, in SkinningMethod's order, and comes round again.
        org.skinlab.skinning.SkinningMethod[] methods = org.skinlab.skinning.SkinningMethod.values();
        for (int i = 0; i < methods.length; i++) {
            String next = methods[(i + 1) % methods.length].key().toUpperCase(java.util.Locale.ROOT);
            app.tap(methods[i].key().toUpperCase(java.util.Locale.ROOT));
            assertTrue(next, app.status().contains("| " + next + " "));
        }
        String interpolation = app.status();
        app.tap("SLERP");
        assertFalse("another interpolation", app.status().equals(interpolation));
        app.tap("Faster");
        assertTrue(app.status(), app.status().contains(" x1.41"));
        app.tap("Slower");
        app.tap("Slower");
        assertTrue(app.status(), app.status().contains(" x0.71"));
        app.tap("Marker 100 mm");
        assertNotNull(app.button("Marker 150 mm"));
        app.tap("Next mesh");
        assertFalse("another model", app.status().contains(DefaultAsset.fileName()));
    }

    @Test
    public void modelsLoadOnTheLoaderAndAnimateOnlyWhileResumed() {
        app.start(true);
        app.awaitStatus("the default model loaded", s -> s.endsWith(DefaultAsset.fileName()));
        app.await("its simulation running", () -> simulationThreads() == 1);
        app.controller.pause();
        app.await("the simulation stopped while paused", () -> simulationThreads() == 0);
        app.controller.resume();
        app.await("running again", () -> simulationThreads() == 1);
        app.tap("Next mesh");
        app.awaitStatus("the next model loaded", s -> !s.contains("(loading)"));
        app.await("one simulation: the old model's ended", () -> simulationThreads() == 1);
    }

    @Test
    public void aModelThatFailsToLoadIsReportedApartFromTheCamera() {
        app.start(true); // no camera on this phone
        app.surfaceReady();
        app.awaitStatus("the missing camera reported", s -> s.contains("this device has no camera"));
        app.awaitStatus("the default model loaded", s -> !s.contains("(loading)"));
        // The tests add a damaged model after the bundled ones.
        String status = app.status();
        for (int taps = 0; !status.contains("zz-broken.dae"); taps++) {
            assertTrue("the damaged model is in the catalog", taps < 20);
            app.tap("Next mesh");
            status = app.awaitStatus("a model loaded", s -> !s.contains("(loading)"));
            assertTrue("a model's success keeps the camera's problem: " + status,
                    status.contains("this device has no camera"));
        }
        assertTrue(status, status.contains("zz-broken.dae") && status.contains("\nzz-broken.dae"));
        assertTrue("both problems shown", status.contains("this device has no camera"));
        app.tap("Next mesh");
        status = app.awaitStatus("the first model again", s -> !s.contains("(loading)"));
        assertFalse("the model's problem is gone with it: " + status, status.contains("\nzz-broken.dae"));
        assertTrue(status.contains("this device has no camera"));
    }

    @Test
    public void recreatedFromSavedStateTheChoicesStay() {
        app.start(true);
        app.tap("LBS");
        app.tap("Faster");
        app.tap("Marker 100 mm");
        app.tap("Next mesh");
        String model = app.status().replace(" (loading)", "");
        model = model.substring(model.lastIndexOf("| ") + 2);
        SkinlabActivity first = app.activity();
        app.controller.recreate();
        app.idle();
        assertNotSame("a new Activity", first, app.activity());
        String status = app.status();
        assertTrue(status, status.contains("| DQS ") && status.contains(" x1.41"));
        assertTrue(status, status.contains(model));
        assertNotNull(app.button("Marker 150 mm"));
    }

    @Test
    public void aRecreationWhileTheDialogIsUpDoesNotAskAgain() {
        app.start(false);
        ShadowActivity.PermissionsRequest asked = app.lastRequest();
        app.controller.recreate();
        app.idle();
        assertNull("the dialog's answer goes to the new Activity: no second request",
                shadowOf(app.activity()).getLastRequestedPermission());
        assertNotNull(asked);
    }

    @Test
    public void aRotationIsHandledInPlace() {
        app.addBackCamera("0");
        app.start(true);
        app.surfaceReady();
        SkinlabActivity before = app.activity();
        CameraSource camera = before.camera;
        Configuration landscape = new Configuration(before.getResources().getConfiguration());
        landscape.orientation = Configuration.ORIENTATION_LANDSCAPE;
        landscape.screenWidthDp = 800;
        landscape.screenHeightDp = 360;
        app.controller.configurationChange(landscape);
        app.idle();
        assertSame("configChanges: the Activity, its GL context and camera stay", before, app.activity());
        assertSame(camera, app.activity().camera);
        assertTrue(app.status().contains(" fps | marker: "));
    }

    @Test
    public void destroyEndsEveryThreadItStarted() throws InterruptedException {
        app.addBackCamera("0");
        app.start(true);
        app.surfaceReady();
        app.awaitStatus("the model loaded", s -> !s.contains("(loading)"));
        app.controller.pause().stop().destroy();
        for (Thread t : AppDriver.appThreads()) {
            if (!before.contains(t)) {
                t.join(AppDriver.TIMEOUT_MILLIS);
                assertFalse(t.getName() + " outlived onDestroy", t.isAlive());
            }
        }
    }

    @Test
    public void runsOnTheRequestedSdkWithOurManifest() throws Exception {
        app.start(true);
        assertEquals("org.skinlab.android", app.activity().getPackageName());
        assertEquals(26, app.app().getPackageManager().getApplicationInfo("org.skinlab.android", 0).minSdkVersion);
        assertTrue("the target SDK is the newest one tested",
                app.activity().getApplicationInfo().targetSdkVersion >= Build.VERSION.SDK_INT);
        assertTrue("an icon", app.activity().getApplicationInfo().icon != 0);
    }

    private int simulationThreads() {
        int n = 0;
        for (Thread t : AppDriver.appThreads()) {
            if (t.getName().startsWith("skinlab-simulation") && !before.contains(t)) {
                n++;
            }
        }
        return n;
    }
}
