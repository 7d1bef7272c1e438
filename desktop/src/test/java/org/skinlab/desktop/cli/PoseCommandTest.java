package org.skinlab.desktop.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.skinlab.desktop.Cli;
import org.skinlab.desktop.ExitCodes;

/**
 * {@code skinlab pose}: the JSON contract (keys, order, clamped times, one array of POSITION-order
 * coordinates per mesh and time), its values against Blender's deformation of our twist cylinder
 * (the committed reference {@code assets/reference/skinning/cylinder-twist-low.json}, made by
 * Blender 3.4 with no code of ours), static meshes placed and animated through their node
 * (expected positions worked out by hand), files without animation, and the usage errors.
 */
class PoseCommandTest {
    private static final ObjectMapper MAPPER = new ObjectMapper();

    /**
     * A static triangle under a node that translates by (1, 2, 3) and then rotates 90 degrees about
     * Z, so a local point (x, y, z) lands at (1 - y, 2 + x, 3 + z). A channel moves the translate's
     * X from 1 at t=1 s to 3 at t=2 s (LINEAR), clip "slide" over [1, 2]. The geometry has no name.
     */
    static final String STATIC_ANIMATED = """
            <?xml version="1.0" encoding="utf-8"?>
            <COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
              <library_geometries>
                <geometry id="tri">
                  <mesh>
                    <source id="tri-pos">
                      <float_array id="tri-pos-array" count="12">0 0 0  1 0 0  0 1 0  5 5 5</float_array>
                      <technique_common>
                        <accessor source="#tri-pos-array" count="4" stride="3">
                          <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
                        </accessor>
                      </technique_common>
                    </source>
                    <vertices id="tri-vtx"><input semantic="POSITION" source="#tri-pos"/></vertices>
                    <triangles count="1">
                      <input semantic="VERTEX" source="#tri-vtx" offset="0"/>
                      <p>2 0 1</p>
                    </triangles>
                  </mesh>
                </geometry>
              </library_geometries>
              <library_animations>
                <animation id="slide">
                  <source id="slide-in">
                    <float_array id="slide-in-array" count="2">1 2</float_array>
                    <technique_common><accessor source="#slide-in-array" count="2"><param name="TIME" type="float"/></accessor></technique_common>
                  </source>
                  <source id="slide-out">
                    <float_array id="slide-out-array" count="2">1 3</float_array>
                    <technique_common><accessor source="#slide-out-array" count="2"><param name="X" type="float"/></accessor></technique_common>
                  </source>
                  <sampler id="slide-sampler">
                    <input semantic="INPUT" source="#slide-in"/>
                    <input semantic="OUTPUT" source="#slide-out"/>
                  </sampler>
                  <channel source="#slide-sampler" target="mover/location.X"/>
                </animation>
              </library_animations>
              <library_animation_clips>
                <animation_clip name="slide" start="1" end="2"><instance_animation url="#slide"/></animation_clip>
              </library_animation_clips>
              <library_visual_scenes>
                <visual_scene id="scene">
                  <node id="mover">
                    <translate sid="location">1 2 3</translate>
                    <rotate sid="spin">0 0 1 90</rotate>
                    <instance_geometry url="#tri"/>
                  </node>
                </visual_scene>
              </library_visual_scenes>
              <scene><instance_visual_scene url="#scene"/></scene>
            </COLLADA>
            """;

    @TempDir
    Path dir;

    private static Path asset(String relative) {
        return Cli.root().resolve("assets").resolve(relative);
    }

    private static JsonNode json(Cli r) throws Exception {
        assertEquals(ExitCodes.OK, r.status, r::toString);
        assertEquals("", r.err, r::toString);
        return MAPPER.readTree(r.out);
    }

    private static double[] doubles(JsonNode array) {
        double[] d = new double[array.size()];
        for (int i = 0; i < d.length; i++) {
            assertTrue(array.get(i).isNumber(), () -> "not a number: " + array);
            d[i] = array.get(i).doubleValue();
        }
        return d;
    }

