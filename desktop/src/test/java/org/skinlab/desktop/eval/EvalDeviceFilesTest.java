package org.skinlab.desktop.eval;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.skinlab.internal.bench.DeviceResults;
import org.skinlab.internal.bench.DeviceResultsJson;
import org.skinlab.internal.bench.FrameBench;
import org.skinlab.internal.bench.FrameTimes;
import org.skinlab.internal.bench.Spread;
import org.skinlab.desktop.Cli;
import org.skinlab.desktop.ExitCodes;
import org.skinlab.skinning.SkinningMethod;

/**
 * {@code skinlab eval --add-device}: a phone's file, written by the app's code (core's
 * {@link DeviceResultsJson}), added to a copy of the shared quick run's report, whose README then
 * shows its numbers, every one a value of results.json, with every figure (the pictures kept as
 * the measuring run drew them) and nothing else changed; the same phone and app version replace
 * their earlier file; a new run keeps the phones of the results it replaces; and bad files are
 * refused naming the file and the JSON pointer, leaving results.json as it was. Before any phone,
 * the quick run's report says what no phone measured.
 */
class EvalDeviceFilesTest {
    private static final ObjectMapper JSON = new ObjectMapper();

    @TempDir
    Path dir;

    /**
     * A phone's measurement as the app writes it: the two models the time section also times here,
     * every method, and the GPU part, with numbers chosen to be found in the report.
     */
    static DeviceResults phone(String model, String version, boolean drawn) {
        List<DeviceResults.ModelTimes> models = new ArrayList<>();
        double base = 1000;
        for (String file : List.of("humanoid-walk.dae", "tentacle-wave.dae")) {
            List<FrameTimes.Result> methods = new ArrayList<>();
            for (SkinningMethod m : SkinningMethod.values()) {
                base += 111.111;
                methods.add(new FrameTimes.Result(m, "scalar", Spread.of(base, base - 10, base + 20, base - 5, base + 7),
                        250));
            }
            models.add(new DeviceResults.ModelTimes(file, new FrameBench.Shape(951, 950, 19, 4), methods));
        }
        List<DeviceResults.DrawnPoint> points = new ArrayList<>();
        for (int copies : new int[] {1, 4, 8, 12}) {
            for (SkinningMethod m : List.of(SkinningMethod.LBS, SkinningMethod.DQS, SkinningMethod.COR)) {
                // Runs at most the display's 60 Hz: the median 0.4 below the best, quartiles 0.2 either side.
                double fps = Math.min(60, 600.0 / copies) - m.ordinal() * 0.25;
                points.add(new DeviceResults.DrawnPoint(copies, m, Spread.of(fps - 0.4, fps - 0.2, fps - 0.6, fps,
                        fps - 0.8), 120));
            }
        }
        return new DeviceResults(new DeviceResults.App("org.skinlab.android", version, 1), "2025-03-01T10:00:00Z",
                301.5, new DeviceResults.Device("samsung", model, "hero2lte", "8.0.0", 26, List.of("arm64-v8a"),
                        new DeviceResults.Cpu(8, "Samsung Exynos 8890", "/proc/cpuinfo"), 60),
                DeviceResults.Gpu.of("Mali-T880", "ARM", "OpenGL ES 3.2"),
                new DeviceResults.Protocol("full", new FrameTimes.Protocol(5, 2, 0.5, 1)), models, List.of(),
                drawn ? new DeviceResults.Drawn("humanoid-walk.dae", 2, 5, 10, points, null)
                        : DeviceResults.Drawn.unavailable("the GL view drew no frame in 5 s"));
    }

    private Path write(DeviceResults results, String name) throws IOException {
        Path file = dir.resolve(name);
        try (OutputStream out = Files.newOutputStream(file)) {
            DeviceResultsJson.write(results, out);
        }
        return file;
    }

    private static void copy(Path from, Path to) throws IOException {
        Files.createDirectories(to);
        try (Stream<Path> files = Files.list(from)) {
            for (Path f : (Iterable<Path>) files::iterator) {
                Files.copy(f, to.resolve(f.getFileName()));
            }
        }
    }

