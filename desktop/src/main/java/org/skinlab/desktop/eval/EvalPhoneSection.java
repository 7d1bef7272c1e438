package org.skinlab.desktop.eval;

import java.util.List;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;

/**
 * Section "phone": phones beside the thesis' Galaxy S7 Edge. This machine measures no phone: the
 * Android app's "Measure" writes a device file (core's {@code DeviceResultsJson}: the scalar
 * kernels' time per frame of each bundled model and method, and the GPU's frames per second with
 * 1, 4, 8 and 12 copies), and {@code skinlab eval --add-device FILE} adds it here
 * ({@link EvalDeviceFiles}). {@link #measure} stores the thesis' numbers, copies this machine's
 * scalar frame times from the time section for scale, and keeps the phones an earlier run of the
 * same folder had added; until a phone is added, the report lists the numbers no phone has
 * produced.
 */
final class EvalPhoneSection implements EvalSection {
    static final String KEY = "phone";
    /** The thesis' phone (its 6.1: the cowboy, one mesh, skinned on the CPU and drawn). */
    static final String THESIS_PHONE = "Samsung Galaxy S7 Edge";
    static final int THESIS_PHONE_LBS_FPS = 4;
    static final int THESIS_PHONE_DQS_FPS = 3;
    static final int THESIS_PHONE_UNDEFORMED_FPS = 30;
    /** The display rate the "one character" column assumes: a frame is 1/60 s. */
    static final int DISPLAY_HZ = 60;
    /** The copies the app draws, the thesis' meshes. */
    static final int[] COPIES = {1, 4, 8, 12};

    @Override
    public String key() {
        return KEY;
    }

    @Override
    public String title() {
        return "A phone beside the thesis' Galaxy S7";
    }

    @Override
    public double estimatedSeconds(EvalContext context) {
        return 0; // copies numbers, measures nothing
    }

    @Override
    public void measure(EvalContext context, ObjectNode results) {
        prepare(results, context.measured("time"));
        JsonNode earlier = context.earlier(KEY);
        if (earlier != null && earlier.path("devices").isArray()) {
            for (JsonNode d : earlier.get("devices")) {
                ((ArrayNode) results.get("devices")).add(d.deepCopy());
            }
            context.say("phone: kept " + earlier.get("devices").size() + " phone(s) added to the earlier results");
        }
        skipReason(results);
    }

    /**
     * A phone section without phones: the thesis' numbers, the copies and display rate the report
     * names, and this machine's scalar frame times from {@code time} (the time section's results,
     * null when it was not run).
     */
    static void prepare(ObjectNode results, JsonNode time) {
        ObjectNode phone = results.putObject("thesisPhone");
        phone.put("device", THESIS_PHONE);
        phone.put("asset", "cowboy");
        phone.put("meshes", 1);
        phone.put("lbsFps", THESIS_PHONE_LBS_FPS);
        phone.put("dqsFps", THESIS_PHONE_DQS_FPS);
        phone.put("undeformedFps", THESIS_PHONE_UNDEFORMED_FPS);
        ArrayNode desktop = results.putArray("thesisDesktop");
        for (double[] t : EvalCrowdsThesis.THESIS) {
            desktop.addObject().put("meshes", (int) t[0]).put("dqsFps", t[1]).put("lbsFps", t[2]);
        }
        ArrayNode copies = results.putArray("copies");
        for (int c : COPIES) {
            copies.add(c);
        }
        results.put("displayHz", DISPLAY_HZ);
        results.put("frameMicros", EvalReport.round(1e6 / DISPLAY_HZ));
        if (time == null || !time.path("assets").isArray()) {
            results.put("hereMissing", "the time section was not run");
        } else {
            ArrayNode here = results.putArray("here");
            for (JsonNode asset : time.get("assets")) {
                for (JsonNode run : asset.path("runs")) {
                    if (isScalarWithEveryInfluence(run)) {
                        ObjectNode row = here.addObject();
                        row.put("file", asset.get("file").asText());
                        row.put("method", run.get("method").asText());
                        row.set("micros", scalarMicros(run));
                        putCharacter(row, row.at("/micros/median").asDouble());
                    }
                }
            }
        }
        results.putArray("devices");
    }

