package org.skinlab.collada;

import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Random;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestFactory;
import org.skinlab.model.Mesh;
import org.skinlab.model.Model;
import org.skinlab.testing.TestPaths;

/**
 * Robustness fuzzing with fixed seeds: valid documents (our skinned quad fixture, two of our
 * assets and, when present, seven small corpus files) get one to three random mutations each (truncation, byte and token deletion,
 * duplication and replacement, numbers turned huge, negative or non-finite, element names swapped
 * throughout, attribute values exchanged, leaf elements deleted, duplicated or moved) and are
 * imported. Every import must either succeed with
 * finite positions or fail with a {@link ColladaException} that the importer raised on purpose;
 * never another exception, an {@code Error}, or a {@code RuntimeException} caught by the
 * importer's last-resort safety net (that would be a crash with a vague message). Each batch of
 * cases must finish within {@link #BATCH_TIME}.
 *
 * <p>Failing inputs are written to {@code core/build/fuzz-failures/} for reproduction. For a longer
 * hunt, run the class with {@code -Dskinlab.fuzz.rounds=N}: N rounds with seeds derived from the
 * fixed ones (the default, 1, runs exactly the fixed seeds).
 */
class ImportFuzzTest {
    private static final Duration BATCH_TIME = Duration.ofSeconds(10);
    private static final int BATCH = 250;

    private static final String[] NUMBERS = {
        "-1", "0", "-0", "1", "3", "16", "65536", "2147483647", "2147483648", "-2147483648", "4294967296",
        "99999999999999999999", "1e39", "-1e39", "1e-50", "NaN", "INF", "-INF", "1.#QNAN", "0x10", "1,5", "",
    };

    /** Swapped throughout the document (open and close tags alike), so the XML stays well-formed. */
    private static final String[][] RENAMES = {
        {"triangles", "polylist"}, {"polylist", "polygons"}, {"triangles", "tristrips"}, {"polylist", "trifans"},
        {"triangles", "lines"}, {"vcount", "p"}, {"float_array", "int_array"}, {"float_array", "Name_array"},
        {"Name_array", "IDREF_array"}, {"Name_array", "float_array"}, {"float_array", "bool_array"},
        {"matrix", "translate"}, {"translate", "rotate"}, {"rotate", "scale"}, {"matrix", "lookat"},
        {"matrix", "skew"}, {"node", "instance_node"}, {"input", "param"}, {"accessor", "technique_common"},
        {"source", "vertices"}, {"v", "vcount"}, {"mesh", "spline"}, {"skin", "morph"}, {"animation", "sampler"},
        {"animation_clip", "animation"}, {"instance_controller", "instance_geometry"}, {"joints", "vertex_weights"},
        {"COLLADA", "collada"}, {"library_geometries", "library_controllers"}, {"visual_scene", "node"},
    };

    private static final Pattern TOKEN = Pattern.compile("[^\\s<>\"]+");
    private static final Pattern NUMBER = Pattern.compile("-?\\d+(\\.\\d+)?(e-?\\d+)?");
    private static final Pattern ATTRIBUTE_VALUE = Pattern.compile("=\"([^\"]*)\"");
    /** An element without child elements: self-closing, or with text only. */
    private static final Pattern LEAF = Pattern.compile("<([\\w:]+)[^<>]*?(/>|>[^<]*</\\1>)");

    @Test
    void mutatedSkinnedQuadNeverCrashes() {
        fuzz("skinned-quad.dae", QuadFixture.text(), 3000, 20190501L);
    }

    @Test
    void mutatedHumanoidNeverCrashes() throws IOException {
        fuzz("humanoid-walk.dae", Files.readString(TestPaths.asset("characters/humanoid-walk.dae")), 500, 951L);
    }

    @Test
    void mutatedCylinderNeverCrashes() throws IOException {
        fuzz("cylinder-twist-low.dae", Files.readString(TestPaths.asset("cylinders/cylinder-twist-low.dae")), 500,
                1148L);
    }