    @Test
    void beforeAnyPhoneTheReportSaysWhatNoPhoneMeasured() {
        EvalQuickRun run = EvalQuickRun.get();
        JsonNode phone = run.section("phone");
        assertEquals(0, phone.get("devices").size());
        assertTrue(phone.get("figureSkipped").asText().startsWith("no phone has been added"));
        assertTrue(run.readme.contains("No phone has been added yet, so these numbers exist for no phone"), run.readme);
        assertTrue(run.readme.contains("with 1, 4, 8 and 12 copies"), run.readme);
        // This machine's scalar kernels, for scale, as the time section measured them.
        assertTrue(phone.get("here").size() > 0);
        assertTrue(run.readme.contains("| `humanoid-walk.dae` | LBS | "), run.readme);
    }

    @Test
    void aPhoneIsAddedAndTheReportIsWrittenFromResultsAlone() throws Exception {
        EvalQuickRun run = EvalQuickRun.get();
        Path report = dir.resolve("report");
        copy(run.dir, report);
        Path file = write(phone("SM-G935F", "0.1.0", true), "results-android.json");

        Cli cli = Cli.run("eval", "--add-device", file.toString(), "--out", report.toString());
        assertEquals(ExitCodes.OK, cli.status, cli.toString());
        assertTrue(cli.out.startsWith("eval: added samsung SM-G935F (hero2lte), Android 8.0.0 in "), cli.out);
        JsonNode results = JSON.readTree(report.resolve("results.json").toFile());
        String readme = Files.readString(report.resolve("README.md"));
        JsonNode devices = results.at("/sections/phone/devices");
        assertEquals(1, devices.size());
        assertEquals("results-android.json", devices.get(0).get("file").asText());
        // The phone's numbers, read back from its file: a median with its quartiles, what it leaves a
        // character at 60 Hz (1e6 / 1111.111 µs = 900 fps, so 60, 6.667 % of the frame), drawn fps.
        assertEquals(1111.111, devices.get(0).at("/results/models/0/methods/0/micros/median").asDouble());
        assertTrue(readme.contains("| `humanoid-walk.dae` | LBS | "), readme);
        assertTrue(readme.contains("1111.111 (1106.111–1118.111) | 60 (6.667 %)"), readme);
        assertTrue(readme.contains("| `SM-G935F` | GPU | LBS | 59.6 (59.4–59.8) | 59.6 (59.4–59.8) | 59.6 (59.4–59.8)"
                + " | 49.6 (49.4–49.8) |"),
                readme);
        assertTrue(readme.contains("`samsung SM-G935F (hero2lte), Android 8.0.0`"), readme);
        assertTrue(readme.contains("`Mali-T880`"), readme);
        assertFalse(readme.contains("No phone has been added yet"), readme);

        // Every number printed is a value of results.json, every PNG is linked (the pictures kept,
        // the phone's figure drawn), and the other sections are as the measuring run left them.
        List<String> linked = EvalReportCheck.figuresAndNumbers(report, results, readme);
        assertTrue(linked.contains("phone-drawn.png"), linked.toString());
        for (String png : EvalReportCheck.linked(run.readme)) {
            assertTrue(linked.contains(png), "still linked: " + png);
        }
        for (String key : List.of("load", "time", "crowds", "quality", "pictures", "tracking", "advice")) {
            assertEquals(run.results.at("/sections/" + key), results.at("/sections/" + key), key);
        }
        assertEquals(run.results.get("machine"), results.get("machine"));

        // The same phone and app version replace their file; another version is another column.
        Cli again = Cli.run("eval", "--add-device", write(phone("SM-G935F", "0.1.0", false), "again.json").toString(),
                "--out", report.toString());
        assertEquals(ExitCodes.OK, again.status, again.toString());
        assertTrue(again.out.startsWith("eval: replaced the earlier file of samsung SM-G935F"), again.out);
        results = JSON.readTree(report.resolve("results.json").toFile());
        assertEquals(1, results.at("/sections/phone/devices").size());
        assertEquals("again.json", results.at("/sections/phone/devices/0/file").asText());
        readme = Files.readString(report.resolve("README.md"));
        assertTrue(readme.contains("| `SM-G935F` | GPU | not measured: `the GL view drew no frame in 5 s` |"), readme);
        assertTrue(readme.contains("No figure: no added phone drew copies (its GPU part was not measured)."), readme);
        assertFalse(EvalReportCheck.linked(readme).contains("phone-drawn.png"), readme);
        Cli other = Cli.run("eval", "--add-device", write(phone("SM-G935F", "0.2.0", true), "newer.json").toString(),
                "--out", report.toString());
        assertEquals(ExitCodes.OK, other.status, other.toString());
        assertEquals(2, JSON.readTree(report.resolve("results.json").toFile()).at("/sections/phone/devices").size());
    }

