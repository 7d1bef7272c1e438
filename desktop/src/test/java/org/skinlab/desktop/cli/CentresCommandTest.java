package org.skinlab.desktop.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.skinlab.collada.ColladaImporter;
import org.skinlab.desktop.Cli;
import org.skinlab.model.Mesh;
import org.skinlab.skinning.CentresOfRotation;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinnedModel;

/** {@code skinlab centres}: the precomputation's table, and its JSON for other tools. */
class CentresCommandTest {
    private static final Path TWIST_LOW = Cli.root().resolve("assets/cylinders/cylinder-twist-low.dae");

    @Test
    void theTableHasARowPerSkinnedMesh() {
        Cli r = Cli.run("centres", TWIST_LOW.toString(), Cli.defaultAsset().toString(), "--runs", "2");
        assertEquals(0, r.status, r::toString);
        assertTrue(r.out.startsWith("sigma 0.1, epsilon 0.1, "), r::toString);
        // 576 positions, 1148 triangles; the coarse rings across the joint are subdivided.
        assertTrue(r.out.contains("| cylinder-twist-low.dae | Cylinder-mesh | 576 | 1148 | 5628 | "), r::toString);
        assertTrue(r.out.contains("| humanoid-walk.dae | Humanoid-mesh | 951 | 1896 | "), r::toString);
        Cli none = Cli.run("centres", TWIST_LOW.toString(), "--runs", "1", "--epsilon", "none");
        assertTrue(none.out.contains("| 576 | 1148 | 1148 | "), none::toString);
    }

    @Test
    void theJsonHoldsWhatAnotherToolNeedsInSourceOrder(@TempDir Path dir) throws Exception {
        Path json = dir.resolve("centres.json");
        Cli r = Cli.run("centres", TWIST_LOW.toString(), "--runs", "1", "--json", json.toString(), "--time", "4,9");
        assertEquals(0, r.status, r::toString);
        JsonNode doc = new ObjectMapper().readTree(json.toFile());
        assertEquals(0.1, doc.get("sigma").asDouble());
        assertEquals(0.1, doc.get("epsilon").asDouble());
        JsonNode m = doc.get("meshes").get(0);
        assertEquals("Cylinder-mesh", m.get("geometry").asText());

        SkinnedModel skinned = SkinnedModel.of(ColladaImporter.read(TWIST_LOW));
        SkinnedGeometry g = skinned.geometries().get(0);
        Mesh mesh = g.mesh();
        assertEquals(3 * mesh.positionCount(), m.get("positions").size());
        assertEquals(3 * mesh.triangleCount(), m.get("triangles").size());
        assertEquals(g.jointCount(), m.get("joints").asInt());
        assertEquals(mesh.positionCount(), m.get("influences").size());
        float[] centres = g.positionsInSourceOrder(
                CentresOfRotation.compute(g, CentresOfRotation.Parameters.DEFAULT, CentresOfRotation.Progress.NONE),
                new float[3 * mesh.positionCount()]);
        float[] rest = g.positionsInSourceOrder(g.positionArray(), new float[3 * mesh.positionCount()]);
        for (int i = 0; i < centres.length; i++) {
            assertEquals(centres[i], m.get("centres").get(i).floatValue(), 0f, "centre coordinate " + i);
            assertEquals(rest[i], m.get("positions").get(i).floatValue(), 0f, "position coordinate " + i);
        }
        // Triangles name positions: the first triangle's corners are its render vertices' positions.
        for (int c = 0; c < 3; c++) {
            assertEquals(mesh.vertexPosition(mesh.triangles()[c]), m.get("triangles").get(c).asInt());
        }
        // Influences as joint, weight pairs, the weights of a position summing to 1.
        for (JsonNode influences : m.get("influences")) {
            double sum = 0;
            for (int a = 1; a < influences.size(); a += 2) {
                sum += influences.get(a).asDouble();
            }
            assertEquals(1, sum, 1e-6);
        }

        // Each pose: its time clamped to the clip, the palette, and the CoR-skinned points, which are
        // the matrices applied to positions and centres as the paper's formula says (checked on a
        // point moved by one joint only: there it is that joint's matrix times the position).
        JsonNode poses = m.get("poses");
        assertEquals(2, poses.size());
        assertEquals(4.0, poses.get(1).get("time").asDouble(), 1e-6, "9 s clamped to the clip's end");
        JsonNode pose = poses.get(0);
        assertEquals(12 * g.jointCount(), pose.get("matrices").size());
        Cli poseCommand = Cli.run("pose", TWIST_LOW.toString(), "--time", "4", "--method", "cor", "--json",
                dir.resolve("pose.json").toString());
        assertEquals(0, poseCommand.status, poseCommand::toString);
        JsonNode cor = new ObjectMapper().readTree(dir.resolve("pose.json").toFile()).get("meshes").get(0).get("poses").get(0);
        assertEquals(cor.size(), pose.get("cor").size());
        for (int i = 0; i < cor.size(); i++) {
            assertEquals(cor.get(i).floatValue(), pose.get("cor").get(i).floatValue(), 0f, "the same as skinlab pose");
        }
        int rigid = -1;
        for (int p = 0; p < mesh.positionCount() && rigid < 0; p++) {
            if (m.get("influences").get(p).size() == 2) {
                rigid = p;
            }
        }
        JsonNode matrices = pose.get("matrices");
        int j = m.get("influences").get(rigid).get(0).asInt();
        for (int row = 0; row < 3; row++) {
            double v = matrices.get(12 * j + 4 * row + 3).asDouble();
            for (int col = 0; col < 3; col++) {
                v += matrices.get(12 * j + 4 * row + col).asDouble() * rest[3 * rigid + col];
            }
            assertEquals(v, pose.get("cor").get(3 * rigid + row).asDouble(), 1e-5, "one joint: its matrix times the point");
        }
    }

    @Test
    void badUseIsAUsageError(@TempDir Path dir) {
        String out = dir.resolve("c.json").toString();
        String[][] cases = {
            {"centres", TWIST_LOW.toString(), TWIST_LOW.toString(), "--json", out},
            {"centres", TWIST_LOW.toString(), "--time", "1"},
            {"centres", TWIST_LOW.toString(), "--epsilon", "0.001"},
            {"centres", TWIST_LOW.toString(), "--epsilon", "fine"},
            {"centres", TWIST_LOW.toString(), "--sigma", "0"},
            {"centres", TWIST_LOW.toString(), "--runs", "0"},
            {"centres", TWIST_LOW.toString(), "--sigma", "0.2", "--json", out, "--time", "1"},
        };
        for (String[] args : cases) {
            Cli r = Cli.run(args);
            assertEquals(2, r.status, () -> String.join(" ", args) + ": " + r);
        }
        Cli fine = Cli.run("centres", TWIST_LOW.toString(), "--epsilon", "0.001");
        assertTrue(fine.err.contains("weight epsilon 0.001 (need at least 0.01, or infinity for no subdivision)"),
                fine::toString);
        Cli missing = Cli.run("centres", "no-such-file.dae");
        assertEquals(2, missing.status, missing::toString);
    }
}
