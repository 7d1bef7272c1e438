package org.skinlab.desktop.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.collada.ColladaImporter;
import org.skinlab.desktop.Cli;
import org.skinlab.skinning.SkinnedModel;
import org.skinlab.skinning.SkinningMethod;

/** CoR is chosen on the command line like LBS and DQS: pose, bench skinning, bench frame. */
class CorMethodCommandTest {
    @Test
    void poseWritesTheCorPositions(@TempDir Path dir) throws Exception {
        Path file = Cli.root().resolve("assets/cylinders/cylinder-bend.dae");
        Path json = dir.resolve("pose.json");
        Cli r = Cli.run("pose", file.toString(), "--time", "2", "--method", "cor", "--json", json.toString());
        assertEquals(0, r.status, r::toString);
        JsonNode doc = new ObjectMapper().readTree(json.toFile());
        assertEquals("cor", doc.get("method").asText());
        JsonNode pose = doc.get("meshes").get(0).get("poses").get(0);
        // The same as core's CoR kernel on the same pose (pose writes positions in source order).
        SkinnedModel skinned = SkinnedModel.of(ColladaImporter.read(file));
        skinned.pose(2f, RotationInterpolation.SLERP);
        var g = skinned.geometries().get(0);
        float[] points = new float[3 * g.pointCount()];
        skinned.skin(0, SkinningMethod.COR, points, new float[points.length]);
        float[] bySource = g.positionsInSourceOrder(points, new float[3 * g.positionCount()]);
        assertEquals(bySource.length, pose.size());
        for (int i = 0; i < bySource.length; i += 37) {
            assertEquals(bySource[i], pose.get(i).floatValue(), 0f, "coordinate " + i);
        }
    }

    @Test
    void benchmarksTakeCor() {
        Cli skinning = Cli.run("bench", "skinning", "--vertices", "2000", "--method", "cor", "--warmup-seconds", "0.2",
                "--seconds", "0.3");
        assertEquals(0, skinning.status, skinning::toString);
        assertTrue(skinning.out.contains("skinning cor"), skinning::toString);
        Cli baseline = Cli.run("bench", "skinning", "--method", "cor", "--baseline", "thesis");
        assertEquals(2, baseline.status, baseline::toString);
        Cli frame = Cli.run("bench", "frame", Cli.root().resolve("assets/characters/humanoid-walk.dae").toString(),
                "--method", "cor", "--warmup-seconds", "0.2", "--seconds", "0.3");
        assertEquals(0, frame.status, frame::toString);
        Cli unknown = Cli.run("pose", Cli.defaultAsset().toString(), "--time", "0", "--method", "xyz");
        assertEquals(2, unknown.status, unknown::toString);
        assertTrue(unknown.err.contains("expected one of lbs, dqs, cor, bfdqs, stbs-lbs, stbs-dqs, spline"),
                unknown::toString);
    }

    @Test
    void compareTabulatesTheMethodsAtAJoint() {
        Cli r = Cli.run("compare", Cli.root().resolve("assets/cylinders/cylinder-bend.dae").toString(), "--joint", "upper",
                "--time", "4", "--method", "cor,lbs", "--method", "dqs");
        assertEquals(0, r.status, r::toString);
        // The chosen set, in the enum's order, whatever order it was named in.
        assertTrue(r.out.contains("| bulge | distance to LBS | DQS | COR |\n|---|---:|---:|---:|---:|---:|---:|"),
                r::toString);
        assertTrue(r.out.contains("joint upper with parent lower, 640 points in the joint region"), r::toString);
        // At 170 degrees of bend: DQS bulges 0.038 m, CoR 0.006, LBS loses 8.5% of the volume.
        assertTrue(r.out.contains("| LBS | 0.9146 |"), r::toString);
        assertTrue(r.out.contains("| DQS | 0.9985 | 0.8182 | 0.0378 |"), r::toString);
        assertTrue(r.out.contains("| COR | 0.9749 | 0.8173 | 0.0061 |"), r::toString);
        Cli none = Cli.run("compare", Cli.defaultAsset().toString(), "--joint", "no_such_joint");
        assertEquals(2, none.status, none::toString);
        assertTrue(none.err.contains("no skin has a joint named no_such_joint"), none::toString);
    }
}