    @Test
    void aNewRunKeepsThePhonesAddedToTheResultsItReplaces() throws Exception {
        ObjectNode earlier = JSON.createObjectNode();
        ObjectNode phone = earlier.putObject("phone");
        EvalPhoneSection.prepare(phone, null);
        ByteArrayOutputStream file = new ByteArrayOutputStream();
        DeviceResultsJson.write(phone("SM-G935F", "0.1.0", true), file);
        EvalPhoneSection.addDevice(phone, (ObjectNode) JSON.readTree(file.toByteArray()), "results-android.json",
                "2025-03-02T09:00:00Z");
        StringWriter log = new StringWriter();
        EvalContext context = new EvalContext(true, Cli.root(), new PrintWriter(log), new ViewerProcess(Object.class));
        context.useResults(JSON.createObjectNode());
        context.useEarlier(earlier);
        ObjectNode results = JSON.createObjectNode();
        new EvalPhoneSection().measure(context, results);
        assertEquals(phone.get("devices"), results.get("devices"));
        assertFalse(results.has("figureSkipped"), "the kept phone drew copies");
        assertEquals("the time section was not run", results.get("hereMissing").asText());
        assertTrue(log.toString().contains("phone: kept 1 phone(s)"), log.toString());
    }

    @Test
    void badFilesAreRefusedNamingTheJsonPointerAndChangeNothing() throws Exception {
        Path report = dir.resolve("report");
        Files.createDirectories(report);
        Files.writeString(report.resolve("results.json"), "{\"machine\": {\"cpu\": \"test\", \"command\": \"skinlab eval\"},"
                + " \"quick\": true, \"started\": \"2025-01-01T00:00:00Z\", \"seconds\": 1.5, \"sections\": {}}");
        byte[] before = Files.readAllBytes(report.resolve("results.json"));
        String good = new String(Files.readAllBytes(write(phone("SM-A", "1", true), "good.json")), StandardCharsets.UTF_8);
        String[][] cases = {
            {"not JSON at all", "", "not valid JSON"},
            {good.replace("skinlab-device-results", "results-ios"), "/format", "not a device file"},
            {good.replace("\"manufacturer\" : \"samsung\",", ""), "/device/manufacturer", "missing"},
            {good.replace("\"median\" : 1111.111", "\"median\" : -1111.111"), "/models/0/methods/0/micros/median",
                "a time must be a positive number, not -1111.111"},
        };
        for (String[] c : cases) {
            Path bad = dir.resolve("bad.json");
            Files.writeString(bad, c[0]);
            Cli cli = Cli.run("eval", "--add-device", bad.toString(), "--out", report.toString());
            assertEquals(ExitCodes.USAGE, cli.status, cli.toString());
            assertTrue(cli.err.contains(bad + ": " + (c[1].isEmpty() ? "" : c[1] + ": ")), cli.err);
            assertTrue(cli.err.contains(c[2]), cli.err);
            assertArrayEquals(before, Files.readAllBytes(report.resolve("results.json")), "results.json untouched");
            assertFalse(Files.exists(report.resolve("README.md")));
        }
        Cli missing = Cli.run("eval", "--add-device", dir.resolve("none.json").toString(), "--out", report.toString());
        assertEquals(ExitCodes.USAGE, missing.status, missing.toString());
        assertTrue(missing.err.contains("none.json: not found"), missing.err);
        Cli noReport = Cli.run("eval", "--add-device", dir.resolve("good.json").toString(), "--out",
                dir.resolve("nowhere").toString());
        assertEquals(ExitCodes.USAGE, noReport.status, noReport.toString());
        Cli quick = Cli.run("eval", "--quick", "--add-device", dir.resolve("good.json").toString(), "--out",
                report.toString());
        assertEquals(ExitCodes.USAGE, quick.status, quick.toString());

        // A results.json without a phone section (or a time section) gets one; the report says what
        // this machine did not measure.
        Cli added = Cli.run("eval", "--add-device", dir.resolve("good.json").toString(), "--out", report.toString());
        assertEquals(ExitCodes.OK, added.status, added.toString());
        JsonNode results = JSON.readTree(report.resolve("results.json").toFile());
        assertEquals("the time section was not run", results.at("/sections/phone/hereMissing").asText());
        String readme = Files.readString(report.resolve("README.md"));
        assertTrue(readme.contains("## A phone beside the thesis' Galaxy S7"), readme);
        EvalReportCheck.figuresAndNumbers(report, results, readme);
    }
}
