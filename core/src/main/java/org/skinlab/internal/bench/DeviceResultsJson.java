package org.skinlab.internal.bench;

import java.io.IOException;
import java.io.OutputStream;

import com.fasterxml.jackson.core.JsonEncoding;
import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonGenerator;
import com.fasterxml.jackson.core.StreamWriteFeature;
import com.fasterxml.jackson.core.util.DefaultPrettyPrinter;

/**
 * {@code results-android.json}, a {@link DeviceResults} as JSON: the contract between the Android
 * app, which writes it, and {@code skinlab eval --add-device}, which reads it
 * ({@link DeviceResultsReader}). The format is documented in docs/evaluation.md ("The device
 * file"); a change to it is a new {@link #VERSION}. Written with jackson-core's streaming
 * generator (Android-safe, already core's JSON library); measured values rounded to 3 decimals,
 * as the evaluation's results.json stores them.
 */
public final class DeviceResultsJson {
    /** The value of the file's "format". */
    public static final String FORMAT = "skinlab-device-results";
    /** The value of the file's "version": the format's, not the app's. */
    public static final int VERSION = 1;
    /** The name the app gives the file. */
    public static final String FILE_NAME = "results-android.json";
    /** The value of "drawn"."skinning": the copies are skinned by the GPU. */
    static final String GPU_SKINNING = "gpu";

    private DeviceResultsJson() {
    }

    /** Writes {@code results} to {@code out} (UTF-8, indented); leaves {@code out} open. */
    public static void write(DeviceResults results, OutputStream out) throws IOException {
        JsonFactory factory = JsonFactory.builder().disable(StreamWriteFeature.AUTO_CLOSE_TARGET).build();
        try (JsonGenerator g = factory.createGenerator(out, JsonEncoding.UTF8)) {
            g.setPrettyPrinter(new DefaultPrettyPrinter());
            g.writeStartObject();
            g.writeStringField("format", FORMAT);
            g.writeNumberField("version", VERSION);
            app(g, results.app());
            g.writeStringField("started", results.started());
            g.writeNumberField("seconds", round(results.seconds()));
            device(g, results.device());
            gpu(g, results.gpu());
            protocol(g, results.protocol());
            g.writeArrayFieldStart("models");
            for (DeviceResults.ModelTimes m : results.models()) {
                model(g, m);
            }
            g.writeEndArray();
            g.writeArrayFieldStart("skipped");
            for (DeviceResults.Skipped k : results.skipped()) {
                g.writeStartObject();
                g.writeStringField("file", k.file());
                g.writeStringField("reason", k.reason());
                g.writeEndObject();
            }
            g.writeEndArray();
            drawn(g, results.drawn());
            g.writeEndObject();
        }
    }

    /** A measured value as stored: rounded to 3 decimals. */
    public static double round(double value) {
        return Math.round(value * 1000.0) / 1000.0;
    }

    private static void app(JsonGenerator g, DeviceResults.App app) throws IOException {
        g.writeObjectFieldStart("app");
        g.writeStringField("package", app.packageName());
        g.writeStringField("versionName", app.versionName());
        g.writeNumberField("versionCode", app.versionCode());
        g.writeEndObject();
    }

    private static void device(JsonGenerator g, DeviceResults.Device d) throws IOException {
        g.writeObjectFieldStart("device");
        g.writeStringField("manufacturer", d.manufacturer());
        g.writeStringField("model", d.model());
        g.writeStringField("device", d.device());
        g.writeStringField("release", d.release());
        g.writeNumberField("sdk", d.sdk());
        g.writeArrayFieldStart("abis");
        for (String abi : d.abis()) {
            g.writeString(abi);
        }
        g.writeEndArray();
        g.writeObjectFieldStart("cpu");
        g.writeNumberField("cores", d.cpu().cores());
        g.writeStringField("name", d.cpu().name());
        g.writeStringField("nameFrom", d.cpu().nameFrom());
        g.writeEndObject();
        g.writeNumberField("refreshHz", round(d.refreshHz()));
        g.writeEndObject();
    }

    private static void gpu(JsonGenerator g, DeviceResults.Gpu gpu) throws IOException {
        g.writeObjectFieldStart("gpu");
        if (gpu.known()) {
            g.writeStringField("renderer", gpu.renderer());
            g.writeStringField("vendor", gpu.vendor());
            g.writeStringField("version", gpu.version());
        } else {
            g.writeStringField("unavailable", gpu.unavailable());
        }
        g.writeEndObject();
    }

    private static void protocol(JsonGenerator g, DeviceResults.Protocol p) throws IOException {
        g.writeObjectFieldStart("protocol");
        g.writeStringField("name", p.name());
        g.writeNumberField("rounds", p.times().rounds());
        g.writeNumberField("firstWarmupSeconds", p.times().firstWarmupSeconds());
        g.writeNumberField("warmupSeconds", p.times().warmupSeconds());
        g.writeNumberField("seconds", p.times().seconds());
        g.writeEndObject();
    }

    private static void model(JsonGenerator g, DeviceResults.ModelTimes m) throws IOException {
        g.writeStartObject();
        g.writeStringField("file", m.file());
        g.writeNumberField("positionsSkinned", m.shape().positionsSkinned());
        g.writeNumberField("renderVertices", m.shape().renderVertices());
        g.writeNumberField("joints", m.shape().joints());
        g.writeNumberField("influences", m.shape().influences());
        g.writeArrayFieldStart("methods");
        for (FrameTimes.Result r : m.methods()) {
            g.writeStartObject();
            g.writeStringField("method", r.method().key());
            g.writeStringField("kernel", r.kernel());
            g.writeNumberField("frames", r.frames());
            spread(g, "micros", r.micros());
            g.writeEndObject();
        }
        g.writeEndArray();
        g.writeEndObject();
    }

    private static void drawn(JsonGenerator g, DeviceResults.Drawn d) throws IOException {
        g.writeObjectFieldStart("drawn");
        if (!d.measured()) {
            g.writeStringField("unavailable", d.unavailable());
            g.writeEndObject();
            return;
        }
        g.writeStringField("file", d.file());
        g.writeStringField("skinning", GPU_SKINNING);
        // GLSurfaceView swaps with vsync: no fps exceeds the display's refresh rate (device.refreshHz).
        g.writeBooleanField("vsync", true);
        g.writeNumberField("seconds", d.seconds());
        g.writeNumberField("rounds", d.rounds());
        g.writeNumberField("warmupFrames", d.warmupFrames());
        g.writeArrayFieldStart("points");
        for (DeviceResults.DrawnPoint p : d.points()) {
            g.writeStartObject();
            g.writeNumberField("copies", p.copies());
            g.writeStringField("method", p.method().key());
            g.writeNumberField("frames", p.frames());
            spread(g, "fps", p.fps());
            g.writeEndObject();
        }
        g.writeEndArray();
        g.writeEndObject();
    }

    /** {@code name: {"median", "min", "max", "q1", "q3", "runs": [...]}}, the evaluation's layout of a spread. */
    private static void spread(JsonGenerator g, String name, Spread s) throws IOException {
        g.writeObjectFieldStart(name);
        g.writeNumberField("median", round(s.median()));
        g.writeNumberField("min", round(s.min()));
        g.writeNumberField("max", round(s.max()));
        g.writeNumberField("q1", round(s.lowerQuartile()));
        g.writeNumberField("q3", round(s.upperQuartile()));
        g.writeArrayFieldStart("runs");
        for (double r : s.runs()) {
            g.writeNumber(round(r));
        }
        g.writeEndArray();
        g.writeEndObject();
    }
}
