package org.skinlab.internal.bench;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.skinlab.skinning.SkinningMethod;

/**
 * The device file written and read back: every value survives (rounded to 3 decimals), and each
 * kind of bad file is refused naming the file, the JSON pointer of the fault and what was wrong.
 */
class DeviceResultsJsonTest {
    private static final String FILE = "results-android.json";

    /** A measurement with both parts, its runs given to more decimals than the file keeps. */
    static DeviceResults sample() {
        DeviceResults.Device device = new DeviceResults.Device("samsung", "SM-G935F", "hero2lte", "8.0.0", 26,
                List.of("arm64-v8a", "armeabi-v7a"), new DeviceResults.Cpu(8, "Samsung Exynos 8890", "/proc/cpuinfo"),
                60.0001);
        DeviceResults.ModelTimes walk = new DeviceResults.ModelTimes("humanoid-walk.dae",
                new FrameBench.Shape(951, 950, 19, 4), List.of(
                        new FrameTimes.Result(SkinningMethod.LBS, "scalar", Spread.of(810.1234, 805, 830.5, 799.25, 812),
                                2400),
                        new FrameTimes.Result(SkinningMethod.DQS, "scalar", Spread.of(900, 901, 899, 950, 902), 2200)));
        DeviceResults.Drawn drawn = new DeviceResults.Drawn("humanoid-walk.dae", 2, 5, 10, List.of(
                new DeviceResults.DrawnPoint(1, SkinningMethod.LBS, Spread.of(60, 59.9, 60, 60, 59.8), 600),
                new DeviceResults.DrawnPoint(12, SkinningMethod.DQS, Spread.of(31.5, 30, 32, 31, 30.75), 310)), null);
        return new DeviceResults(new DeviceResults.App("org.skinlab.android", "0.1.0", 1), "2025-03-01T10:00:00Z",
                301.25, device, DeviceResults.Gpu.of("Mali-T880", "ARM", "OpenGL ES 3.2 v1.r22p0"),
                new DeviceResults.Protocol("full", new FrameTimes.Protocol(5, 2, 0.5, 1)), List.of(walk),
                List.of(new DeviceResults.Skipped("broken.dae", "broken.dae: not a COLLADA document")), drawn);
    }

    static String json(DeviceResults results) throws IOException {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        DeviceResultsJson.write(results, out);
        return out.toString(StandardCharsets.UTF_8);
    }

    private static DeviceResults read(String json) throws InvalidDeviceResults {
        return DeviceResultsReader.read(json.getBytes(StandardCharsets.UTF_8), FILE);
    }

    @Test
    void whatIsWrittenIsReadBack() throws Exception {
        DeviceResults written = sample();
        String text = json(written);
        assertTrue(text.startsWith("{\n  \"format\" : \"skinlab-device-results\",\n  \"version\" : 1,"), text);
        DeviceResults read = read(text);
        assertEquals(written.app(), read.app());
        assertEquals(written.started(), read.started());
        assertEquals(301.25, read.seconds());
        assertEquals(60.0, read.device().refreshHz(), "rounded to 3 decimals");
        assertEquals(written.device().cpu(), read.device().cpu());
        assertEquals(written.device().abis(), read.device().abis());
        assertEquals(written.gpu(), read.gpu());
        assertEquals(written.protocol(), read.protocol());
        DeviceResults.ModelTimes m = read.models().get(0);
        assertEquals("humanoid-walk.dae", m.file());
        assertEquals(new FrameBench.Shape(951, 950, 19, 4), m.shape());
        FrameTimes.Result lbs = m.methods().get(0);
        assertEquals(SkinningMethod.LBS, lbs.method());
        assertEquals(2400, lbs.frames());
        assertArrayEquals(new double[] {810.123, 805, 830.5, 799.25, 812}, lbs.micros().runs());
        assertEquals(810.123, lbs.micros().median());
        assertEquals(805, lbs.micros().lowerQuartile());
        assertTrue(read.drawn().measured());
        assertEquals(12, read.drawn().points().get(1).copies());
        assertEquals(31, read.drawn().points().get(1).fps().median());
        assertEquals(10, read.drawn().warmupFrames());
        assertEquals(written.skipped(), read.skipped());
    }

