package org.skinlab.desktop.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.skinlab.desktop.Cli;
import org.skinlab.desktop.ExitCodes;

/**
 * {@code skinlab pose --blend ... [--additive ...]}: a blend of one clip is that clip's plain pose,
 * blends lie between their clips, every clip of a set loops by its own duration, an additive layer
 * at its own reference time adds nothing, the JSON names the blend, the mixer's warnings go to
 * stderr once, and every bad input is one line naming the value. The glTF fixtures' clips start at
 * 0 s, so there T seconds after a clip's start is clip time T; clip-a lasts 1.6 s, clip-b 1.8 s.
 */
class PoseBlendTest {
    private static final ObjectMapper MAPPER = new ObjectMapper();
    private static final Path GLTF = Cli.root().resolve("core/src/test/resources/gltf");
    private static final String INTERPOLATION = GLTF.resolve("anim-interpolation.gltf").toString();
    private static final String MORPH_SKIN = GLTF.resolve("morph-skin.gltf").toString();

    @TempDir
    Path dir;

    /** The poses of {@code pose FILE --method lbs --json - ARGS...}: [mesh][time] x,y,z per position. */
    private static double[][][] poses(String file, String... args) throws Exception {
        JsonNode meshes = json(file, args).get("meshes");
        double[][][] poses = new double[meshes.size()][][];
        for (int m = 0; m < poses.length; m++) {
            JsonNode perTime = meshes.get(m).get("poses");
            poses[m] = new double[perTime.size()][];
            for (int t = 0; t < perTime.size(); t++) {
                poses[m][t] = doubles(perTime.get(t));
            }
        }
        return poses;
    }

    private static JsonNode json(String file, String... args) throws Exception {
        List<String> all = new ArrayList<>(List.of("pose", file, "--method", "lbs", "--json", "-"));
        all.addAll(Arrays.asList(args));
        Cli r = Cli.run(all.toArray(String[]::new));
        assertEquals(ExitCodes.OK, r.status, r::toString);
        assertEquals("", r.err, r::toString);
        return MAPPER.readTree(r.out);
    }

    private static double[] doubles(JsonNode array) {
        double[] d = new double[array.size()];
        for (int i = 0; i < d.length; i++) {
            d[i] = array.get(i).doubleValue();
        }
        return d;
    }

    /** Largest distance between corresponding points of two poses (every mesh, every time). */
    private static double maxDistance(double[][][] a, double[][][] b) {
        assertEquals(a.length, b.length);
        double max = 0;
        for (int m = 0; m < a.length; m++) {
            assertEquals(a[m].length, b[m].length);
            for (int t = 0; t < a[m].length; t++) {
                double[] p = a[m][t];
                double[] q = b[m][t];
                assertEquals(p.length, q.length);
                for (int i = 0; i < p.length; i += 3) {
                    max = Math.max(max, Math.sqrt(sq(p[i] - q[i]) + sq(p[i + 1] - q[i + 1]) + sq(p[i + 2] - q[i + 2])));
                }
            }
        }
        return max;
    }

    /** The diagonal of the box around every point of the poses: the model's size. */
    private static double size(double[][][] poses) {
        double[] lo = {Double.MAX_VALUE, Double.MAX_VALUE, Double.MAX_VALUE};
        double[] hi = {-Double.MAX_VALUE, -Double.MAX_VALUE, -Double.MAX_VALUE};
        for (double[][] mesh : poses) {
            for (double[] pose : mesh) {
                for (int i = 0; i < pose.length; i++) {
                    lo[i % 3] = Math.min(lo[i % 3], pose[i]);
                    hi[i % 3] = Math.max(hi[i % 3], pose[i]);
                }
            }
        }
        return Math.sqrt(sq(hi[0] - lo[0]) + sq(hi[1] - lo[1]) + sq(hi[2] - lo[2]));
    }

    private static double sq(double x) {
        return x * x;
    }

