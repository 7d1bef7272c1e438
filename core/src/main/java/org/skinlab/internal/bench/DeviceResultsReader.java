package org.skinlab.internal.bench;

import java.io.IOException;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.core.JsonToken;
import com.fasterxml.jackson.core.StreamReadConstraints;
import com.fasterxml.jackson.core.StreamReadFeature;
import org.skinlab.skinning.SkinningMethod;

/**
 * Reads a device file ({@link DeviceResultsJson}) and checks every value the format promises:
 * the format's name and version, every field present with its type, times and frame rates
 * positive, each spread's median, extremes and quartiles those of its runs, one run per round. A
 * problem is an {@link InvalidDeviceResults} naming the file, the JSON pointer of the value
 * and what was expected; nothing is read past the first problem.
 */
public final class DeviceResultsReader {
    /** Larger than any device file the app writes (a few kB); a larger file is refused unread. */
    public static final int MAX_BYTES = 4 << 20;
    /** How far a stored median, extreme or quartile may lie from its runs' (both rounded to 3 decimals). */
    private static final double ROUNDING = 0.002;

    private final String file;

    private DeviceResultsReader(String file) {
        this.file = file;
    }

    /** The device file {@code bytes}, named {@code file} in messages. */
    public static DeviceResults read(byte[] bytes, String file) throws InvalidDeviceResults {
        return new DeviceResultsReader(file).results(bytes);
    }

    private DeviceResults results(byte[] bytes) throws InvalidDeviceResults {
        if (bytes.length > MAX_BYTES) {
            throw new InvalidDeviceResults(file, "", bytes.length + " bytes: larger than any device file ("
                    + MAX_BYTES + " at most)");
        }
        Value root = parse(bytes);
        String format = root.get("format").string();
        if (!format.equals(DeviceResultsJson.FORMAT)) {
            throw root.get("format").problem("not a device file: the format is \"" + format + "\", expected \""
                    + DeviceResultsJson.FORMAT + "\"");
        }
        Value version = root.get("version");
        if (version.integer(1) != DeviceResultsJson.VERSION) {
            throw version.problem("format version " + version.integer(1) + "; this skinlab reads version "
                    + DeviceResultsJson.VERSION + (version.integer(1) > DeviceResultsJson.VERSION
                            ? " (the file is from a newer app: update skinlab)" : ""));
        }
        Value app = root.get("app");
        DeviceResults.App a = new DeviceResults.App(app.get("package").text(), app.get("versionName").text(),
                app.get("versionCode").integer(0));
        DeviceResults.Protocol protocol = protocol(root.get("protocol"));
        List<DeviceResults.ModelTimes> models = new ArrayList<>();
        Value list = root.get("models");
        if (list.size() == 0) {
            throw list.problem("no model was measured");
        }
        Set<String> files = new HashSet<>();
        for (int i = 0; i < list.size(); i++) {
            DeviceResults.ModelTimes m = model(list.at(i), protocol.times().rounds());
            if (!files.add(m.file())) {
                throw list.at(i).get("file").problem("\"" + m.file() + "\" is measured twice");
            }
            models.add(m);
        }
        List<DeviceResults.Skipped> skipped = new ArrayList<>();
        Value notMeasured = root.get("skipped");
        for (int i = 0; i < notMeasured.size(); i++) {
            Value k = notMeasured.at(i);
            skipped.add(new DeviceResults.Skipped(k.get("file").text(), k.get("reason").text()));
        }
        return new DeviceResults(a, root.get("started").text(), root.get("seconds").positive(), device(
                root.get("device")), gpu(root.get("gpu")), protocol, models, skipped, drawn(root.get("drawn")));
    }

    private static DeviceResults.Device device(Value d) throws InvalidDeviceResults {
        List<String> abis = new ArrayList<>();
        Value list = d.get("abis");
        for (int i = 0; i < list.size(); i++) {
            abis.add(list.at(i).text());
        }
        Value cpu = d.get("cpu");
        return new DeviceResults.Device(d.get("manufacturer").text(), d.get("model").text(), d.get("device").text(),
                d.get("release").text(), (int) d.get("sdk").integer(1), abis, new DeviceResults.Cpu(
                        (int) cpu.get("cores").integer(1), cpu.get("name").textOrNull(),
                        cpu.get("nameFrom").textOrNull()), d.get("refreshHz").positive());
    }

    private static DeviceResults.Gpu gpu(Value g) throws InvalidDeviceResults {
        if (g.has("unavailable")) {
            return DeviceResults.Gpu.unavailable(g.get("unavailable").text());
        }
        return DeviceResults.Gpu.of(g.get("renderer").text(), g.get("vendor").text(), g.get("version").text());
    }

    private static DeviceResults.Protocol protocol(Value p) throws InvalidDeviceResults {
        Value rounds = p.get("rounds");
        if (rounds.integer(1) < Rounds.MIN_RUNS) {
            throw rounds.problem(rounds.integer(1) + " rounds: the evaluation's timings take at least "
                    + Rounds.MIN_RUNS);
        }
        return new DeviceResults.Protocol(p.get("name").text(), new FrameTimes.Protocol((int) rounds.integer(1),
                p.get("firstWarmupSeconds").nonNegative(), p.get("warmupSeconds").nonNegative(),
                p.get("seconds").positive()));
    }

