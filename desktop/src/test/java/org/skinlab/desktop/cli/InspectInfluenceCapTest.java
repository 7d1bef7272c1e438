package org.skinlab.desktop.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import org.skinlab.collada.ColladaImporter;
import org.skinlab.desktop.Cli;
import org.skinlab.desktop.ExitCodes;
import org.skinlab.model.AnimationClip;
import org.skinlab.model.Model;
import org.skinlab.internal.metrics.InfluenceCapError;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.SkinnedModel;

/**
 * What {@code skinlab inspect} reports of influence caps, checked against
 * {@link InfluenceCapError} run directly (whose numbers core's InfluenceCapErrorTest checks
 * against an independent computation): here the wiring, the key layout, the worst over several
 * clips, and the option that turns it off. The file is core's hand-made five-influence chain
 * ({@code fixtures/skin/capped-chain.dae}).
 */
class InspectInfluenceCapTest {
    private static final ObjectMapper JSON = new ObjectMapper();
    /** JSON numbers are the float nearest the double result, printed shortest. */
    private static final double FLOAT = 1e-7;

    @TempDir
    Path dir;

    private static Path chain() {
        return Cli.root().resolve("core/src/test/resources/fixtures/skin/capped-chain.dae");
    }

    private static JsonNode inspectJson(Path file, String... options) throws Exception {
        String[] args = new String[options.length + 3];
        args[0] = "inspect";
        args[1] = "--json";
        System.arraycopy(options, 0, args, 2, options.length);
        args[args.length - 1] = file.toString();
        Cli r = Cli.run(args);
        assertEquals(ExitCodes.OK, r.status, r::toString);
        return JSON.readTree(r.out);
    }

    /** The direct result of one clip for caps 4 and 8 (one geometry). */
    private static List<InfluenceCapError.Result> direct(Model model, AnimationClip clip) {
        return InfluenceCapError.measure(new SkinnedModel(model, clip, NormalTransform.INVERSE_TRANSPOSE), 4, 8).get(0);
    }

    private static void assertWorst(InfluenceCapError.Worst expected, String clip, JsonNode actual) {
        assertEquals(expected.distance(), actual.get("distance").doubleValue(), FLOAT * expected.distance(), actual::toString);
        assertEquals(expected.relative(), actual.get("relative").doubleValue(), FLOAT * expected.relative(), actual::toString);
        assertEquals(expected.position(), actual.get("position").intValue(), actual::toString);
        assertEquals(clip, actual.get("clip").asText(), actual::toString);
        assertEquals(expected.time(), actual.get("time").floatValue(), 0f, actual::toString);
    }

    @Test
    void jsonReportsTheCapErrorsOfTheFilesClip() throws Exception {
        Model model = ColladaImporter.read(chain());
        List<InfluenceCapError.Result> expected = direct(model, model.clips().get(0));
        JsonNode cap = inspectJson(chain()).get("meshes").get(0).get("influenceCap");
        assertEquals(expected.get(0).size(), cap.get("restSize").doubleValue(), FLOAT * expected.get(0).size());
        assertEquals(31, cap.get("samples").intValue());
        JsonNode four = cap.get("caps").get("4");
        // The fixture's positions 3 and 7 have five influences, of which 0.1 and 0.05 are dropped.
        assertEquals(2, four.get("cappedPositions").intValue());
        assertEquals(0.1, four.get("maxDroppedWeight").doubleValue(), FLOAT);
        assertTrue(expected.get(0).lbs().relative() > 0.01, "the cap must matter for this test to say anything");
        assertWorst(expected.get(0).lbs(), "default", four.get("lbs"));
        assertWorst(expected.get(0).dqs(), "default", four.get("dqs"));
        JsonNode eight = cap.get("caps").get("8");
        assertEquals(0, eight.get("cappedPositions").intValue());
        assertEquals(0.0, eight.get("lbs").get("distance").doubleValue(), 0.0);
        assertTrue(eight.get("dqs").get("position").isNull());
    }