    @Test
    void aBlendOfOneClipAtWeightOneIsThePlainPoseOfThatClip() throws Exception {
        // Between keys and on them; the mixer samples into local T, R, S and evaluates those, the
        // plain pose samples the transform stack: equal within float rounding, 1e-6 of the size.
        String[][] cases = {{INTERPOLATION, "clip-a", "0,0.35,0.9,1.55"}, {INTERPOLATION, "clip-b", "0,0.35,0.9,1.75"},
            {MORPH_SKIN, "bend", "0,0.25,0.6"}};
        for (String[] c : cases) {
            double[][][] plain = poses(c[0], "--clip", c[1], "--time", c[2]);
            double[][][] blend = poses(c[0], "--blend", c[1] + "=1", "--time", c[2]);
            double d = maxDistance(plain, blend);
            assertTrue(d <= 1e-6 * size(plain), c[1] + ": " + d + " of a size " + size(plain));
        }
    }

    @Test
    void theIssuesCommandLineWorksAsWrittenWithLbsByDefault() throws Exception {
        // skinlab pose FILE --time T[,T...] --blend CLIP=W[,CLIP=W...] [--additive CLIP=W[@REFTIME]] [--json OUT]
        Path out = dir.resolve("blend.json");
        Cli r = Cli.run("pose", INTERPOLATION, "--time", "0.2,0.7", "--blend", "clip-a=0.4,clip-b=0.6", "--additive",
                "clip-b=0.5@0.1", "--json", out.toString());
        assertEquals(ExitCodes.OK, r.status, r::toString);
        JsonNode written = MAPPER.readTree(out.toFile());
        assertEquals("lbs", written.get("method").asText().toLowerCase(java.util.Locale.ROOT));
        assertEquals(MAPPER.readTree(MAPPER.writeValueAsString(json(INTERPOLATION, "--time", "0.2,0.7", "--blend",
                "clip-a=0.4,clip-b=0.6", "--additive", "clip-b=0.5@0.1"))), written);
    }

    @Test
    void everyClipOfASetLoopsByItsOwnDuration() throws Exception {
        // At 2 s clip-a (1.6 s) is at 0.4 and clip-b (1.8 s) at 0.2: each clip of the one weighted
        // set, the other at weight 0, is the plain pose of its clip at its own wrapped time.
        JsonNode root = json(INTERPOLATION, "--blend", "clip-a=1,clip-b=0", "--time", "2");
        assertEquals(0.4f, root.get("blend").get(0).get("times").get(0).floatValue(), 1e-6f);
        assertEquals(0.2f, root.get("blend").get(1).get("times").get(0).floatValue(), 1e-6f);
        String[][] cases = {{"clip-a=1,clip-b=0", "clip-a", "0.4"}, {"clip-a=0,clip-b=1", "clip-b", "0.2"}};
        for (String[] c : cases) {
            double[][][] plain = poses(INTERPOLATION, "--clip", c[1], "--time", c[2]);
            double[][][] blend = poses(INTERPOLATION, "--blend", c[0], "--time", "2");
            assertTrue(maxDistance(plain, blend) <= 1e-5 * size(plain), c[0] + ": " + maxDistance(plain, blend));
        }
    }

    @Test
    void halfAndHalfLiesBetweenItsClips() throws Exception {
        String t = "0.35,0.9";
        double[][][] a = poses(INTERPOLATION, "--clip", "clip-a", "--time", t);
        double[][][] b = poses(INTERPOLATION, "--clip", "clip-b", "--time", t);
        double[][][] half = poses(INTERPOLATION, "--blend", "clip-a=0.5,clip-b=0.5", "--time", t);
        double apart = maxDistance(a, b);
        assertTrue(apart > 1e-2 * size(a), "the fixture's clips differ: " + apart);
        // Nearer to each clip than the clips are to each other, and at neither.
        assertTrue(maxDistance(half, a) < apart && maxDistance(half, b) < apart, maxDistance(half, a) + ", "
                + maxDistance(half, b) + " against " + apart);
        assertTrue(maxDistance(half, a) > 0.1 * apart && maxDistance(half, b) > 0.1 * apart);

        // The same clip twice is that clip at the sum of its weights: the very same numbers.
        JsonNode twice = json(INTERPOLATION, "--blend", "clip-a=0.5,clip-a=0.5", "--time", t);
        JsonNode once = json(INTERPOLATION, "--blend", "clip-a=1", "--time", t);
        assertEquals(once.get("meshes"), twice.get("meshes"));
        assertEquals(1, twice.get("blend").size());
        assertEquals(1.0, twice.get("blend").get(0).get("weight").doubleValue(), 0.0);

        // One clip at 0.5: the rest pose (every weight 0) fills the other half.
        double[][][] rest = poses(INTERPOLATION, "--blend", "clip-a=0", "--time", t);
        double[][][] halfA = poses(INTERPOLATION, "--blend", "clip-a=0.5", "--time", t);
        double restToA = maxDistance(rest, a);
        assertTrue(maxDistance(halfA, a) < restToA && maxDistance(halfA, rest) < restToA, "between rest and clip-a");
    }

