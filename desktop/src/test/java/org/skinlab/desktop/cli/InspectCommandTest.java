package org.skinlab.desktop.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import org.junit.jupiter.api.Test;
import org.skinlab.desktop.Cli;
import org.skinlab.desktop.ExitCodes;

/**
 * {@code skinlab inspect} on the default asset. The JSON form is a contract other tools parse, so
 * the exact keys and their order are checked, with the values assets/README.md states for
 * humanoid-walk.dae (951 positions, 1896 triangles, 19 joints, at most 4 influences, one
 * one-second walk; 20 channels: one per joint and one for the armature node; one Lambert material
 * of diffuse colour 0.45 0.6 0.8). Its influence caps lose nothing; {@link InspectInfluenceCapTest}
 * checks caps that do.
 */
class InspectCommandTest {
    @Test
    void jsonHasTheContractKeysInOrderAndTheAssetsCounts() throws Exception {
        String file = Cli.defaultAsset().toString();
        Cli r = Cli.run("inspect", "--json", file);
        assertEquals(ExitCodes.OK, r.status, r::toString);
        assertEquals("", r.err, r::toString);
        // One line of JSON.
        assertTrue(r.out.endsWith("\n") && r.out.indexOf('\n') == r.out.length() - 1, r::toString);

        JsonNode root = new ObjectMapper().readTree(r.out);
        assertEquals(List.of("file", "upAxis", "unitMeter", "meshes", "clips", "warnings", "loadMillis"), Cli.keys(root));
        assertEquals(file, root.get("file").asText());
        assertEquals("Z_UP", root.get("upAxis").asText());
        assertTrue(root.get("unitMeter").isDouble());
        assertEquals(1.0, root.get("unitMeter").doubleValue(), 0.0);

        assertEquals(1, root.get("meshes").size());
        JsonNode mesh = root.get("meshes").get(0);
        assertEquals(List.of("geometry", "name", "positions", "triangles", "skinned", "joints", "maxInfluences",
                "materials", "influenceCap"), Cli.keys(mesh));
        assertEquals("Humanoid-mesh", mesh.get("geometry").asText());
        assertEquals("Humanoid", mesh.get("name").asText());
        assertEquals(951, mesh.get("positions").intValue());
        assertEquals(1896, mesh.get("triangles").intValue());
        assertTrue(mesh.get("skinned").isBoolean());
        assertTrue(mesh.get("skinned").booleanValue());
        assertEquals(19, mesh.get("joints").intValue());
        assertEquals(4, mesh.get("maxInfluences").intValue());
        assertEquals(1, mesh.get("materials").size());
        JsonNode material = mesh.get("materials").get(0);
        assertEquals(List.of("symbol", "name", "diffuse", "texture"), Cli.keys(material));
        assertEquals("BodyMaterial-material", material.get("symbol").asText());
        assertEquals("BodyMaterial", material.get("name").asText());
        assertEquals("[0.45,0.6,0.8,1.0]", material.get("diffuse").toString());
        assertTrue(material.get("texture").isNull());
        // Four influences at most: both caps keep everything (InspectInfluenceCapTest has errors).
        JsonNode cap = mesh.get("influenceCap");
        assertEquals(List.of("restSize", "samples", "caps"), Cli.keys(cap));
        assertTrue(cap.get("restSize").doubleValue() > 1.0, cap::toString);
        assertEquals(31, cap.get("samples").intValue(), "30 per second over one second, and the end");
        assertEquals(List.of("4", "8"), Cli.keys(cap.get("caps")));
        for (String k : List.of("4", "8")) {
            JsonNode c = cap.get("caps").get(k);
            assertEquals(List.of("cappedPositions", "maxDroppedWeight", "lbs", "dqs"), Cli.keys(c));
            assertEquals(0, c.get("cappedPositions").intValue());
            assertEquals(0.0, c.get("maxDroppedWeight").doubleValue(), 0.0);
            for (String m : List.of("lbs", "dqs")) {
                JsonNode w = c.get(m);
                assertEquals(List.of("distance", "relative", "position", "clip", "time"), Cli.keys(w));
                assertEquals(0.0, w.get("distance").doubleValue(), 0.0);
                assertEquals(0.0, w.get("relative").doubleValue(), 0.0);
                assertTrue(w.get("position").isNull() && w.get("clip").isNull() && w.get("time").isNull(), w::toString);
            }
        }

        assertEquals(1, root.get("clips").size());
        JsonNode clip = root.get("clips").get(0);
        assertEquals(List.of("name", "duration", "channels"), Cli.keys(clip));
        assertEquals("default", clip.get("name").asText());
        assertEquals(1.0, clip.get("duration").doubleValue(), 0.0);
        assertEquals(20, clip.get("channels").intValue());

        assertTrue(root.get("warnings").isArray());
        assertEquals(0, root.get("warnings").size());
        assertTrue(root.get("loadMillis").isNumber());
        assertTrue(root.get("loadMillis").doubleValue() >= 0.0);
    }