    @Test
    void textNamesTheWorstPositionAndTime() {
        Cli r = Cli.run("inspect", chain().toString());
        assertEquals(ExitCodes.OK, r.status, r::toString);
        String[] lines = r.out.split("\n");
        int at = List.of(lines).indexOf("        4 influences: 2 positions lose weight (up to 0.100)");
        assertTrue(at > 0, r::toString);
        assertTrue(lines[at - 1].matches("      influence caps over clip default \\(31 samples; rest size 3\\.082\\):"),
                lines[at - 1]);
        assertTrue(lines[at + 1].matches("          LBS 0\\.\\d+ \\(0\\.\\d+ of the size\\) at position \\d, default \\d\\.\\d{3} s"),
                lines[at + 1]);
        assertTrue(lines[at + 2].startsWith("          DQS "), lines[at + 2]);
        assertEquals("        8 influences: exact, no position loses weight", lines[at + 3]);
    }

    @Test
    void severalClipsReportTheWorstOfAllAndWhichClip() throws Exception {
        // Two clips: "gentle" (only fin turns) first, "whole" (everything) second.
        String text = Files.readString(chain()).replace("  <scene>", "  <library_animation_clips>\n"
                + "    <animation_clip id=\"gentle\" name=\"gentle\" start=\"0\" end=\"1\"><instance_animation url=\"#fin-rot\"/></animation_clip>\n"
                + "    <animation_clip id=\"whole\" name=\"whole\" start=\"0\" end=\"0.5\">"
                + "<instance_animation url=\"#root-rot\"/><instance_animation url=\"#mid-rot\"/>"
                + "<instance_animation url=\"#upper-rot\"/><instance_animation url=\"#upper-scale\"/>"
                + "<instance_animation url=\"#tip-rot\"/><instance_animation url=\"#fin-rot\"/></animation_clip>\n"
                + "  </library_animation_clips>\n  <scene>");
        Path file = Files.writeString(dir.resolve("two-clips.dae"), text);
        Model model = ColladaImporter.read(file);
        assertEquals(List.of("gentle", "whole"), model.clips().stream().map(AnimationClip::name).toList());
        List<InfluenceCapError.Result> gentle = direct(model, model.clips().get(0));
        List<InfluenceCapError.Result> whole = direct(model, model.clips().get(1));
        assertTrue(whole.get(0).lbs().distance() > gentle.get(0).lbs().distance());
        assertTrue(whole.get(0).dqs().distance() > gentle.get(0).dqs().distance());

        JsonNode cap = inspectJson(file).get("meshes").get(0).get("influenceCap");
        assertEquals(31 + 16, cap.get("samples").intValue());
        assertWorst(whole.get(0).lbs(), "whole", cap.get("caps").get("4").get("lbs"));
        assertWorst(whole.get(0).dqs(), "whole", cap.get("caps").get("4").get("dqs"));

        Cli r = Cli.run("inspect", file.toString());
        assertTrue(r.out.contains("      influence caps over 2 clips (47 samples; rest size 3.082):\n"), r::toString);
        assertTrue(r.out.contains(" at position " + whole.get(0).lbs().position() + ", whole "), r::toString);
    }

    @Test
    void staticMeshesHaveNoneAndTheOptionTurnsItOff() throws Exception {
        Path fixture = Cli.root().resolve("core/src/test/resources/fixtures/skin/two-skins-and-a-static-mesh.dae");
        JsonNode meshes = inspectJson(fixture).get("meshes");
        int measured = 0;
        for (JsonNode mesh : meshes) {
            assertTrue(mesh.has("influenceCap"), mesh::toString);
            if (mesh.get("skinned").booleanValue()) {
                assertTrue(mesh.get("influenceCap").isObject(), mesh::toString);
                measured++;
            } else {
                assertTrue(mesh.get("influenceCap").isNull(), mesh::toString);
            }
        }
        assertEquals(2, measured);

        JsonNode off = inspectJson(chain(), "--no-influence-caps").get("meshes").get(0);
        assertTrue(off.get("influenceCap").isNull(), off::toString);
        Cli r = Cli.run("inspect", "--no-influence-caps", chain().toString());
        assertEquals(ExitCodes.OK, r.status, r::toString);
        assertFalse(r.out.contains("influence caps"), r::toString);
    }
}