    /**
     * Small corpus files bring constructs our own files lack: {@code <polygons>} and clips (S12),
     * nested animations (S11), several skeleton roots (S14), control bones (S15), a skin without
     * animation (K01), Cinema 4D's and an empty-tag writer's habits (T01, M03). Skipped, saying
     * so, without the corpus.
     */
    @TestFactory
    Stream<DynamicTest> mutatedCorpusFilesNeverCrash() {
        String[] names = {"K01_simple_bone.dae", "M03_cube_empty_tags.dae", "S11_box_nested_animation.dae",
            "S12_library_animation_clips.dae", "S14_two_skinned_cubes.dae", "S15_leg_control_bones.dae",
            "T01_cinema4d.dae"};
        TestPaths.corpusOrSkip();
        return Stream.of(names).map(name -> DynamicTest.dynamicTest(name, () -> {
            Path file = TestPaths.corpusFileOrSkip(name);
            fuzz(name, Files.readString(file), 300, name.hashCode());
        }));
    }

    /** One mutated document and how it was made. */
    private static final class Case {
        final int index;
        final String how;
        final byte[] bytes;

        Case(int index, String how, byte[] bytes) {
            this.index = index;
            this.how = how;
            this.bytes = bytes;
        }
    }

    private static void fuzz(String name, String document, int cases, long seed) {
        int rounds = Integer.getInteger("skinlab.fuzz.rounds", 1);
        List<String> failures = new ArrayList<>();
        for (int round = 0; round < rounds; round++) {
            fuzzRound(name, document, cases, seed + 7919L * round, failures);
        }
        if (!failures.isEmpty()) {
            fail(failures.size() + " of " + rounds * cases + " mutations of " + name + " crashed the importer:\n"
                    + String.join("\n", failures.subList(0, Math.min(10, failures.size()))));
        }
    }

    private static void fuzzRound(String name, String document, int cases, long seed, List<String> failures) {
        Random random = new Random(seed);
        Mutator mutator = new Mutator(document);
        int succeeded = 0;
        int refused = 0;
        for (int start = 0; start < cases; start += BATCH) {
            // Cases are made outside the timed batch so the bound covers only the imports.
            List<Case> batch = new ArrayList<>();
            for (int i = start; i < Math.min(cases, start + BATCH); i++) {
                StringBuilder how = new StringBuilder();
                byte[] bytes = mutator.mutate(random, how);
                batch.add(new Case(i, how.toString(), bytes));
            }
            int first = start;
            int[] outcome = assertTimeoutPreemptively(BATCH_TIME, () -> {
                int ok = 0;
                int no = 0;
                for (Case c : batch) {
                    String problem = importOnce(name, c.bytes);
                    if (problem == null) {
                        ok++;
                    } else if (problem.isEmpty()) {
                        no++;
                    } else {
                        failures.add(record(name, seed, c, problem));
                    }
                }
                return new int[] {ok, no};
            }, () -> name + ": cases " + first + ".." + (first + batch.size() - 1) + " took longer than " + BATCH_TIME);
            succeeded += outcome[0];
            refused += outcome[1];
        }
        // The mutations must exercise both outcomes, or the test proves little.
        int s = succeeded;
        int r = refused;
        assertTrue(s > cases / 50 && r > cases / 50, () -> name + ": " + s + " imported, " + r + " refused");
    }

    /** null: imported; "": refused on purpose; otherwise what went wrong. */
    private static String importOnce(String name, byte[] bytes) {
        try {
            Model m = ColladaImporter.read(new ByteArrayInputStream(bytes), name);
            for (Mesh mesh : m.meshes()) {
                for (float f : mesh.positions()) {
                    if (!Float.isFinite(f)) {
                        return "imported a non-finite position in " + mesh.id();
                    }
                }
            }
            return null;
        } catch (ColladaException e) {
            if (e.getCause() instanceof RuntimeException) {
                return "safety net caught " + stackTrace(e.getCause());
            }
            if (!e.getMessage().startsWith(name + ": ")) {
                return "message does not start with the file name: " + e.getMessage();
            }
            return "";
        } catch (Throwable t) {
            // Errors included: a StackOverflowError or OutOfMemoryError is exactly what we look for.
            return stackTrace(t);
        }
    }

