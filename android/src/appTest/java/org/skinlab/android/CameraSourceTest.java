package org.skinlab.android;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertNotSame;
import static org.junit.Assert.assertNull;
import static org.junit.Assert.assertTrue;
import static org.robolectric.Shadows.shadowOf;

import java.nio.ByteBuffer;

import android.hardware.camera2.CameraCharacteristics;
import android.hardware.camera2.CameraMetadata;
import android.os.Build;
import android.util.Size;

import org.junit.After;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.robolectric.RobolectricTestRunner;
import org.robolectric.annotation.Config;
import org.robolectric.shadows.ShadowCameraCharacteristics;
import org.robolectric.shadows.StreamConfigurationMapBuilder;
import org.skinlab.android.logic.FocusMode;

/**
 * The camera path through Robolectric's Camera2 shadows, as the Activity drives it: opening when
 * the renderer's surface is ready, a phone without a camera, a camera that cannot give the streams,
 * a disconnect, pause and resume, a lost GL context, and camera frames of the printed marker
 * through the same entry as the ImageReader's, reaching the tracker and the renderer's session.
 * Robolectric cannot configure a capture session below API 28 (its stubs start there): at 26 that
 * failure is reported in the status line, which is checked too.
 */
@RunWith(RobolectricTestRunner.class)
@Config(minSdk = 26, shadows = ShadowPermissionRequestState.class)
public class CameraSourceTest {
    private final AppDriver app = new AppDriver();

    @After
    public void finish() {
        app.finish();
    }

    @Test
    public void theCameraOpensOnceTheSurfaceIsReadyAndTracksTheMarker() throws InterruptedException {
        app.addBackCamera("0");
        app.start(true);
        assertNull("no camera before the renderer's surface exists", app.activity().camera);
        app.surfaceReady();
        assertNotNull(app.activity().camera);
        app.awaitStatus("the camera opened and tracking started", s -> s.contains("marker: searching"));
        if (Build.VERSION.SDK_INT >= 28) {
            app.await("the capture running", () -> !app.status().contains("\n"));
        } else {
            app.awaitStatus("Robolectric's missing capture session reported, not thrown",
                    s -> s.contains("cannot start the camera"));
        }
        app.feedMarkerFrame(1_000_000_000L);
        String status = app.awaitStatus("the marker tracked", s -> s.contains("marker: tracking"));
        assertTrue("the followed id, the markers in view and the tracker's time are shown: " + status,
                status.matches("(?s).*marker: tracking id 0, 1 in view \\(\\d+\\.\\d ms\\).*"));
    }

    @Test
    public void aPhoneWithoutACameraSaysSo() {
        app.start(true);
        app.surfaceReady();
        app.awaitStatus("the problem shown", s -> s.contains("this device has no camera"));
    }

    @Test
    public void aCameraWithoutTheNeededStreamsIsReportedNotFatal() {
        CameraCharacteristics c = ShadowCameraCharacteristics.newCameraCharacteristics();
        shadowOf(c).set(CameraCharacteristics.LENS_FACING, CameraCharacteristics.LENS_FACING_BACK);
        shadowOf(c).set(CameraCharacteristics.SCALER_STREAM_CONFIGURATION_MAP, StreamConfigurationMapBuilder.newBuilder()
                .addOutputSize(android.graphics.ImageFormat.PRIVATE, new Size(1280, 960)).build());
        shadowOf(app.cameras()).addCamera("0", c);
        app.start(true);
        app.surfaceReady();
        app.awaitStatus("the open failure shown", s -> s.contains("cannot open the camera: the camera lists no YUV"));
        assertTrue("the thread lives on", AppDriver.thread("camera").isAlive());
    }

    @Test
    public void aDisconnectIsReportedAndAResumeOpensAgain() {
        app.addBackCamera("0");
        app.start(true);
        app.surfaceReady();
        app.awaitStatus("open", s -> s.contains("marker: searching"));
        shadowOf(app.cameras()).triggerDisconnect();
        app.awaitStatus("the disconnect shown", s -> s.contains("the camera was disconnected"));
        CameraSource lost = app.activity().camera;
        app.controller.pause();
        assertNull("closed on pause", app.activity().camera);
        app.controller.resume();
        assertNull("not before the renderer's surface is back", app.activity().camera);
        app.surfaceReadyAgain();
        assertNotNull(app.activity().camera);
        assertNotSame(lost, app.activity().camera);
        app.awaitStatus("the old problem cleared by the new camera", s -> !s.contains("disconnected"));
    }

    @Test
    public void aLostGlContextMovesTheCameraToTheNewTexture() {
        app.addBackCamera("0");
        app.start(true);
        app.surfaceReady();
        CameraSource firstCamera = app.activity().camera;
        app.surfaceReady(); // a new EGL context: a new texture
        assertNotSame("the camera reopened onto the new texture", firstCamera, app.activity().camera);
        app.awaitStatus("tracking with the new camera", s -> s.contains("marker: searching"));
    }

    @Test
    public void aFrameThatCannotBeReadIsReportedNotFatal() throws InterruptedException {
        app.addBackCamera("0");
        app.start(true);
        app.surfaceReady();
        app.awaitStatus("open", s -> s.contains("marker: searching"));
        app.feed(ByteBuffer.allocate(10), 4, 1, 640, 480, 1);
        app.awaitStatus("the tracking problem shown", s -> s.contains("tracking: bad Y plane layout"));
        app.feedMarkerFrame(2_000_000_000L);
        app.awaitStatus("and tracking goes on", s -> s.contains("marker: tracking"));
    }

    @Test
    public void aNewMarkerSizeRestartsTheTracking() throws InterruptedException {
        app.addBackCamera("0");
        app.start(true);
        app.surfaceReady();
        app.awaitStatus("open", s -> s.contains("marker: searching"));
        app.feedMarkerFrame(1_000_000_000L);
        app.awaitStatus("tracked", s -> s.contains("marker: tracking"));
        app.tap("Marker 100 mm");
        app.awaitStatus("a new session searches", s -> s.contains("marker: searching"));
        app.feedMarkerFrame(2_000_000_000L);
        app.awaitStatus("and finds the marker", s -> s.contains("marker: tracking"));
    }

    @Test
    public void focusModesAreCamera2s() {
        assertEquals(CameraMetadata.CONTROL_AF_MODE_CONTINUOUS_VIDEO, FocusMode.CONTINUOUS_VIDEO);
        assertEquals(CameraMetadata.CONTROL_AF_MODE_CONTINUOUS_PICTURE, FocusMode.CONTINUOUS_PICTURE);
    }
}
