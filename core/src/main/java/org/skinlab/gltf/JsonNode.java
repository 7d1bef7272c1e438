package org.skinlab.gltf;

import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * A value of the parsed document with its JSON path (RFC 6901 pointer), so that every check can
 * name where it failed. A missing key gives a node whose {@link #isMissing()} is true; the typed
 * getters take a default for optional properties and throw a {@link GltfException} naming the
 * path for a value of the wrong type or range.
 */
final class JsonNode {
    private final GltfContext ctx;
    private final String path;
    private final Object value;

    JsonNode(GltfContext ctx, String path, Object value) {
        this.ctx = ctx;
        this.path = path;
        this.value = value;
    }

    String path() {
        return path;
    }

    /** The path of a child key or index, escaped as RFC 6901 asks. */
    String path(String key) {
        return path + "/" + key.replace("~", "~0").replace("/", "~1");
    }

    boolean isMissing() {
        return value == null;
    }

    boolean isObject() {
        return value instanceof Map;
    }

    GltfException error(String problem) {
        return ctx.error(path, problem);
    }

    /** The member {@code key} of this object (missing when absent, or when this node is missing). */
    JsonNode get(String key) throws GltfException {
        if (value == null) {
            return new JsonNode(ctx, path(key), null);
        }
        return new JsonNode(ctx, path(key), object().get(key));
    }

    /** Element {@code i} of this array. */
    JsonNode get(int i) throws GltfException {
        return new JsonNode(ctx, path + "/" + i, array().get(i));
    }

    /** The number of elements of this array (0 when missing). */
    int size() throws GltfException {
        return value == null ? 0 : array().size();
    }

    /** The keys of this object in document order (none when missing). */
    Set<String> keys() throws GltfException {
        return value == null ? Collections.emptySet() : object().keySet();
    }

    boolean has(String key) throws GltfException {
        return value != null && object().containsKey(key);
    }

    @SuppressWarnings("unchecked")
    private Map<String, Object> object() throws GltfException {
        if (!(value instanceof Map)) {
            throw error("expected a JSON object, found " + describe());
        }
        return (Map<String, Object>) value;
    }

    @SuppressWarnings("unchecked")
    private List<Object> array() throws GltfException {
        if (!(value instanceof List)) {
            throw error("expected a JSON array, found " + describe());
        }
        return (List<Object>) value;
    }

    /** This node, which must be an object, or an empty object's worth of nothing when missing. */
    JsonNode objectOrMissing() throws GltfException {
        if (value != null) {
            object();
        }
        return this;
    }

    /** This node, which must be a non-empty array when present. */
    JsonNode arrayOrMissing() throws GltfException {
        if (value != null && array().isEmpty()) {
            throw error("an empty array (the specification asks for at least one element or none at all)");
        }
        return this;
    }

    /** The number, which must be present and finite. */
    double number() throws GltfException {
        if (!(value instanceof Number)) {
            throw error(value == null ? "missing (a number is required)" : "expected a number, found " + describe());
        }
        double d = ((Number) value).doubleValue();
        if (!Double.isFinite(d)) {
            throw error("the number " + d + " is not finite");
        }
        return d;
    }

    double number(double defaultValue) throws GltfException {
        return value == null ? defaultValue : number();
    }

    /** The integer, which must be present and within [min, max]. */
    int integer(long min, long max) throws GltfException {
        double d = number();
        if (d != Math.rint(d)) {
            throw error("expected an integer, found " + d);
        }
        if (d < min || d > max) {
            throw error(format(d) + " is outside [" + min + ", " + max + "]");
        }
        return (int) d;
    }

    int integer(long min, long max, int defaultValue) throws GltfException {
        return value == null ? defaultValue : integer(min, max);
    }

    /** An index into the top-level array {@code what} of {@code count} elements. */
    int index(int count, String what) throws GltfException {
        double d = number();
        if (d != Math.rint(d) || d < 0 || d >= count) {
            throw error("index " + format(d) + " does not name one of the " + count + " " + what);
        }
        return (int) d;
    }

    String string() throws GltfException {
        if (!(value instanceof String)) {
            throw error(value == null ? "missing (a string is required)" : "expected a string, found " + describe());
        }
        return (String) value;
    }

    String string(String defaultValue) throws GltfException {
        return value == null ? defaultValue : string();
    }

    boolean bool(boolean defaultValue) throws GltfException {
        if (value == null) {
            return defaultValue;
        }
        if (!(value instanceof Boolean)) {
            throw error("expected true or false, found " + describe());
        }
        return (Boolean) value;
    }

    /** An array of exactly {@code n} finite numbers, or a copy of the default when missing. */
    float[] floats(int n, float[] defaultValue) throws GltfException {
        if (value == null) {
            return defaultValue == null ? null : defaultValue.clone();
        }
        if (array().size() != n) {
            throw error("expected " + n + " numbers, found " + array().size());
        }
        float[] result = new float[n];
        for (int i = 0; i < n; i++) {
            result[i] = (float) get(i).number();
        }
        return result;
    }

    /** The elements' numbers (any count). */
    float[] floats() throws GltfException {
        float[] result = new float[size()];
        for (int i = 0; i < result.length; i++) {
            result[i] = (float) get(i).number();
        }
        return result;
    }

    private static String format(double d) {
        return d == Math.rint(d) && Math.abs(d) < 1e15 ? Long.toString((long) d) : Double.toString(d);
    }

    private String describe() {
        if (value instanceof Map) {
            return "an object";
        }
        if (value instanceof List) {
            return "an array";
        }
        if (value instanceof String) {
            String s = (String) value;
            return "the string \"" + (s.length() > 40 ? s.substring(0, 40) + "..." : s) + "\"";
        }
        return value == null ? "nothing" : String.valueOf(value);
    }
}