    private static String stackTrace(Throwable t) {
        StringWriter w = new StringWriter();
        t.printStackTrace(new PrintWriter(w));
        String[] lines = w.toString().split("\n");
        StringBuilder sb = new StringBuilder();
        for (int i = 0; i < Math.min(8, lines.length); i++) {
            sb.append(lines[i].trim()).append(i == 0 ? " at " : " < ");
        }
        return sb.toString();
    }

    private static String record(String name, long seed, Case c, String problem) {
        String saved = "";
        try {
            Path dir = TestPaths.root().resolve("core/build/fuzz-failures");
            Files.createDirectories(dir);
            Path file = dir.resolve(name.replace(".dae", "") + "-seed-" + seed + "-case-" + c.index + ".dae");
            Files.write(file, c.bytes);
            saved = " (saved as " + file + ")";
        } catch (IOException | RuntimeException e) {
            saved = " (could not save: " + e + ")";
        }
        return "seed " + seed + " case " + c.index + " [" + c.how + "]" + saved + ": " + problem;
    }

    /** Random mutations of one document. */
    private static final class Mutator {
        private final String document;
        private final List<String> attributeValues = new ArrayList<>();

        Mutator(String document) {
            this.document = document;
            Set<String> values = new LinkedHashSet<>();
            Matcher m = ATTRIBUTE_VALUE.matcher(document);
            while (m.find()) {
                values.add(m.group(1));
            }
            attributeValues.addAll(values);
        }

        byte[] mutate(Random random, StringBuilder how) {
            String text = document;
            int n = 1 + random.nextInt(3);
            for (int k = 0; k < n; k++) {
                text = once(text, random, how);
            }
            byte[] bytes = text.getBytes(StandardCharsets.UTF_8);
            // Byte-level mutations last, so they can break the encoding too.
            switch (random.nextInt(8)) {
                case 0: {
                    int at = random.nextInt(bytes.length + 1);
                    how.append(" truncate@").append(at);
                    return java.util.Arrays.copyOf(bytes, at);
                }
                case 1: {
                    int at = random.nextInt(bytes.length);
                    byte b = (byte) random.nextInt(256);
                    how.append(" byte@").append(at).append('=').append(b & 0xFF);
                    bytes = bytes.clone();
                    bytes[at] = b;
                    return bytes;
                }
                default:
                    return bytes;
            }
        }

