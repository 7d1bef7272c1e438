package org.skinlab.skinning;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.EnumMap;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.gltf.GltfImporter;
import org.skinlab.model.Model;
import org.skinlab.testing.TestPaths;
import org.skinlab.internal.metrics.JointArtifacts;
import org.skinlab.internal.metrics.MethodComparison;
import org.skinlab.internal.metrics.RestPose;

/**
 * The measures on a character of many parts as FBX and Sketchfab exports make them
 * ({@code gltf/scaled-parts.gltf}, tools/gltf/make-fixtures.py): an armature scaled by 0.01, parts
 * under nodes with uniform, non-uniform and mirroring scales whose skins' inverse bind matrices
 * are taken against those nodes, an open part, a box cut into two meshes by material, a static
 * crate. Every expectation is derived here by hand from the fixture's numbers.
 *
 * <p>The fixture, in the armature's centimetres (times 0.01 in the document; its root only turns
 * Z-up into Y-up, which changes no volume or distance): joints hips (z = 0), spine (z = 100),
 * head (z = 200); parts in {@link Model#instances()} order: 0 body, a square column of half-width
 * 12.5 on local z 0..100 under a node of scale 2 (so half-width 25 on 0..200), rings every 25
 * local, on the hips up to z = 25, half and half on the ring at the spine (local z = 50), on the
 * spine from 75; 1 cloak, the same column of half-width 15 without its bottom; 2 and 3 the boot, a
 * cube of side 20 local (40) cut into three faces each; 4 helmet, a unit cube on the head under
 * translation (0, 0, 250), 30 degrees about z and scale (40, 30, 50); 5 badge, the same mesh
 * under translation (60, 0, 250) and scale (-20, 15, 25); 6 crate, static, a unit cube under
 * translation (-150, 0, 0) and scale 30. The clip scales the spine by 1.25 at t = 1 s and twists
 * it by 170 degrees about its bone at t = 2 s.
 */
class ScaledPartsMeasuresTest {
    /** The armature's scale: centimetres into the document's metres. */
    private static final double CM = 0.01;
    private static final double SIGMA = 1.25;
    private static final double TWIST = Math.toRadians(170);
    /** The body's and the cloak's joint ring: corners at half-width times sqrt 2 from the bone. */
    private static final double BODY_RING = 25 * Math.sqrt(2) * CM;
    private static final double CLOAK_RING = 30 * Math.sqrt(2) * CM;
    /** Rest volumes, cm^3 times CM^3: body 50 x 50 x 200, boot 40^3, helmet and badge by their scales. */
    private static final double BODY = 50.0 * 50 * 200 * CM * CM * CM;
    private static final double BOOT = 40.0 * 40 * 40 * CM * CM * CM;
    private static final double HELMET = 40.0 * 30 * 50 * CM * CM * CM;
    private static final double BADGE = 20.0 * 15 * 25 * CM * CM * CM;
    /**
     * The rest bounds over every part: x from the crate's -165 to the boot's 95, y within the
     * cloak's +-30, z from the crate's -15 to the helmet's 275 (the helmet turned by 30 degrees
     * reaches x and y +-24.8 and +-23.0, inside those).
     */
    private static final double SIZE = Math.sqrt(260.0 * 260 + 60 * 60 + 290 * 290) * CM;
    /**
     * Float rounding of DQS's scale phase: every joint is scaled here (0.02 for the body), and the
     * scale part of a joint 50 local units from the origin translates by 49, whose float steps are
     * 4e-6 (observed 1e-6 of the size in distance and 1.3e-6 in volume). LBS reproduces its rest
     * bit for bit.
     */
    private static final double ROUNDING = 1e-5;

    private static SkinnedModel skinned;
    private static RestPose rest;
    private static MethodComparison[] comparisons;

    @BeforeAll
    static void load() throws Exception {
        Model model = GltfImporter.read(TestPaths.root().resolve("core/src/test/resources/gltf/scaled-parts.gltf"));
        skinned = SkinnedModel.of(model);
        rest = RestPose.of(skinned);
        comparisons = new MethodComparison[skinned.geometries().size()];
        for (int g = 0; g < comparisons.length; g++) {
            comparisons[g] = new MethodComparison(rest, g);
        }
    }