    @Test
    void anAdditiveLayerAtItsReferenceTimeAddsNothing() throws Exception {
        double[][][] base = poses(INTERPOLATION, "--blend", "clip-a=0.5,clip-b=0.5", "--time", "0.35");
        double[][][] same = poses(INTERPOLATION, "--blend", "clip-a=0.5,clip-b=0.5", "--additive", "clip-a=1@0.35",
                "--time", "0.35");
        assertTrue(maxDistance(base, same) <= 1e-6 * size(base), "the difference from itself is none");
        double[][][] unweighted = poses(INTERPOLATION, "--blend", "clip-a=0.5,clip-b=0.5", "--additive", "clip-b=0",
                "--time", "0.35");
        assertEquals(0.0, maxDistance(base, unweighted), 0.0);
        double[][][] added = poses(INTERPOLATION, "--blend", "clip-a=0.5,clip-b=0.5", "--additive", "clip-b=0.6",
                "--time", "0.35");
        assertTrue(maxDistance(base, added) > 1e-3 * size(base), "clip-b at 0.35 s differs from its pose at 0 s");
        double[][][] repeated = poses(INTERPOLATION, "--blend", "clip-a=0.5,clip-b=0.5", "--additive",
                "clip-b=0.6,clip-a=0.3@0.1", "--time", "0.35");
        double[][][] twice = poses(INTERPOLATION, "--blend", "clip-a=0.5,clip-b=0.5", "--additive", "clip-b=0.6",
                "--additive", "clip-a=0.3@0.1", "--time", "0.35");
        assertEquals(0.0, maxDistance(repeated, twice), 0.0, "comma-separated or repeated: the same layers");
    }

    @Test
    void jsonNamesTheBlendAfterTheTimes() throws Exception {
        JsonNode root = json(INTERPOLATION, "--blend", "clip-b=0.25,clip-a=0.75", "--additive", "clip-b=0.6@0.1",
                "--time", "-0.5,0.3,3");
        assertEquals(List.of("file", "clip", "method", "times", "blend", "additive", "meshes"), Cli.keys(root));
        assertEquals("clip-a", root.get("clip").textValue(), "the heaviest clip");
        assertEquals(MAPPER.readTree("[-0.5,0.3,3.0]"), root.get("times"), "as given");
        JsonNode blend = root.get("blend");
        assertEquals(2, blend.size());
        assertEquals(List.of("clip", "weight", "times"), Cli.keys(blend.get(0)));
        assertEquals("clip-b", blend.get(0).get("clip").textValue(), "in the order given");
        assertEquals(0.25, blend.get(0).get("weight").doubleValue(), 0.0);
        assertEquals(0.75, blend.get(1).get("weight").doubleValue(), 0.0);
        // -0.5 s loops to 1.3 of clip-b's 1.8 s, 3 s to 1.2; clip-a: 1.1 and 1.4 of its 1.6 s.
        assertArrayEquals(new double[] {1.3, 0.3, 1.2}, doubles(blend.get(0).get("times")));
        assertArrayEquals(new double[] {1.1, 0.3, 1.4}, doubles(blend.get(1).get("times")));
        JsonNode additive = root.get("additive");
        assertEquals(1, additive.size());
        assertEquals(List.of("clip", "weight", "referenceTime", "times"), Cli.keys(additive.get(0)));
        assertEquals("clip-b", additive.get(0).get("clip").textValue());
        assertEquals(0.6, additive.get(0).get("weight").doubleValue(), 0.0);
        assertEquals(0.1, additive.get(0).get("referenceTime").doubleValue(), 0.0);
        assertArrayEquals(new double[] {1.3, 0.3, 1.2}, doubles(additive.get(0).get("times")));
        assertEquals(3, root.get("meshes").get(0).get("poses").size());

        Cli text = Cli.run("pose", INTERPOLATION, "--method", "dqs", "--time", "0.3", "--blend", "clip-b=0.25,clip-a=0.75",
                "--additive", "clip-b=0.6@0.1");
        assertEquals(ExitCodes.OK, text.status, text::toString);
        assertEquals("  clip:   blend clip-b=0.25, clip-a=0.75 + additive clip-b=0.6@0.1, method dqs", text.out.split("\n")[1]);
    }