    /** Largest distance between corresponding points of two flat x,y,z arrays. */
    private static double maxDistance(double[] a, double[] b) {
        assertEquals(a.length, b.length);
        double max = 0;
        for (int i = 0; i < a.length; i += 3) {
            max = Math.max(max, Math.sqrt(sq(a[i] - b[i]) + sq(a[i + 1] - b[i + 1]) + sq(a[i + 2] - b[i + 2])));
        }
        return max;
    }

    private static List<Double> refTimesOf(JsonNode array) {
        List<Double> list = new java.util.ArrayList<>();
        for (double d : doubles(array)) {
            list.add(d);
        }
        return list;
    }

    private static double sq(double x) {
        return x * x;
    }

    @Test
    void jsonHasTheContractKeysClampedTimesAndMatchesBlenderForLbsAndDqs() throws Exception {
        JsonNode reference = MAPPER.readTree(asset("reference/skinning/cylinder-twist-low.json").toFile());
        double extent = reference.get("extent").doubleValue();
        List<Double> refTimes = refTimesOf(reference.get("times"));
        // The reference keys are 0, 1, 2, 3, 4 s; the clip is [0, 4]. -1 clamps to 0 and 9 to 4;
        // 2.5 lies between keys (no reference: checked for shape only).
        String file = asset("cylinders/cylinder-twist-low.dae").toString();
        for (String method : new String[] {"lbs", "dqs"}) {
            JsonNode root = json(Cli.run("pose", file, "--time", "-1,0,1,2.5,4,9", "--method", method, "--json", "-"));
            assertEquals(List.of("file", "clip", "method", "times", "meshes"), Cli.keys(root));
            assertEquals(file, root.get("file").textValue());
            assertEquals("default", root.get("clip").textValue());
            assertEquals(method, root.get("method").textValue());
            assertEquals(List.of(0.0, 0.0, 1.0, 2.5, 4.0, 4.0), refTimesOf(root.get("times")));

            assertEquals(1, root.get("meshes").size());
            JsonNode mesh = root.get("meshes").get(0);
            assertEquals(List.of("geometry", "name", "poses"), Cli.keys(mesh));
            assertEquals("Cylinder-mesh", mesh.get("geometry").textValue());
            assertEquals("Cylinder", mesh.get("name").textValue());
            JsonNode poses = mesh.get("poses");
            assertEquals(6, poses.size());
            for (JsonNode pose : poses) {
                assertEquals(3 * 576, pose.size(), "576 positions (assets/README.md), 3 numbers each");
            }
            // Clamped times give the very same pose as the key they clamp to.
            assertEquals(poses.get(1), poses.get(0));
            assertEquals(poses.get(4), poses.get(5));

            int[] posesAtRefTime = {1, 2, 4}; // our times 0, 1, 4
            double[] atTime = {0, 1, 4};
            for (int i = 0; i < posesAtRefTime.length; i++) {
                int k = refTimes.indexOf(atTime[i]);
                double[] blender = doubles(reference.get(method).get(k));
                double d = maxDistance(doubles(poses.get(posesAtRefTime[i])), blender);
                // Floats against Blender's floats, through different arithmetic: 1e-4 of the extent.
                assertTrue(d <= 1e-4 * extent, method + " at t=" + atTime[i] + ": " + d + " from Blender");
            }
            // 2.5 s lies between keys 2 and 3: its pose is neither.
            assertNotEquals(poses.get(3), poses.get(2));
        }
    }

