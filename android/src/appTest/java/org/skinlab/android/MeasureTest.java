package org.skinlab.android;

import static org.junit.Assert.assertArrayEquals;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertTrue;
import static org.robolectric.Shadows.shadowOf;

import java.io.ByteArrayOutputStream;
import java.io.File;
import java.nio.file.Files;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

import android.app.Activity;
import android.content.Intent;
import android.net.Uri;
import android.os.Build;

import org.junit.After;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.robolectric.RobolectricTestRunner;
import org.robolectric.annotation.Config;
import org.robolectric.shadows.ShadowActivity;
import org.skinlab.android.logic.MeasureProtocol;
import org.skinlab.internal.bench.DeviceResults;
import org.skinlab.internal.bench.DeviceResultsJson;
import org.skinlab.internal.bench.DeviceResultsReader;
import org.skinlab.internal.bench.FrameTimes;
import org.skinlab.internal.bench.Rounds;
import org.skinlab.skinning.SkinningMethod;

/**
 * "Measure" in the real Activity (Robolectric, at minSdk and targetSdk), launched with the quick
 * protocol's extra: a tap writes results-android.json into the app's external files folder, which
 * names the device as the platform reports it, times every bundled model with every method in at
 * least five rounds and names the test's damaged model as skipped; Robolectric's GLSurfaceView
 * draws nothing, so the file says why the GPU part is missing, and the status line says where the
 * file went. "Save results" copies it to the document the user picks. A second tap stops a
 * measurement, and so does closing the Activity, whose threads all end.
 */
@RunWith(RobolectricTestRunner.class)
@Config(minSdk = 26, shadows = ShadowPermissionRequestState.class)
public class MeasureTest {
    private final AppDriver app = new AppDriver();
    private final Set<Thread> before = new HashSet<>(AppDriver.appThreads());

    @After
    public void finish() {
        app.finish();
    }

    private Intent launch(String protocol) {
        Intent intent = new Intent(app.app(), SkinlabActivity.class);
        return protocol == null ? intent : intent.putExtra(MeasureProtocol.EXTRA, protocol);
    }

    @Test
    public void aTapWritesTheDeviceFileAndSaysWhyNothingWasDrawn() throws Exception {
        app.start(true, launch("quick"));
        app.tap("Measure");
        assertNotNull("a second tap would stop it", app.button("Stop measuring"));
        File folder = app.activity().getExternalFilesDir(null);
        File file = new File(folder, DeviceResultsJson.FILE_NAME);
        String status = app.awaitStatus("the file written", s -> s.contains("measure (quick): wrote "));
        assertTrue(status, status.contains("wrote " + file.getPath()));
        assertTrue("the status line says the GPU part is missing: " + status,
                status.contains("; the GPU part was not measured: the GL view drew no frame"));
        assertNotNull("done: the button starts again", app.button("Measure"));

        DeviceResults r = DeviceResultsReader.read(Files.readAllBytes(file.toPath()), file.getName());
        assertEquals(Build.MANUFACTURER, r.device().manufacturer());
        assertEquals(Build.MODEL, r.device().model());
        assertEquals(Build.DEVICE, r.device().device());
        assertEquals(Build.VERSION.RELEASE, r.device().release());
        assertEquals(Build.VERSION.SDK_INT, r.device().sdk());
        assertEquals(Arrays.asList(Build.SUPPORTED_ABIS), r.device().abis());
        assertEquals(Runtime.getRuntime().availableProcessors(), r.device().cpu().cores());
        assertTrue(r.device().refreshHz() > 0);
        assertEquals("org.skinlab.android", r.app().packageName());
        assertEquals("0.1.0", r.app().versionName());
        assertEquals("quick", r.protocol().name());

        String[] assets = app.activity().getAssets().list("models");
        List<String> bundled = new ArrayList<>(Arrays.asList(assets));
        bundled.remove("zz-broken.dae");
        List<String> timed = new ArrayList<>();
        for (DeviceResults.ModelTimes m : r.models()) {
            timed.add(m.file());
            assertEquals(Arrays.asList(SkinningMethod.values()), m.methods().stream().map(FrameTimes.Result::method)
                    .toList());
            for (FrameTimes.Result method : m.methods()) {
                assertTrue(m.file() + " " + method.method(), method.micros().count() >= Rounds.MIN_RUNS);
            }
        }
        assertEquals(new HashSet<>(bundled), new HashSet<>(timed));
        assertEquals(1, r.skipped().size());
        assertEquals("zz-broken.dae", r.skipped().get(0).file());

        // Robolectric's GLSurfaceView never calls its renderer: no frame, no GL strings.
        assertFalse(r.drawn().measured());
        assertTrue(r.drawn().unavailable(), r.drawn().unavailable().contains("the GL view drew no frame"));
        assertFalse(r.gpu().known());

        // Save results: the document the user picks gets the same bytes.
        app.tap("Save results");
        ShadowActivity.IntentForResult picker = shadowOf(app.activity()).getNextStartedActivityForResult();
        assertNotNull("the document picker opened", picker);
        assertEquals(Intent.ACTION_CREATE_DOCUMENT, picker.intent.getAction());
        assertEquals(DeviceResultsJson.FILE_NAME, picker.intent.getStringExtra(Intent.EXTRA_TITLE));
        Uri chosen = Uri.parse("content://org.skinlab.test.documents/document/results-android.json");
        ByteArrayOutputStream saved = new ByteArrayOutputStream();
        shadowOf(app.activity().getContentResolver()).registerOutputStream(chosen, saved);
        shadowOf(app.activity()).receiveResult(picker.intent, Activity.RESULT_OK, new Intent().setData(chosen));
        app.awaitStatus("the copy saved", s -> s.contains("save: saved a copy to " + chosen));
        assertArrayEquals(Files.readAllBytes(file.toPath()), saved.toByteArray());
    }

    @Test
    public void saveBeforeAnyMeasurementSaysSo() {
        app.start(true);
        app.tap("Save results");
        assertTrue(app.status(), app.status().contains("save: nothing measured yet (tap Measure)"));
    }

    @Test
    public void aSecondTapStopsItAndClosingTheActivityEndsItsThreads() throws Exception {
        app.start(true);
        app.tap("Measure");
        app.awaitStatus("measuring", s -> s.contains("\nmeasure: "));
        app.tap("Stop measuring");
        app.awaitStatus("stopped", s -> s.contains("measure: stopped"));
        assertFalse(new File(app.activity().getExternalFilesDir(null), DeviceResultsJson.FILE_NAME).exists());

        app.tap("Measure");
        app.awaitStatus("measuring again", s -> s.contains("measure: CPU"));
        app.controller.pause().stop().destroy();
        for (Thread t : AppDriver.appThreads()) {
            if (!before.contains(t)) {
                t.join(AppDriver.TIMEOUT_MILLIS);
                assertFalse(t.getName() + " outlived onDestroy", t.isAlive());
            }
        }
    }
}
