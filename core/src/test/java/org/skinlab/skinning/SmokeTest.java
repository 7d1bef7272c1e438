package org.skinlab.skinning;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.File;
import java.util.Iterator;
import java.util.Map;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import org.junit.jupiter.api.Test;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.collada.ColladaImporter;
import org.skinlab.model.Model;
import org.skinlab.testing.TestPaths;

class SmokeTest {
    @Test
    void humanoid() throws Exception {
        for (String name : new String[] {"characters/humanoid-walk", "creatures/tentacle-wave", "cylinders/cylinder-twist-low", "cylinders/cylinder-bend"}) {
            Model model = ColladaImporter.read(TestPaths.asset(name + ".dae"));
            SkinnedModel sm = SkinnedModel.of(model);
            JsonNode ref = new ObjectMapper().readTree(new File(TestPaths.root().toFile(), "assets/reference/" + name.substring(name.indexOf('/') + 1) + ".json"));
            SkinnedGeometry g = sm.geometries().get(0);
            float[] pos = new float[3 * g.pointCount()];
            float[] nrm = new float[3 * g.pointCount()];
            double max = 0;
            for (JsonNode key : ref.get("keys")) {
                sm.pose((float) key.get("time").asDouble(), RotationInterpolation.SLERP);
                sm.skin(0, SkinningMethod.LBS, pos, nrm);
                for (Iterator<Map.Entry<String, JsonNode>> it = key.get("vertices").fields(); it.hasNext();) {
                    Map.Entry<String, JsonNode> e = it.next();
                    int p = g.pointOfPosition(Integer.parseInt(e.getKey()));
                    for (int c = 0; c < 3; c++) {
                        max = Math.max(max, Math.abs(pos[3 * p + c] - e.getValue().get(c).asDouble()));
                    }
                }
            }
            System.out.println(name + " max deviation " + max);
            assertEquals(0, max, 1e-4);
        }
    }
}