    /**
     * Animated morph weights: the glTF fixture's clip "pulse" (CUBICSPLINE weights on body, STEP on
     * body2, a joint rotating) between keys, against three.js' positions in the committed reference
     * (core/src/test/resources/gltf/threejs; ThreeJsAgreementTest), within 1e-4 of the size.
     */
    @Test
    void morphWeightsAreAppliedBeforeSkinningAsThreeJsDoes() throws Exception {
        Path gltf = Cli.root().resolve("core/src/test/resources/gltf/morph-skin.gltf");
        JsonNode reference = MAPPER.readTree(Cli.root().resolve(
                "core/src/test/resources/gltf/threejs/morph-skin.gltf.json").toFile());
        JsonNode clip = reference.get("clips").get(2);
        assertEquals("pulse", clip.get("name").textValue());
        int k = 3; // 0.35 s: between the weights' keys 0 and 0.6
        double t = clip.get("times").get(k).doubleValue();
        JsonNode root = json(Cli.run("pose", gltf.toString(), "--clip", "pulse", "--time", Double.toString(t),
                "--method", "lbs", "--json", "-"));
        double size = reference.get("size").doubleValue();
        for (int m = 0; m < 2; m++) {
            double[] ours = doubles(root.get("meshes").get(m).get("poses").get(0));
            double[] three = doubles(clip.get("meshes").get(m).get("positions").get(k));
            assertTrue(maxDistance(ours, three) <= 1e-4 * size, "mesh " + m + ": " + maxDistance(ours, three));
        }
    }

    @Test
    void lbsAndDqsDifferWhereTheCylinderTwists() throws Exception {
        // At 4 s the upper half is twisted by 172 degrees: LBS collapses the joint region, DQS
        // does not, so the two outputs must differ by much more than the Blender tolerance.
        String file = asset("cylinders/cylinder-twist-low.dae").toString();
        double[] lbs = doubles(json(Cli.run("pose", file, "--time", "4", "--method", "lbs", "--json", "-"))
                .get("meshes").get(0).get("poses").get(0));
        double[] dqs = doubles(json(Cli.run("pose", file, "--time", "4", "--method", "dqs", "--json", "-"))
                .get("meshes").get(0).get("poses").get(0));
        assertTrue(maxDistance(lbs, dqs) > 0.05, "LBS and DQS should disagree at the twisted joint");
    }

    @Test
    void staticMeshIsPlacedAndAnimatedByItsNode() throws Exception {
        Path file = dir.resolve("static.dae");
        Files.writeString(file, STATIC_ANIMATED);
        Path out = dir.resolve("pose.json");
        Cli r = Cli.run("pose", file.toString(), "--time", "0,1.5,2", "--method", "lbs", "--json", out.toString());
        assertEquals(ExitCodes.OK, r.status, r::toString);
        assertEquals("", r.out, "with --json FILE nothing goes to stdout");
        JsonNode root = MAPPER.readTree(out.toFile());
        assertEquals("slide", root.get("clip").textValue());
        // 0 lies before the clip [1, 2] and is clamped to 1.
        assertEquals(List.of(1.0, 1.5, 2.0), List.of(root.get("times").get(0).doubleValue(),
                root.get("times").get(1).doubleValue(), root.get("times").get(2).doubleValue()));
        JsonNode mesh = root.get("meshes").get(0);
        assertEquals("tri", mesh.get("geometry").textValue());
        assertTrue(mesh.get("name").isNull(), "a geometry without a name gives null");
        // Positions (0,0,0) (1,0,0) (0,1,0) (5,5,5) map to (tx - y, 2 + x, 3 + z), tx = 1, 2, 3 at
        // t = 1, 1.5, 2. Position 3 is used by no triangle and is still reported, in source order.
        double[] tx = {1, 2, 3};
        for (int t = 0; t < 3; t++) {
            double[] expected = {tx[t], 2, 3, tx[t], 3, 3, tx[t] - 1, 2, 3, tx[t] - 5, 7, 8};
            double[] got = doubles(mesh.get("poses").get(t));
            assertEquals(12, got.length);
            // Float arithmetic on numbers below 10: 1e-5 absolute.
            assertTrue(maxDistance(got, expected) <= 1e-5, "t index " + t + ": " + java.util.Arrays.toString(got));
        }
    }