        private String once(String text, Random random, StringBuilder how) {
            int len = text.length();
            switch (random.nextInt(10)) {
                case 8:
                case 9: { // a whole leaf element deleted, duplicated or moved (duplicate ids, lost inputs)
                    int[] t = token(text, LEAF, random);
                    if (t == null) {
                        return text;
                    }
                    String element = text.substring(t[0], t[1]);
                    String without = text.substring(0, t[0]) + text.substring(t[1]);
                    switch (random.nextInt(3)) {
                        case 0:
                            how.append(" delete-element@").append(t[0]);
                            return without;
                        case 1:
                            how.append(" duplicate-element@").append(t[0]);
                            return text.substring(0, t[1]) + element + text.substring(t[1]);
                        default: {
                            // Moved to just before another tag, anywhere in the document.
                            int to = without.indexOf('<', random.nextInt(without.length()));
                            if (to < 0) {
                                return text;
                            }
                            how.append(" move-element@").append(t[0]).append("->").append(to);
                            return without.substring(0, to) + element + without.substring(to);
                        }
                    }
                }
                case 0: { // delete a character range
                    int at = random.nextInt(len);
                    int end = Math.min(len, at + 1 + random.nextInt(16));
                    how.append(" delete@").append(at).append('+').append(end - at);
                    return text.substring(0, at) + text.substring(end);
                }
                case 1: { // duplicate a character range
                    int at = random.nextInt(len);
                    int end = Math.min(len, at + 1 + random.nextInt(64));
                    how.append(" duplicate@").append(at).append('+').append(end - at);
                    return text.substring(0, end) + text.substring(at, end) + text.substring(end);
                }
                case 2: { // delete or duplicate a token
                    int[] t = token(text, TOKEN, random);
                    if (t == null) {
                        return text;
                    }
                    boolean delete = random.nextBoolean();
                    how.append(delete ? " delete-token@" : " duplicate-token@").append(t[0]);
                    String token = text.substring(t[0], t[1]);
                    return text.substring(0, t[0]) + (delete ? "" : token + " " + token) + text.substring(t[1]);
                }
                case 3:
                case 4: { // a number becomes huge, negative, non-finite or not a number
                    int[] t = token(text, NUMBER, random);
                    if (t == null) {
                        return text;
                    }
                    String value = NUMBERS[random.nextInt(NUMBERS.length)];
                    how.append(" number@").append(t[0]).append('=').append(value);
                    return text.substring(0, t[0]) + value + text.substring(t[1]);
                }
                case 5: { // an element name swapped throughout
                    String[] pair = RENAMES[random.nextInt(RENAMES.length)];
                    boolean swap = random.nextBoolean();
                    how.append(swap ? " swap " : " rename ").append(pair[0]).append(swap ? "<->" : "->").append(pair[1]);
                    return renameElements(text, pair[0], pair[1], swap);
                }
                case 6: { // an attribute value replaced by another from the document (type confusion)
                    int[] t = group(text, ATTRIBUTE_VALUE, random);
                    if (t == null || attributeValues.isEmpty()) {
                        return text;
                    }
                    String value = attributeValues.get(random.nextInt(attributeValues.size()));
                    how.append(" attribute@").append(t[0]).append('=').append(value);
                    return text.substring(0, t[0]) + value + text.substring(t[1]);
                }
                default: { // a random character
                    int at = random.nextInt(len);
                    String chars = "<>&\"'/ #-0189.eE\u00e9\uffff\u0000";
                    char c = chars.charAt(random.nextInt(chars.length()));
                    how.append(" char@").append(at).append("=U+").append(Integer.toHexString(c));
                    return text.substring(0, at) + c + text.substring(at + 1);
                }
            }
        }

        /** Start and end of a random match of the pattern, or null. */
        private static int[] token(String text, Pattern pattern, Random random) {
            Matcher m = pattern.matcher(text);
            int from = random.nextInt(text.length());
            if (m.find(from) || m.find(0)) {
                return new int[] {m.start(), m.end()};
            }
            return null;
        }

        /** Start and end of group 1 of a random match, or null. */
        private static int[] group(String text, Pattern pattern, Random random) {
            Matcher m = pattern.matcher(text);
            int from = random.nextInt(text.length());
            if (m.find(from) || m.find(0)) {
                return new int[] {m.start(1), m.end(1)};
            }
            return null;
        }

        private static String renameElements(String text, String a, String b, boolean swap) {
            Pattern tag = Pattern.compile("(</?)(" + Pattern.quote(a) + (swap ? "|" + Pattern.quote(b) : "") + ")(?=[\\s/>])");
            Matcher m = tag.matcher(text);
            StringBuilder sb = new StringBuilder(text.length() + 64);
            while (m.find()) {
                String to = m.group(2).equals(a) ? b : a;
                m.appendReplacement(sb, Matcher.quoteReplacement(m.group(1) + to));
            }
            m.appendTail(sb);
            return sb.toString();
        }
    }
}
