package org.skinlab.skinning;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.collada.ColladaImporter;
import org.skinlab.model.Model;
import org.skinlab.testing.TestPaths;
import org.skinlab.internal.metrics.ArtifactMetrics;
import org.skinlab.internal.metrics.RestPose;

/**
 * The candy wrapper in numbers, on our twist cylinder (two joints, "upper" twisted about the
 * cylinder's axis by 0, 45, 90, 135 and 172 degrees at 0..4 s; a closed mesh).
 *
 * <p>Expected values by hand: a vertex weighted half and half between a joint at rest and one
 * twisted by phi about the axis is moved by LBS to the average of two points phi apart on its
 * circle, at distance r cos(phi/2) from the axis: at 172 degrees 0.07 r, the ring collapses. DQS
 * blends the rotations instead (half the twist, a rotation): the ring keeps radius r and the
 * mesh its volume up to the smoothing of the bend-free twist.
 */
class CandyWrapperTest {
    private static Model model;
    private static SkinnedModel skinned;
    private static SkinnedGeometry geometry;
    private static RestPose rest;
    private static Vector3f joint;
    private static Vector3f axis;
    private static int[] ring;
    private static double restRadius;

    @BeforeAll
    static void load() throws Exception {
        model = ColladaImporter.read(TestPaths.asset("cylinders/cylinder-twist-low.dae"));
        skinned = SkinnedModel.of(model);
        geometry = skinned.geometries().get(0);
        rest = RestPose.of(skinned);
        // The joint ring sits where "upper" starts; the axis runs from "lower" to "upper".
        Matrix4f m = new Matrix4f();
        Vector3f lower = skinned.pose().world(model.nodeById("Armature_lower").orElseThrow().index(), m)
                .getTranslation(new Vector3f());
        joint = skinned.pose().world(model.nodeById("Armature_upper").orElseThrow().index(), m)
                .getTranslation(new Vector3f());
        axis = new Vector3f(joint).sub(lower);
        ring = ArtifactMetrics.ringPoints(geometry, joint, axis, 1e-4f);
        restRadius = ArtifactMetrics.meanDistanceFromAxis(geometry.positionArray(), ring, joint, axis);
    }

    private static float[] deform(float time, SkinningMethod method) {
        float[] pos = new float[3 * geometry.pointCount()];
        skinned.pose(time, RotationInterpolation.SLERP);
        skinned.skin(0, method, pos, new float[pos.length]);
        return pos;
    }

    @Test
    void ringAndRestVolumeAreWhatTheAssetSays() {
        // 17 even segments over z 0..2: the joint (z = 1) lies midway between the rings at
        // z = 16/17 and 18/17, 32 vertices each (make_cylinder.py).
        assertEquals(64, ring.length, "the two rings next to the joint");
        assertEquals(0.3902, ArtifactMetrics.signedVolume(geometry.positionArray(),
                geometry.mesh().triangles()), 5e-4, "rest volume (check_assets.py: 0.3902 m^3)");
        assertEquals(1.0, rest.relativeVolume(0, deform(0f, SkinningMethod.LBS)), 1e-6,
                "untwisted key keeps the rest shape");
    }

    @Test
    void twistOf172DegreesCollapsesTheLbsJointAndLosesVolume() {
        float[] lbs = deform(4f, SkinningMethod.LBS);
        double volume = rest.relativeVolume(0, lbs);
        double radius = ArtifactMetrics.meanDistanceFromAxis(lbs, ring, joint, axis) / restRadius;
        System.out.printf("LBS at 172 degrees: volume %.3f of rest, joint ring radius %.3f of rest%n", volume,
                radius);
        assertTrue(volume < 0.88, "LBS loses well over 10% of the volume, kept " + volume);
        // Prediction from the weights alone: a ring vertex with weight w on "upper" (twisted by
        // phi = 172 degrees) and 1 - w on "lower" (at rest) lands at |(1 - w) + w e^(i phi)| of
        // its radius.
        int upper = model.skins().get(0).jointNames().indexOf("upper");
        double phi = Math.toRadians(172);
        double predicted = 0;
        int width = geometry.influencesPerPoint();
        for (int i : ring) {
            double w = 0;
            for (int k = 0; k < width; k++) {
                if (geometry.jointArray()[width * i + k] == upper) {
                    w += geometry.weightArray()[width * i + k];
                }
            }
            predicted += Math.hypot(1 - w + w * Math.cos(phi), w * Math.sin(phi));
        }
        predicted /= ring.length;
        assertEquals(predicted, radius, 2e-3, "ring radius as the weights predict");
        assertTrue(radius < 0.5, "the LBS joint ring collapses toward the axis, radius ratio " + radius);
    }

    @Test
    void twistOf172DegreesKeepsTheDqsJointRingAndVolume() {
        float[] dqs = deform(4f, SkinningMethod.DQS);
        double volume = rest.relativeVolume(0, dqs);
        double radius = ArtifactMetrics.meanDistanceFromAxis(dqs, ring, joint, axis) / restRadius;
        System.out.printf("DQS at 172 degrees: volume %.3f of rest, joint ring radius %.3f of rest%n", volume,
                radius);
        assertEquals(1.0, volume, 0.03, "DQS keeps the volume within a few percent");
        // A blended rotation about the axis moves every ring vertex along its circle.
        assertEquals(1.0, radius, 0.01, "DQS keeps the joint ring radius");
    }

    @Test
    void lbsVolumeLossGrowsWithTheTwist() {
        double previous = 1.0;
        for (float t = 1; t <= 4; t++) {
            double v = rest.relativeVolume(0, deform(t, SkinningMethod.LBS));
            assertTrue(v < previous, "more twist, less volume: " + v + " after " + previous);
            previous = v;
        }
    }
}