    @Test
    void textSummaryStatesFrameMeshSkinClipAndWarnings() {
        String file = Cli.defaultAsset().toString();
        Cli r = Cli.run("inspect", file);
        assertEquals(ExitCodes.OK, r.status, r::toString);
        assertEquals("", r.err, r::toString);
        String[] lines = r.out.split("\n");
        assertEquals(12, lines.length, r::toString);
        assertEquals(file, lines[0]);
        assertTrue(lines[1].startsWith("  frame:    Z_UP, 1 unit = 1 m, written by Blender"), lines[1]);
        assertTrue(lines[2].matches("  loaded in \\d+\\.\\d ms"), lines[2]);
        assertEquals("  meshes:   1", lines[3]);
        assertTrue(lines[4].matches("    Humanoid-mesh \\(Humanoid\\) +951 positions +1896 triangles  "
                + "skinned: 19 joints, up to 4 influences per position"), lines[4]);
        assertEquals("      material BodyMaterial-material: BodyMaterial, lambert, diffuse 0.450 0.600 0.800 1.00",
                lines[5]);
        assertTrue(lines[6].matches("      influence caps over clip default \\(31 samples; rest size \\d\\.\\d{3}\\):"),
                lines[6]);
        assertEquals("        4 influences: exact, no position loses weight", lines[7]);
        assertEquals("        8 influences: exact, no position loses weight", lines[8]);
        assertEquals("  clips:    1", lines[9]);
        assertTrue(lines[10].matches("    default +1\\.000 s +20 channels"), lines[10]);
        assertEquals("  warnings: 0", lines[11]);
    }

    @Test
    void materialsNameTheTextureFileResolvedAgainstTheDocumentsFolder() throws Exception {
        // The importer's material fixture: textures through every route, symbols bound and not.
        java.nio.file.Path file = Cli.root().resolve("core/src/test/resources/fixtures/materials/textured.dae");
        Cli r = Cli.run("inspect", "--json", file.toString());
        assertEquals(ExitCodes.OK, r.status, r::toString);
        JsonNode materials = new ObjectMapper().readTree(r.out).get("meshes").get(0).get("materials");
        assertEquals(10, materials.size());
        JsonNode skin = materials.get(0);
        assertEquals("skin", skin.get("symbol").asText());
        assertEquals("Skin", skin.get("name").asText());
        assertTrue(skin.get("diffuse").isNull());
        assertEquals(file.toAbsolutePath().getParent().resolve("skin.png").toString(), skin.get("texture").asText());
        JsonNode glass = materials.get(3);
        assertEquals("[0.25,0.5,0.75,1.0]", glass.get("diffuse").toString());
        assertTrue(glass.get("texture").isNull());
        JsonNode web = materials.get(7);
        assertTrue(web.get("texture").isNull(), "an http: image is no file");
        JsonNode unbound = materials.get(9);
        assertEquals("unbound", unbound.get("symbol").asText());
        assertTrue(unbound.get("name").isNull() && unbound.get("diffuse").isNull() && unbound.get("texture").isNull());
    }
}