    private static DeviceResults.ModelTimes model(Value m, int rounds) throws InvalidDeviceResults {
        FrameBench.Shape shape = new FrameBench.Shape((int) m.get("positionsSkinned").integer(0),
                (int) m.get("renderVertices").integer(0), (int) m.get("joints").integer(0),
                (int) m.get("influences").integer(0));
        List<FrameTimes.Result> methods = new ArrayList<>();
        Value list = m.get("methods");
        if (list.size() == 0) {
            throw list.problem("no method was measured");
        }
        Set<SkinningMethod> seen = new HashSet<>();
        for (int i = 0; i < list.size(); i++) {
            Value r = list.at(i);
            SkinningMethod method = method(r.get("method"));
            if (!seen.add(method)) {
                throw r.get("method").problem(method.key() + " is measured twice");
            }
            methods.add(new FrameTimes.Result(method, r.get("kernel").text(), spread(r.get("micros"), rounds, "a time"),
                    (int) r.get("frames").integer(1)));
        }
        return new DeviceResults.ModelTimes(m.get("file").text(), shape, methods);
    }

    private static DeviceResults.Drawn drawn(Value d) throws InvalidDeviceResults {
        if (d.has("unavailable")) {
            return DeviceResults.Drawn.unavailable(d.get("unavailable").text());
        }
        String skinning = d.get("skinning").text();
        if (!skinning.equals(DeviceResultsJson.GPU_SKINNING)) {
            throw d.get("skinning").problem("\"" + skinning + "\": version " + DeviceResultsJson.VERSION
                    + " draws with \"" + DeviceResultsJson.GPU_SKINNING + "\" skinning only");
        }
        d.get("vsync").bool();
        int rounds = (int) d.get("rounds").integer(1);
        List<DeviceResults.DrawnPoint> points = new ArrayList<>();
        Value list = d.get("points");
        if (list.size() == 0) {
            throw list.problem("no point was drawn (a GPU part that was not measured says why in \"unavailable\")");
        }
        for (int i = 0; i < list.size(); i++) {
            Value p = list.at(i);
            points.add(new DeviceResults.DrawnPoint((int) p.get("copies").integer(1), method(p.get("method")),
                    spread(p.get("fps"), rounds, "a frame rate"), (int) p.get("frames").integer(1)));
        }
        return new DeviceResults.Drawn(d.get("file").text(), d.get("seconds").positive(), rounds,
                (int) d.get("warmupFrames").integer(0), points, null);
    }

    private static SkinningMethod method(Value v) throws InvalidDeviceResults {
        String key = v.text();
        try {
            return SkinningMethod.fromKey(key);
        } catch (IllegalArgumentException e) {
            throw v.problem(e.getMessage());
        }
    }

    /** A spread of {@code rounds} positive runs whose statistics are the stored ones. */
    private static Spread spread(Value s, int rounds, String what) throws InvalidDeviceResults {
        Value list = s.get("runs");
        if (list.size() != rounds) {
            throw list.problem(list.size() + " runs, expected one per round (" + rounds + ")");
        }
        double[] runs = new double[list.size()];
        for (int i = 0; i < runs.length; i++) {
            runs[i] = list.at(i).positive(what);
        }
        Spread of = Spread.of(runs);
        double[] stored = new double[5];
        String[] names = {"median", "min", "max", "q1", "q3"};
        double[] expected = {of.median(), of.min(), of.max(), of.lowerQuartile(), of.upperQuartile()};
        for (int i = 0; i < names.length; i++) {
            stored[i] = s.get(names[i]).positive(what);
            if (Math.abs(stored[i] - expected[i]) > ROUNDING) {
                throw s.get(names[i]).problem(stored[i] + " is not the " + names[i] + " of its runs ("
                        + DeviceResultsJson.round(expected[i]) + ")");
            }
        }
        return new Spread(runs, stored[0], stored[1], stored[2], stored[3], stored[4]);
    }

    /** The document's root object, as plain values with duplicate keys refused. */
    private Value parse(byte[] bytes) throws InvalidDeviceResults {
        JsonFactory factory = JsonFactory.builder()
                .streamReadConstraints(StreamReadConstraints.builder().maxNestingDepth(16).build())
                .enable(StreamReadFeature.STRICT_DUPLICATE_DETECTION).build();
        try (JsonParser p = factory.createParser(bytes)) {
            JsonToken first = p.nextToken();
            if (first != JsonToken.START_OBJECT) {
                throw new InvalidDeviceResults(file, "", first == null ? "empty: not JSON"
                        : "not a JSON object (a device file is one)");
            }
            Object root = value(p, first);
            if (p.nextToken() != null) {
                throw new InvalidDeviceResults(file, "", "more content after the JSON object");
            }
            return new Value(file, "", root);
        } catch (JsonProcessingException e) {
            String where = e.getProcessor() instanceof JsonParser
                    ? ((JsonParser) e.getProcessor()).getParsingContext().pathAsPointer().toString() : "";
            throw new InvalidDeviceResults(file, where, "not valid JSON: " + e.getOriginalMessage());
        } catch (IOException e) {
            throw new InvalidDeviceResults(file, "", "cannot be read: " + e.getMessage());
        }
    }