    @Test
    void aGpuPartThatWasNotMeasuredSaysWhy() throws Exception {
        DeviceResults s = sample();
        DeviceResults without = new DeviceResults(s.app(), s.started(), s.seconds(), s.device(),
                DeviceResults.Gpu.unavailable("the GL thread drew no frame"), s.protocol(), s.models(), s.skipped(),
                DeviceResults.Drawn.unavailable("the GL thread drew no frame in 5 s"));
        String text = json(without);
        assertTrue(text.contains("\"drawn\" : {\n    \"unavailable\" : \"the GL thread drew no frame in 5 s\"\n  }"), text);
        DeviceResults read = read(text);
        assertFalse(read.drawn().measured());
        assertEquals("the GL thread drew no frame in 5 s", read.drawn().unavailable());
        assertFalse(read.gpu().known());
        assertNull(read.gpu().renderer());
    }

    @Test
    void aCpuWithoutANameIsWrittenAsNull() throws Exception {
        DeviceResults s = sample();
        DeviceResults.Device d = s.device();
        DeviceResults nameless = new DeviceResults(s.app(), s.started(), s.seconds(), new DeviceResults.Device(
                d.manufacturer(), d.model(), d.device(), d.release(), d.sdk(), d.abis(),
                new DeviceResults.Cpu(4, null, null), d.refreshHz()), s.gpu(), s.protocol(), s.models(), s.skipped(),
                s.drawn());
        String text = json(nameless);
        assertTrue(text.contains("\"name\" : null"), text);
        assertEquals(new DeviceResults.Cpu(4, null, null), read(text).device().cpu());
    }

    @Test
    void badFilesAreRefusedNamingTheFileAndTheJsonPointer() throws Exception {
        String good = json(sample());
        refused("{ \"format\": ", "/format", "not valid JSON");
        refused("[1, 2]", "", "not a JSON object");
        refused("", "", "empty");
        refused(good.replace("skinlab-device-results", "something-else"), "/format",
                "not a device file: the format is \"something-else\"");
        refused(good.replace("\"version\" : 1", "\"version\" : 2"), "/version", "newer app");
        refused(good.replace("\"model\" : \"SM-G935F\",", ""), "/device/model", "missing: expected a string");
        refused(good.replace("\"sdk\" : 26", "\"sdk\" : \"26\""), "/device/sdk",
                "expected a whole number, not the string \"26\"");
        refused(good.replace("810.123", "-810.123"), "/models/0/methods/0/micros/runs/0",
                "a time must be a positive number, not -810.123");
        refused(good.replace("\"median\" : 810.123", "\"median\" : 700"), "/models/0/methods/0/micros/median",
                "700.0 is not the median of its runs (810.123)");
        refused(good.replace("\"method\" : \"dqs\"", "\"method\" : \"lbs\""), "/models/0/methods/1/method",
                "lbs is measured twice");
        refused(good.replace("\"method\" : \"dqs\"", "\"method\" : \"xyz\""), "/models/0/methods/1/method",
                "unknown skinning method");
        refused(good.replace("\"rounds\" : 5,\n    \"firstWarmupSeconds\"", "\"rounds\" : 3,\n    \"firstWarmupSeconds\""),
                "/protocol/rounds", "at least 5");
        refused(good.replace("\"format\"", "\"version\" : 1, \"format\""), "/version", "Duplicate field");
    }

    private static void refused(String json, String pointer, String problem) {
        InvalidDeviceResults e = assertThrows(InvalidDeviceResults.class, () -> read(json), json);
        assertEquals(FILE, e.file());
        assertEquals(pointer, e.pointer(), e.getMessage());
        assertTrue(e.getMessage().startsWith(FILE + ": " + (pointer.isEmpty() ? "" : pointer + ": ")), e.getMessage());
        assertTrue(e.problem().contains(problem), e.getMessage());
    }
}