    private static void assertArrayEquals(double[] expected, double[] actual) {
        assertEquals(expected.length, actual.length);
        for (int i = 0; i < expected.length; i++) {
            // Clip times are floats: 1e-6 s.
            assertEquals(expected[i], actual[i], 1e-6, "index " + i + " of " + Arrays.toString(actual));
        }
    }

    @Test
    void colladaClipsByNameOrIdAndStaticMeshesThroughTheMixer() throws Exception {
        // The clip "slide" spans [1, 2]: T = 0.5 s after its start is clip time 1.5, where the
        // node's translate X is 2, so (0,0,0) lands at (2 - 0, 2 + 0, 3 + 0) (PoseCommandTest).
        Path file = dir.resolve("static.dae");
        Files.writeString(file, PoseCommandTest.STATIC_ANIMATED.replace("<animation_clip name=\"slide\"",
                "<animation_clip id=\"slide-id\" name=\"slide\""));
        for (String clip : new String[] {"slide", "slide-id"}) {
            JsonNode root = json(file.toString(), "--blend", clip + "=1", "--time", "0.5");
            assertEquals("slide", root.get("clip").textValue());
            assertEquals("slide", root.get("blend").get(0).get("clip").textValue());
            assertEquals(1.5, root.get("blend").get(0).get("times").get(0).doubleValue(), 1e-6);
            double[] p = doubles(root.get("meshes").get(0).get("poses").get(0));
            double[] expected = {2, 2, 3, 2, 3, 3, 1, 2, 3, -3, 7, 8};
            for (int i = 0; i < expected.length; i++) {
                assertEquals(expected[i], p[i], 1e-5, clip + ": " + Arrays.toString(p));
            }
        }
    }

    @Test
    void theMixersWarningsGoToStderrOnce() throws Exception {
        // clip-b without its channels on joint2: clip-a alone animates joint2 in the blend.
        ObjectNode gltf = (ObjectNode) MAPPER.readTree(Path.of(INTERPOLATION).toFile());
        ArrayNode channels = (ArrayNode) gltf.get("animations").get(1).get("channels");
        for (int i = channels.size() - 1; i >= 0; i--) {
            if (channels.get(i).get("target").get("node").intValue() == 2) {
                channels.remove(i);
            }
        }
        Path file = dir.resolve("partial.gltf");
        MAPPER.writeValue(file.toFile(), gltf);
        Cli r = Cli.run("pose", file.toString(), "--method", "lbs", "--time", "0.2,0.4,0.6", "--blend",
                "clip-a=0.5,clip-b=0.5", "--json", "-");
        assertEquals(ExitCodes.OK, r.status, r::toString);
        assertEquals(1, r.errLines().length, r::toString);
        assertTrue(r.errLines()[0].startsWith("skinlab: warning: ") && r.errLines()[0].contains("clip \"clip-b\" does"
                + " not animate 1 joint") && r.errLines()[0].contains("joint2"), r::toString);
        MAPPER.readTree(r.out);

        // A blend plays no morph weights: said once, naming the clip.
        Cli morph = Cli.run("pose", MORPH_SKIN, "--method", "lbs", "--time", "0.2", "--blend", "bend=0.5,pulse=0.5");
        assertEquals(ExitCodes.OK, morph.status, morph::toString);
        assertEquals(List.of("skinlab: warning: " + MORPH_SKIN + ": clip \"pulse\" animates morph weights, which a"
                + " blend does not play: the meshes keep the file's weights"), List.of(morph.errLines()));
    }