    private static Object value(JsonParser p, JsonToken token) throws IOException {
        switch (token) {
            case START_OBJECT: {
                Map<String, Object> map = new LinkedHashMap<>();
                for (JsonToken t = p.nextToken(); t != JsonToken.END_OBJECT; t = p.nextToken()) {
                    String key = p.currentName();
                    map.put(key, value(p, p.nextToken()));
                }
                return map;
            }
            case START_ARRAY: {
                List<Object> list = new ArrayList<>();
                for (JsonToken t = p.nextToken(); t != JsonToken.END_ARRAY; t = p.nextToken()) {
                    list.add(value(p, t));
                }
                return list;
            }
            case VALUE_STRING:
                return p.getText();
            case VALUE_NUMBER_INT:
                return p.getLongValue();
            case VALUE_NUMBER_FLOAT:
                return p.getDoubleValue();
            case VALUE_TRUE:
                return Boolean.TRUE;
            case VALUE_FALSE:
                return Boolean.FALSE;
            default:
                return null;
        }
    }

    /** A value of the document at its JSON pointer; its accessors refuse what the format does not allow. */
    private static final class Value {
        private final String file;
        private final String pointer;
        private final Object value;
        private final boolean present;

        Value(String file, String pointer, Object value) {
            this(file, pointer, value, true);
        }

        private Value(String file, String pointer, Object value, boolean present) {
            this.file = file;
            this.pointer = pointer;
            this.value = value;
            this.present = present;
        }

        InvalidDeviceResults problem(String what) {
            return new InvalidDeviceResults(file, pointer, what);
        }

        private InvalidDeviceResults expected(String what) {
            return problem(!present ? "missing: expected " + what : "expected " + what + ", not " + describe());
        }

        private String describe() {
            if (value == null) {
                return "null";
            }
            if (value instanceof String) {
                return "the string \"" + value + "\"";
            }
            if (value instanceof Map) {
                return "an object";
            }
            if (value instanceof List) {
                return "an array";
            }
            return value.toString();
        }

        @SuppressWarnings("unchecked")
        private Map<String, Object> object() throws InvalidDeviceResults {
            if (!(value instanceof Map)) {
                throw expected("an object");
            }
            return (Map<String, Object>) value;
        }

        @SuppressWarnings("unchecked")
        private List<Object> array() throws InvalidDeviceResults {
            if (!(value instanceof List)) {
                throw expected("an array");
            }
            return (List<Object>) value;
        }

        /** The member {@code key} of this object (absent: a value that says so when asked for anything). */
        Value get(String key) throws InvalidDeviceResults {
            Map<String, Object> map = object();
            String child = pointer + "/" + key.replace("~", "~0").replace("/", "~1");
            return new Value(file, child, map.get(key), map.containsKey(key));
        }

        boolean has(String key) throws InvalidDeviceResults {
            return object().containsKey(key);
        }

        int size() throws InvalidDeviceResults {
            return array().size();
        }

        Value at(int i) throws InvalidDeviceResults {
            return new Value(file, pointer + "/" + i, array().get(i));
        }

        String string() throws InvalidDeviceResults {
            if (!(value instanceof String)) {
                throw expected("a string");
            }
            return (String) value;
        }

        /** A string with something in it. */
        String text() throws InvalidDeviceResults {
            String s = string();
            if (s.isBlank()) {
                throw problem("empty: expected a text");
            }
            return s;
        }

        /** A text, or null where the format allows null (present and null). */
        String textOrNull() throws InvalidDeviceResults {
            return present && value == null ? null : text();
        }

        boolean bool() throws InvalidDeviceResults {
            if (!(value instanceof Boolean)) {
                throw expected("true or false");
            }
            return (Boolean) value;
        }

        long integer(long min) throws InvalidDeviceResults {
            if (!(value instanceof Long)) {
                throw expected("a whole number");
            }
            long v = (Long) value;
            if (v < min) {
                throw problem(v + ": expected at least " + min);
            }
            return v;
        }

        private double number() throws InvalidDeviceResults {
            if (!(value instanceof Number) || !Double.isFinite(((Number) value).doubleValue())) {
                throw expected("a number");
            }
            return ((Number) value).doubleValue();
        }

        double positive() throws InvalidDeviceResults {
            return positive("a value");
        }

        double positive(String what) throws InvalidDeviceResults {
            double v = number();
            if (v <= 0) {
                throw problem(what + " must be a positive number, not " + v);
            }
            return v;
        }

        double nonNegative() throws InvalidDeviceResults {
            double v = number();
            if (v < 0) {
                throw problem("must not be negative, not " + v);
            }
            return v;
        }
    }
}