    /** Whether a run of the time section is core's scalar kernels with every influence. */
    static boolean isScalarWithEveryInfluence(JsonNode run) {
        return run.path("kernels").asText().equals("scalar") && run.path("influences").asText().equals("all");
    }

    /** A time-section run's frame time: its spread node ({@code EvalReport.putSpread}), copied. */
    static ObjectNode scalarMicros(JsonNode run) {
        return run.get("micros").deepCopy();
    }

    /**
     * What a frame time of {@code micros} leaves one character: the frames per second skinning
     * alone allows, those a {@value #DISPLAY_HZ} Hz display shows (at most its rate), and the
     * share of its frame in percent.
     */
    static void putCharacter(ObjectNode row, double micros) {
        double fps = 1e6 / micros;
        row.put("cpuFps", EvalReport.round(fps));
        row.put("fpsAt60Hz", EvalReport.round(Math.min(DISPLAY_HZ, fps)));
        row.put("framePercent", EvalReport.round(100 * micros / (1e6 / DISPLAY_HZ)));
    }

    /**
     * Adds a device file ({@code device}: as core's {@code DeviceResultsJson} writes it, checked)
     * read from {@code fileName} at {@code added} to the phone section {@code results}: in place of
     * an earlier file of the same device (maker, model, device name) and app version, else after
     * the others. Returns whether it replaced one.
     */
    static boolean addDevice(ObjectNode results, ObjectNode device, String fileName, String added) {
        ObjectNode entry = JsonNodeFactory.instance.objectNode();
        entry.put("file", fileName);
        entry.put("added", added);
        entry.set("results", device);
        ArrayNode characters = entry.putArray("characters");
        for (JsonNode model : device.get("models")) {
            for (JsonNode method : model.get("methods")) {
                ObjectNode row = characters.addObject();
                row.put("file", model.get("file").asText());
                row.put("method", method.get("method").asText());
                putCharacter(row, method.at("/micros/median").asDouble());
            }
        }
        ArrayNode devices = (ArrayNode) results.get("devices");
        boolean replaced = false;
        for (int i = 0; i < devices.size() && !replaced; i++) {
            if (identity(devices.get(i).get("results")).equals(identity(device))) {
                devices.set(i, entry);
                replaced = true;
            }
        }
        if (!replaced) {
            devices.add(entry);
        }
        skipReason(results);
        return replaced;
    }

    /** What makes two device files the same phone and app: maker, model, device name, app version. */
    private static List<String> identity(JsonNode device) {
        return List.of(device.at("/device/manufacturer").asText(), device.at("/device/model").asText(),
                device.at("/device/device").asText(), device.at("/app/versionName").asText());
    }

    /** How the report names a device: maker, model, device name, Android release. */
    static String name(JsonNode device) {
        return device.at("/device/manufacturer").asText() + " " + device.at("/device/model").asText() + " ("
                + device.at("/device/device").asText() + "), Android " + device.at("/device/release").asText();
    }

    /** Why there is no figure (no phone drew copies), or none when one did. */
    static void skipReason(ObjectNode results) {
        results.remove("figureSkipped");
        for (JsonNode d : results.get("devices")) {
            if (d.at("/results/drawn").has("points")) {
                return;
            }
        }
        results.put("figureSkipped", results.get("devices").size() == 0
                ? "no phone has been added (it shows a phone's drawn frames per second against copies)"
                : "no added phone drew copies (its GPU part was not measured)");
    }

    @Override
    public void report(JsonNode results, EvalReport report) {
        EvalPhoneReport.write(results, report);
    }
}