    @Test
    void jsonToStdoutAndToAFileAreTheSame() throws Exception {
        Path file = dir.resolve("static.dae");
        Files.writeString(file, STATIC_ANIMATED);
        Path out = dir.resolve("pose.json");
        Cli toFile = Cli.run("pose", file.toString(), "--time", "1.25", "--method", "dqs", "--json", out.toString());
        assertEquals(ExitCodes.OK, toFile.status, toFile::toString);
        Cli toStdout = Cli.run("pose", file.toString(), "--time", "1.25", "--method", "dqs", "--json", "-");
        assertEquals(ExitCodes.OK, toStdout.status, toStdout::toString);
        assertEquals(Files.readString(out), toStdout.out);
        assertTrue(toStdout.out.endsWith("}\n") && toStdout.out.indexOf('\n') == toStdout.out.length() - 1,
                "one line of JSON");
    }

    @Test
    void fileWithoutAnimationGivesTheRestPoseWithNullClipAndTheTimesAsGiven() throws Exception {
        // The same file without its animation: every time is the rest placement (tx = 1).
        String still = STATIC_ANIMATED.replaceAll("(?s)<library_animations>.*</library_animation_clips>", "");
        assertFalse(still.contains("<animation"));
        Path file = dir.resolve("still.dae");
        Files.writeString(file, still);
        JsonNode root = json(Cli.run("pose", file.toString(), "--time", "-3,7.5", "--method", "lbs", "--json", "-"));
        assertTrue(root.get("clip").isNull());
        assertEquals(-3.0, root.get("times").get(0).doubleValue(), 0.0);
        assertEquals(7.5, root.get("times").get(1).doubleValue(), 0.0);
        double[] expected = {1, 2, 3, 1, 3, 3, 0, 2, 3, -4, 7, 8};
        for (JsonNode pose : root.get("meshes").get(0).get("poses")) {
            assertTrue(maxDistance(doubles(pose), expected) <= 1e-5, pose.toString());
        }
    }

    @Test
    void numbersArePrintedSoThatTheyReadBackToTheSameFloat() throws Exception {
        // 2.5 / 3 is not a short decimal: the printed digits must be Float.toString's.
        Path file = dir.resolve("static.dae");
        Files.writeString(file, STATIC_ANIMATED);
        Cli r = Cli.run("pose", file.toString(), "--time", "1.3333333", "--method", "lbs", "--json", "-");
        JsonNode root = json(r);
        float t = root.get("times").get(0).floatValue();
        assertEquals(1.3333333f, t, 0f);
        assertTrue(r.out.contains("\"times\":[" + Float.toString(1.3333333f) + "]"), r.out);
        // The raw text of the one pose, number by number (a parsed JsonNode would reformat them).
        int start = r.out.indexOf("\"poses\":[[") + "\"poses\":[[".length();
        String[] printed = r.out.substring(start, r.out.indexOf("]]", start)).split(",");
        assertEquals(12, printed.length, r.out);
        for (String p : printed) {
            assertEquals(Float.toString(Float.parseFloat(p)), p, "not the float's own digits");
        }
    }

    @Test
    void textSummaryNamesClipMethodTimesAndBoxes() {
        Path file = asset("cylinders/cylinder-twist-low.dae");
        Cli r = Cli.run("pose", file.toString(), "--time", "0,9", "--method", "dqs");
        assertEquals(ExitCodes.OK, r.status, r::toString);
        String[] lines = r.out.split("\n");
        assertEquals(6, lines.length, r::toString);
        assertEquals(file.toString(), lines[0]);
        assertEquals("  clip:   default, method dqs", lines[1]);
        assertEquals("  times:  0.0, 4.0 s", lines[2]);
        assertEquals("  Cylinder-mesh (Cylinder): 576 positions", lines[3]);
        // At rest the cylinder spans z 0..2 with radius 0.25 (assets/README.md).
        assertTrue(lines[4].matches("    t=0\\.0 +box \\(-0\\.2500, -0\\.2500, 0\\.0000\\) \\.\\. \\(0\\.2500, 0\\.2500, 2\\.0000\\)"),
                lines[4]);
        assertTrue(lines[5].startsWith("    t=4.0 "), lines[5]);
    }