    /** Poses the model and compares every part; returns the largest LBS-DQS distance. */
    private static double compare(float time) {
        skinned.pose(time, RotationInterpolation.SLERP);
        double max = 0;
        for (int g = 0; g < comparisons.length; g++) {
            comparisons[g].compare(skinned.palette(g).matrices());
            max = Math.max(max, comparisons[g].maxDistance());
        }
        return max;
    }

    private static double modelVolume(boolean dqs) {
        float[][] posed = new float[comparisons.length][];
        for (int g = 0; g < posed.length; g++) {
            posed[g] = dqs ? comparisons[g].dqsPositions() : comparisons[g].lbsPositions();
        }
        return rest.relativeVolume(posed);
    }

    /**
     * The body under the spine scaled by s: every ring is scaled about the spine's origin by
     * k = 1 - w + w s for its weight w on the spine (LBS of the identity and a uniform scale;
     * DQS's scale phase blends the same, its rigid parts all turn alike), so the column's square
     * rings at local z 0, 25, 50, 75, 100 get k = 1, 1, (1 + s) / 2, s, s, stand at
     * 50 + k (z - 50), and each slab between two rings is a frustum: h / 3 (A1 + A2 + sqrt(A1 A2)).
     */
    private static double bodyVolumeScaledBy(double s) {
        double[] z = {0, 25, 50, 75, 100};
        double[] k = {1, 1, (1 + s) / 2, s, s};
        double sum = 0;
        for (int r = 0; r + 1 < z.length; r++) {
            double h = 50 + k[r + 1] * (z[r + 1] - 50) - (50 + k[r] * (z[r] - 50));
            double a1 = 25 * 25 * k[r] * k[r];
            double a2 = 25 * 25 * k[r + 1] * k[r + 1];
            sum += h / 3 * (a1 + a2 + Math.sqrt(a1 * a2));
        }
        return sum / (25.0 * 25 * 100);
    }

    @Test
    void partsAreSortedAndTheirRestIsMeasuredWhereThePosesAre() {
        assertEquals(List.of(RestPose.PartVolume.CLOSED, RestPose.PartVolume.OPEN,
                RestPose.PartVolume.CLOSED_WITH_OTHERS, RestPose.PartVolume.CLOSED_WITH_OTHERS,
                RestPose.PartVolume.CLOSED, RestPose.PartVolume.CLOSED, RestPose.PartVolume.STATIC),
                java.util.stream.IntStream.range(0, 7).mapToObj(rest::partVolume).toList());
        assertEquals("5 of 6 skinned parts (2 closed only together); 1 open, 1 static part: not counted",
                rest.volumeNote());
        // Rest volumes in the document's units (the points themselves are in the meshes' own).
        assertEquals(BODY, rest.volume(0), 1e-6 * BODY);
        assertEquals(HELMET, rest.volume(4), 1e-6 * HELMET);
        // The badge's node mirrors: its triangles wind the other way in the document.
        assertEquals(-BADGE, rest.volume(5), 1e-6 * BADGE);
        assertEquals(SIZE, rest.size(), 1e-6 * SIZE);
        assertEquals(SIZE, comparisons[0].size(), 1e-6 * SIZE);
    }

    @Test
    void atTheBindPoseEveryMeasureIsNeutral() {
        double max = compare(0f);
        assertEquals(1.0, modelVolume(false), 1e-12, "LBS reproduces the rest bit for bit");
        assertEquals(1.0, modelVolume(true), ROUNDING);
        for (int g : new int[] {0, 4, 5}) {
            assertEquals(1.0, comparisons[g].lbsVolume(), 1e-12, "part " + g);
            assertEquals(1.0, comparisons[g].dqsVolume(), ROUNDING, "part " + g);
        }
        assertEquals(0.0, max / SIZE, ROUNDING);
        assertEquals(0.0, comparisons[0].maxRelative(), ROUNDING);
    }

