package org.skinlab.android;

import java.io.File;
import java.io.FileInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;

import android.app.Activity;
import android.content.ActivityNotFoundException;
import android.content.Intent;
import android.net.Uri;

import org.skinlab.android.logic.AppActions;
import org.skinlab.android.logic.DeviceMeasurement;
import org.skinlab.android.logic.DrawnCopies;
import org.skinlab.android.logic.MeasureProtocol;
import org.skinlab.internal.bench.DeviceResultsJson;

/**
 * The Activity's "Measure" and "Save results" (UI thread): starts a {@link DeviceMeasurement} of
 * the bundled models into the app's external files folder ({@code getExternalFilesDir(null)},
 * which {@code adb pull} reaches and which needs no permission; the app's own files folder when no
 * shared storage is mounted), stops it on a second tap, and saves a copy of its file where the user
 * chooses (the Storage Access Framework's {@code ACTION_CREATE_DOCUMENT}) on a thread of its own.
 * While a measurement runs the Activity holds its camera and its simulation off ({@link #holding}),
 * and the GL thread draws the measurement's copies ({@link DrawnCopies}).
 */
final class MeasureControl implements AppActions.Measuring {
    private final Activity activity;
    private final int saveRequest;
    private final List<String> models;
    private final MeasureProtocol protocol;
    private final DrawnCopies copies;
    private final Runnable hold;
    private final Runnable release;
    private final ExecutorService saving = Executors.newSingleThreadExecutor(r -> new Thread(r, "save-results"));
    /** The last measurement started (running or ended), or null. */
    private DeviceMeasurement measurement;
    private boolean holding;
    /** What saving a copy last said ("" before). */
    private volatile String saveNote = "";

    /**
     * Measures {@code models} (the APK's {@code assets/models}) by {@code protocol}, the GPU part
     * through {@code copies}; {@code hold} and {@code release} take the camera and the simulation
     * off and back; a save's document request is {@code saveRequest}.
     */
    MeasureControl(Activity activity, int saveRequest, List<String> models, MeasureProtocol protocol,
            DrawnCopies copies, Runnable hold, Runnable release) {
        this.activity = activity;
        this.saveRequest = saveRequest;
        this.models = models;
        this.protocol = protocol;
        this.copies = copies;
        this.hold = hold;
        this.release = release;
    }

    @Override
    public boolean running() {
        return measurement != null && measurement.running();
    }

    /** Whether the camera and the simulation are held off for a measurement (until {@link #poll} sees it end). */
    boolean holding() {
        return holding;
    }

    @Override
    public void toggle() {
        if (running()) {
            measurement.cancel();
            return;
        }
        File folder = activity.getExternalFilesDir(null);
        if (folder == null) {
            folder = activity.getFilesDir();
        }
        saveNote = "";
        measurement = new DeviceMeasurement(name -> activity.getAssets().open("models/" + name), models, protocol,
                copies, DeviceFacts.app(activity), DeviceFacts.of(activity), folder);
        holding = true;
        hold.run();
        measurement.start();
    }

    /** With each status refresh: once the measurement has ended, the camera and the simulation come back. */
    void poll() {
        if (holding && !running()) {
            holding = false;
            release.run();
        }
    }

    /** The measurement's line and the last save's, "" for none. */
    String[] statusLines() {
        return new String[] {measurement == null ? "" : measurement.status(), saveNote};
    }

    /**
     * The Activity leaves the screen: a measurement needs it in front (the GPU part draws there,
     * and a phone slows an app it does not show), so it stops and the status line says so.
     */
    void stop() {
        if (running()) {
            measurement.cancel();
        }
    }

    /** The Activity ends: a measurement stops, a copy being saved (a few kB) is finished, the threads end. */
    void close() {
        stop();
        saving.shutdown();
    }

    @Override
    public void saveCopy() {
        if (measurement == null || measurement.written() == null) {
            saveNote = running() ? "save: the measurement is still running" : "save: nothing measured yet (tap Measure)";
            return;
        }
        Intent create = new Intent(Intent.ACTION_CREATE_DOCUMENT).addCategory(Intent.CATEGORY_OPENABLE)
                .setType("application/json").putExtra(Intent.EXTRA_TITLE, DeviceResultsJson.FILE_NAME);
        try {
            activity.startActivityForResult(create, saveRequest);
        } catch (ActivityNotFoundException e) {
            saveNote = "save: no document picker here; the file is " + measurement.written().getPath();
        }
    }

    /** The document the user chose (or not) for request {@code requestCode}; false when it is not ours. */
    boolean onActivityResult(int requestCode, int resultCode, Intent data) {
        if (requestCode != saveRequest) {
            return false;
        }
        Uri target = resultCode == Activity.RESULT_OK && data != null ? data.getData() : null;
        File source = measurement == null ? null : measurement.written();
        if (target == null || source == null) {
            saveNote = "save: cancelled";
            return true;
        }
        saveNote = "save: saving a copy to " + target;
        saving.execute(() -> saveNote = copy(source, target));
        return true;
    }

    /** Copies {@code source} to the document {@code target} (the saving thread); says how it went. */
    private String copy(File source, Uri target) {
        try (InputStream in = new FileInputStream(source);
                OutputStream out = activity.getContentResolver().openOutputStream(target)) {
            if (out == null) {
                return "save: " + target + " cannot be written";
            }
            byte[] buffer = new byte[8192];
            for (int n; (n = in.read(buffer)) > 0;) {
                out.write(buffer, 0, n);
            }
            return "save: saved a copy to " + target;
        } catch (IOException | RuntimeException e) {
            return "save: " + target + ": " + e.getMessage();
        }
    }
}