    @Test
    void unknownClipIsAUsageErrorListingTheClips() throws Exception {
        Path file = dir.resolve("static.dae");
        Files.writeString(file, STATIC_ANIMATED);
        Cli r = Cli.run("pose", file.toString(), "--time", "1", "--method", "lbs", "--clip", "walk");
        assertEquals(ExitCodes.USAGE, r.status, r::toString);
        assertEquals("", r.out, r::toString);
        assertTrue(r.errLines()[0].equals("unknown clip 'walk' in " + file + "; available clips: 'slide'"), r::toString);
        Cli named = Cli.run("pose", file.toString(), "--time", "1", "--method", "lbs", "--clip", "slide", "--json", "-");
        assertEquals("slide", json(named).get("clip").textValue());
    }

    @Test
    void badTimesAndMethodsAreUsageErrors() {
        String file = asset("cylinders/cylinder-twist-low.dae").toString();
        for (String time : new String[] {"abc", "NaN", "1,,2", "Infinity", "1e40", "0x1p3", "1f"}) {
            Cli r = Cli.run("pose", file, "--time", time, "--method", "lbs");
            assertEquals(ExitCodes.USAGE, r.status, () -> time + ": " + r);
            assertEquals("", r.out, r::toString);
            assertTrue(r.err.startsWith("Invalid value for option '--time'"), () -> time + ": " + r);
        }
        Cli method = Cli.run("pose", file, "--time", "1", "--method", "blend");
        assertEquals(ExitCodes.USAGE, method.status, method::toString);
        assertTrue(method.err.startsWith("Invalid value for option '--method'"), method::toString);
        // Without --method: LBS, as the blend command line has it.
        Cli missing = Cli.run("pose", file, "--time", "1");
        assertEquals(ExitCodes.OK, missing.status, missing::toString);
        assertEquals(Cli.run("pose", file, "--time", "1", "--method", "lbs").out, missing.out);
        Cli interpolation = Cli.run("pose", file, "--time", "1", "--method", "lbs", "--interpolation", "cubic");
        assertEquals(ExitCodes.USAGE, interpolation.status, interpolation::toString);
    }

    @Test
    void interpolationChangesPosesBetweenKeysOnly() throws Exception {
        // Twist keys are 45 degrees apart: LERP shortens the quaternion between keys (the
        // thesis' shrinking artifact), so at 0.5 s it differs from SLERP; at the key 1 s the key
        // itself is used and the two agree exactly.
        String file = asset("cylinders/cylinder-twist-low.dae").toString();
        JsonNode slerp = json(Cli.run("pose", file, "--time", "0.5,1", "--method", "lbs", "--json", "-"));
        JsonNode lerp = json(Cli.run("pose", file, "--time", "0.5,1", "--method", "lbs", "--interpolation", "lerp",
                "--json", "-"));
        JsonNode s = slerp.get("meshes").get(0).get("poses");
        JsonNode l = lerp.get("meshes").get(0).get("poses");
        assertTrue(maxDistance(doubles(s.get(0)), doubles(l.get(0))) > 1e-3);
        assertEquals(s.get(1), l.get(1));
    }

    @Test
    void brokenFileTakesTheImportErrorPath() throws Exception {
        Path broken = dir.resolve("broken.dae");
        Files.writeString(broken, STATIC_ANIMATED.replace("<p>2 0 1</p>", "<p>2 0 4</p>"));
        Cli r = Cli.run("pose", broken.toString(), "--time", "1", "--method", "lbs", "--json", "-");
        assertEquals(ExitCodes.INVALID_FILE, r.status, r::toString);
        assertEquals("", r.out, r::toString);
        assertEquals(1, r.errLines().length, r::toString);
        assertTrue(r.errLines()[0].startsWith("skinlab: broken.dae: <p> in <geometry id=\"tri\">"), r::toString);
        Cli missing = Cli.run("pose", dir.resolve("missing.dae").toString(), "--time", "1", "--method", "lbs");
        assertEquals(ExitCodes.USAGE, missing.status, missing::toString);
    }
}