    @Test
    void aJointScaledBySKeepsSCubedOfWhatItCarriesAlone() {
        double max = compare(1f);
        double body = bodyVolumeScaledBy(SIGMA);
        assertEquals(1.4619140625, body, 1e-12, "1 + 1.130208 + 1.764323 + 1.953125 over 4");
        double cube = SIGMA * SIGMA * SIGMA;
        for (MethodComparison c : new MethodComparison[] {comparisons[0]}) {
            assertEquals(body, c.lbsVolume(), ROUNDING);
            assertEquals(body, c.dqsVolume(), ROUNDING);
        }
        for (int g : new int[] {4, 5}) {
            assertEquals(cube, comparisons[g].lbsVolume(), ROUNDING, "part " + g);
            assertEquals(cube, comparisons[g].dqsVolume(), ROUNDING, "part " + g);
        }
        // The boot stays on the hips; the cloak is open and the crate static: neither counts.
        double whole = (BODY * body + BOOT + (HELMET + BADGE) * cube) / (BODY + BOOT + HELMET + BADGE);
        assertEquals(whole, modelVolume(false), ROUNDING);
        assertEquals(whole, modelVolume(true), ROUNDING);
        assertTrue(Double.isNaN(comparisons[1].lbsVolume()), "the cloak has no volume");
        assertTrue(Double.isNaN(comparisons[2].lbsVolume()), "half a boot has no volume of its own");
        // A uniform scale: DQS blends it as LBS does.
        assertEquals(0.0, max / SIZE, ROUNDING);
    }

    @Test
    void underTheTwistTheLargestDistanceIsTheCloaksRingOverTheModelsSize() {
        double max = compare(2f);
        // A ring point half on each joint: LBS averages it with itself turned by 170 degrees
        // (r cos 85 from the bone, on the bisector), DQS turns it by 85 (r from the bone, on the
        // same bisector): r (1 - cos 85) apart. Points on one joint move alike under both.
        double cloak = CLOAK_RING * (1 - Math.cos(TWIST / 2));
        assertEquals(cloak / SIZE, max / SIZE, ROUNDING);
        assertEquals(BODY_RING * (1 - Math.cos(TWIST / 2)) / SIZE, comparisons[0].maxRelative(), ROUNDING);
    }

    private static Map<SkinningMethod, JointArtifacts.Report> bodyAtSpine(float time) {
        JointArtifacts artifacts = new JointArtifacts(rest, 0, 1, 0);
        assertEquals(4, artifacts.regionSize(), "the ring at the spine");
        skinned.pose(time, RotationInterpolation.SLERP);
        Map<SkinningMethod, float[]> posed = new EnumMap<>(SkinningMethod.class);
        for (SkinningMethod m : new SkinningMethod[] {SkinningMethod.LBS, SkinningMethod.DQS}) {
            float[] p = new float[3 * skinned.geometries().get(0).pointCount()];
            skinned.skin(0, m, p, new float[p.length]);
            posed.put(m, p);
        }
        Map<SkinningMethod, JointArtifacts.Report> byMethod = new EnumMap<>(SkinningMethod.class);
        for (JointArtifacts.Report r : artifacts.report(posed, skinned.palette(0).matrices())) {
            byMethod.put(r.method(), r);
        }
        return byMethod;
    }

    @Test
    void theJointRingAndBulgeAreMeasuredAgainstTheRestPose() {
        for (JointArtifacts.Report r : bodyAtSpine(0f).values()) {
            assertEquals(1.0, r.volume(), ROUNDING, r.method() + " volume at rest");
            assertEquals(1.0, r.ringRadius(), ROUNDING, r.method() + " ring at rest");
            assertEquals(0.0, r.bulge() / SIZE, ROUNDING, r.method() + " bulge at rest");
        }
        // Scaled by s: the ring, half on the spine, moves out to (1 + s) / 2 of its radius; the
        // region is that ring, so the bulge is r ((1 + s) / 2 - 1), in metres.
        for (JointArtifacts.Report r : bodyAtSpine(1f).values()) {
            assertEquals(bodyVolumeScaledBy(SIGMA), r.volume(), ROUNDING, r.method() + " volume");
            assertEquals((1 + SIGMA) / 2, r.ringRadius(), ROUNDING, r.method() + " ring");
            assertEquals(BODY_RING * (SIGMA - 1) / 2, r.bulge(), ROUNDING * SIZE, r.method() + " bulge");
        }
        Map<SkinningMethod, JointArtifacts.Report> twist = bodyAtSpine(2f);
        assertEquals(Math.cos(TWIST / 2), twist.get(SkinningMethod.LBS).ringRadius(), ROUNDING, "the candy wrapper");
        assertEquals(1.0, twist.get(SkinningMethod.DQS).ringRadius(), ROUNDING);
        assertEquals(BODY_RING * (1 - Math.cos(TWIST / 2)) / SIZE,
                twist.get(SkinningMethod.LBS).distanceTo().get(SkinningMethod.DQS), ROUNDING);
    }
}
