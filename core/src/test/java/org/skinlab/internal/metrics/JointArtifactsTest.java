package org.skinlab.internal.metrics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.EnumMap;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.collada.ColladaImporter;
import org.skinlab.model.Model;
import org.skinlab.testing.TestPaths;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinnedModel;
import org.skinlab.skinning.SkinningMethod;

/** The per-method table on the cylinders: each method's artifact where the thesis and the paper put it. */
class JointArtifactsTest {
    private static Map<SkinningMethod, JointArtifacts.Report> reports(String asset, float time) throws Exception {
        Model model = ColladaImporter.read(TestPaths.asset(asset));
        SkinnedModel skinned = SkinnedModel.of(model);
        SkinnedGeometry g = skinned.geometries().get(0);
        int lower = model.skins().get(0).jointNames().indexOf("lower");
        int upper = model.skins().get(0).jointNames().indexOf("upper");
        JointArtifacts artifacts = new JointArtifacts(RestPose.of(skinned), 0, upper, lower);
        assertTrue(artifacts.regionSize() > 100, "region " + artifacts.regionSize());
        skinned.pose(time, RotationInterpolation.SLERP);
        Map<SkinningMethod, float[]> posed = new EnumMap<>(SkinningMethod.class);
        for (SkinningMethod m : SkinningMethod.values()) {
            float[] p = new float[3 * g.pointCount()];
            skinned.skin(0, m, p, new float[p.length]);
            posed.put(m, p);
        }
        List<JointArtifacts.Report> list = artifacts.report(posed, skinned.palette(0).matrices());
        Map<SkinningMethod, JointArtifacts.Report> byMethod = new EnumMap<>(SkinningMethod.class);
        for (JointArtifacts.Report r : list) {
            byMethod.put(r.method(), r);
            System.out.printf("%s at %.0f s, %s: volume %.4f, ring %.3f, bulge %.4f, distances %s%n", asset, time,
                    r.method(), r.volume(), r.ringRadius(), r.bulge(), r.distanceTo());
        }
        return byMethod;
    }

    @Test
    void twistTheCandyWrapperIsLbssAlone() throws Exception {
        Map<SkinningMethod, JointArtifacts.Report> r = reports("cylinders/cylinder-twist-high.dae", 4f);
        assertEquals(0.830, r.get(SkinningMethod.LBS).volume(), 0.005, "assets/README.md: LBS keeps 83%");
        assertTrue(r.get(SkinningMethod.LBS).ringRadius() < 0.5, "the LBS ring collapses");
        assertEquals(1.0, r.get(SkinningMethod.DQS).ringRadius(), 0.01);
        assertEquals(1.0, r.get(SkinningMethod.COR).ringRadius(), 0.05);
        assertEquals(1.0, r.get(SkinningMethod.COR).volume(), 0.02);
        // The same distance MethodComparison shows in the viewer (10.9% of the size).
        assertEquals(0.109, r.get(SkinningMethod.LBS).distanceTo().get(SkinningMethod.DQS), 0.003);
        assertEquals(r.get(SkinningMethod.LBS).distanceTo().get(SkinningMethod.DQS),
                r.get(SkinningMethod.DQS).distanceTo().get(SkinningMethod.LBS), 1e-12);
    }

    @Test
    void bendDqsBulgesAndCorLess() throws Exception {
        for (float time : new float[] {2f, 4f}) {
            Map<SkinningMethod, JointArtifacts.Report> r = reports("cylinders/cylinder-bend.dae", time);
            assertTrue(r.get(SkinningMethod.DQS).bulge() > 0.01, "DQS bulges at a bent joint");
            assertTrue(r.get(SkinningMethod.COR).bulge() < r.get(SkinningMethod.DQS).bulge(), "CoR bulges less");
            assertTrue(r.get(SkinningMethod.LBS).volume() < r.get(SkinningMethod.COR).volume(), "LBS loses the most");
        }
    }
}