    @Test
    void badInputIsOneLineNamingTheValue() {
        String[][] cases = {
            {"--blend", "walk=1"}, {"pose: --blend: unknown clip 'walk' in " + INTERPOLATION
                + "; available clips: 'clip-a', 'clip-b'"},
            {"--blend", "clip-a=heavy"}, {"pose: --blend: the weight of clip 'clip-a' is 'heavy', not a number"},
            {"--blend", "clip-a=NaN"}, {"pose: --blend: the weight of clip 'clip-a' is 'NaN', not a number"},
            {"--blend", "clip-a=-0.5"}, {"pose: --blend: the weight of clip 'clip-a' is -0.5, negative (a weight is 0"
                + " or more)"},
            {"--blend", "clip-a=1e999"}, {"pose: --blend: the weight of clip 'clip-a' is '1e999', beyond the range of"
                + " numbers"},
            {"--blend", "clip-a"}, {"pose: --blend: 'clip-a' is not CLIP=W (a clip's name, '=', a weight)"},
            {"--blend", "=1"}, {"pose: --blend: '=1' is not CLIP=W (a clip's name, '=', a weight)"},
            {"--blend", "clip-a=0.5,,clip-b=0.5"}, {"pose: --blend: '' is not CLIP=W (a clip's name, '=', a weight)"},
            {"--blend", "clip-a=1", "--additive", "clip-x=1"}, {"pose: --additive: unknown clip 'clip-x' in "
                + INTERPOLATION + "; available clips: 'clip-a', 'clip-b'"},
            {"--blend", "clip-a=1", "--additive", "clip-b"}, {"pose: --additive: 'clip-b' is not CLIP=W[@REFTIME] (a"
                + " clip's name, '=', a weight)"},
            {"--blend", "clip-a=1", "--additive", "clip-b=-1"}, {"pose: --additive: the weight of clip 'clip-b' is -1,"
                + " negative (a weight is 0 or more)"},
            {"--blend", "clip-a=1", "--additive", "clip-b=1@soon"}, {"pose: --additive: the reference time of clip"
                + " 'clip-b' is 'soon', not a time in seconds (a decimal number)"},
            {"--blend", "clip-a=1", "--additive", "clip-b=1@NaN"}, {"pose: --additive: the reference time of clip"
                + " 'clip-b' is 'NaN', not a time in seconds (a decimal number)"},
            {"--blend", "clip-a=1", "--additive", "clip-b=1@-0.5"}, {"pose: --additive: the reference time of clip"
                + " 'clip-b' is -0.5, not 0 or more seconds after the clip's start"},
            {"--additive", "clip-b=1"}, {"pose: --additive needs --blend (the clips of the base layer that additive"
                + " layers go on)"},
            {"--blend", "clip-a=1", "--clip", "clip-b"}, {"pose: --clip and --blend exclude each other (name the clip"
                + " in --blend: --blend clip-b=1)"},
        };
        for (int i = 0; i < cases.length; i += 2) {
            List<String> args = new ArrayList<>(List.of("pose", INTERPOLATION, "--method", "lbs", "--time", "0.5"));
            args.addAll(List.of(cases[i]));
            Cli r = Cli.run(args.toArray(String[]::new));
            String what = String.join(" ", cases[i]);
            assertEquals(ExitCodes.USAGE, r.status, () -> what + ": " + r);
            assertEquals("", r.out, () -> what + ": " + r);
            assertEquals(List.of("skinlab: " + cases[i + 1][0]), List.of(r.errLines()), what);
        }
    }
}
