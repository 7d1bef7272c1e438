package org.skinlab.skinning;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.EnumMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.importer.ModelImporter;
import org.skinlab.model.Model;
import org.skinlab.testing.TestPaths;
import org.skinlab.internal.metrics.ArtifactMetrics;
import org.skinlab.internal.metrics.JointArtifacts;
import org.skinlab.internal.metrics.RestPose;

/**
 * LBS and DQS of the whole-turn cylinders (assets/README.md) at 30 samples a second over the whole
 * clip, between the keys too, against their closed forms. {@code lower} stays at rest and
 * {@code upper} turns by θ = 60 t degrees about the line through its head along its local axis a
 * (Y for the twist, X for the bend; both taken from upper's bind frame), so for a point v with
 * weights w_l, w_u, c the head and R(a, x) the rotation by x about a:
 * <ul>
 * <li>LBS: v' = c + w_l (v − c) + w_u R(a, θ) (v − c), the same at θ and θ − 360;</li>
 * <li>DQS (Kavan et al. 2008): both joints' dual quaternions are rotations about the same line, so
 *     their blend is one too, by φ = 2 atan2(w_u sin(θ'/2), w_l + w_u cos(θ'/2)), where θ' is θ
 *     wrapped into (−180, 180]: the shortest arc. v' = c + R(a, φ) (v − c). Past 180 degrees θ'
 *     changes sign, and so does every blended point's angle: DQS flips there (Blender's does too,
 *     assets/README.md).</li>
 * </ul>
 * Left out: the sample at the half turn (t = 3 s), where the blend's sign is arbitrary (the Blender
 * references leave it out too). Tolerance 1e-5 of the size: float arithmetic.
 */
class WholeTurnSkinningTest {
    private static final double TOLERANCE = 1e-5;
    private static final int SAMPLES_PER_SECOND = 30;
    /** Degrees; the samples next to the half turn, 2 degrees away, are kept (their blend is well defined). */
    private static final double HALF_TURN_MARGIN = 1;

    @ParameterizedTest(name = "{0}")
    @CsvSource({"cylinders/cylinder-twist-full.dae, 1", "cylinders/cylinder-twist-full.glb, 1",
        "cylinders/cylinder-bend-full.dae, 0", "cylinders/cylinder-bend-full.glb, 0"})
    void lbsAndDqsFollowTheirClosedFormsAndDqsFlipsPastAHalfTurn(String asset, int localAxis) throws Exception {
        Model model = ModelImporter.read(TestPaths.asset(asset));
        SkinnedModel skinned = SkinnedModel.of(model);
        SkinnedGeometry g = skinned.geometries().get(0);
        int lower = model.skins().get(0).jointNames().indexOf("lower");
        int upper = model.skins().get(0).jointNames().indexOf("upper");
        Matrix4f head = new Matrix4f().set(g.bindMatrixArray(), 16 * upper).invert();
        Vector3f c = head.getTranslation(new Vector3f());
        Vector3f a = (localAxis == 0 ? head.getColumn(0, new Vector3f()) : head.getColumn(1, new Vector3f()))
                .normalize();
        int n = g.pointCount();
        float[] rest = g.positionArray();
        float[] wl = new float[n];
        float[] wu = new float[n];
        int k = g.influencesPerPoint();
        for (int i = 0; i < n; i++) {
            for (int s = 0; s < k; s++) {
                int j = g.jointArray()[k * i + s];
                float w = g.weightArray()[k * i + s];
                if (j == lower) {
                    wl[i] += w;
                } else if (j == upper) {
                    wu[i] += w;
                }
            }
            assertEquals(1.0, wl[i] + wu[i], 1e-6, "point " + i + " is weighted by lower and upper alone");
        }
        double size = ArtifactMetrics.boundsDiagonal(rest, n);

        float[] lbs = new float[3 * n];
        float[] dqs = new float[3 * n];
        float[] normals = new float[3 * n];
        double[] worst = new double[2];
        int compared = 0;
        for (int step = 0; step <= 6 * SAMPLES_PER_SECOND; step++) {
            float t = (float) step / SAMPLES_PER_SECOND;
            double theta = Math.toRadians(60.0 * t);
            double wrapped = Math.atan2(Math.sin(theta), Math.cos(theta));
            if (Math.PI - Math.abs(wrapped) <= Math.toRadians(HALF_TURN_MARGIN)) {
                continue;
            }
            skinned.pose(t, RotationInterpolation.SLERP);
            skinned.skin(0, SkinningMethod.LBS, lbs, normals);
            skinned.skin(0, SkinningMethod.DQS, dqs, normals);
            Vector3f v = new Vector3f();
            Vector3f turned = new Vector3f();
            Vector3f expected = new Vector3f();
            for (int i = 0; i < n; i++) {
                v.set(rest[3 * i], rest[3 * i + 1], rest[3 * i + 2]).sub(c);
                rotate(v, a, theta, turned);
                expected.set(v).mul(wl[i]).add(turned.mul(wu[i])).add(c);
                worst[0] = Math.max(worst[0], check(asset, "lbs", t, i, lbs, expected, size));
                double phi = 2 * Math.atan2(wu[i] * Math.sin(wrapped / 2), wl[i] + wu[i] * Math.cos(wrapped / 2));
                rotate(v, a, phi, expected).add(c);
                worst[1] = Math.max(worst[1], check(asset, "dqs", t, i, dqs, expected, size));
            }
            compared++;
        }
        System.out.printf(Locale.ROOT, "%-36s %d times: LBS worst %.1e, DQS worst %.1e of the size%n", asset, compared,
                worst[0], worst[1]);
        assertEquals(6 * SAMPLES_PER_SECOND, compared, "every sample but the half turn's");
        printArtifacts(asset, skinned, g, lower, upper);
    }

    /** The distance of point i from {@code expected}, relative to the size; fails above the tolerance. */
    private static double check(String asset, String method, float t, int i, float[] posed, Vector3f expected,
            double size) {
        double d = expected.distance(posed[3 * i], posed[3 * i + 1], posed[3 * i + 2]) / size;
        if (d > TOLERANCE) {
            throw new AssertionError(String.format(Locale.ROOT, "%s %s t=%s point %d: (%.6f, %.6f, %.6f), the closed "
                    + "form gives (%.6f, %.6f, %.6f): %.2e of the size", asset, method, t, i, posed[3 * i],
                    posed[3 * i + 1], posed[3 * i + 2], expected.x, expected.y, expected.z, d));
        }
        return d;
    }

    /** Rodrigues: v turned by {@code angle} radians about unit axis a, into dest. */
    private static Vector3f rotate(Vector3f v, Vector3f a, double angle, Vector3f dest) {
        double cos = Math.cos(angle);
        double sin = Math.sin(angle);
        double dot = a.dot(v);
        Vector3f cross = a.cross(v, new Vector3f());
        return dest.set((float) (v.x * cos + cross.x * sin + a.x * dot * (1 - cos)),
                (float) (v.y * cos + cross.y * sin + a.y * dot * (1 - cos)),
                (float) (v.z * cos + cross.z * sin + a.z * dot * (1 - cos)));
    }

    /** The joint's numbers (JointArtifacts) at 90, 165, 180, 195, 270 and 360 degrees, for docs and issues. */
    private static void printArtifacts(String asset, SkinnedModel skinned, SkinnedGeometry g, int lower, int upper) {
        JointArtifacts artifacts = new JointArtifacts(RestPose.of(skinned), 0, upper, lower);
        assertTrue(artifacts.regionSize() > 0, "a joint region");
        for (float t : new float[] {1.5f, 2.75f, 3f, 3.25f, 4.5f, 6f}) {
            skinned.pose(t, RotationInterpolation.SLERP);
            Map<SkinningMethod, float[]> posed = new EnumMap<>(SkinningMethod.class);
            for (SkinningMethod m : new SkinningMethod[] {SkinningMethod.LBS, SkinningMethod.DQS}) {
                float[] p = new float[3 * g.pointCount()];
                skinned.skin(0, m, p, new float[p.length]);
                posed.put(m, p);
            }
            List<JointArtifacts.Report> reports = artifacts.report(posed, skinned.palette(0).matrices());
            StringBuilder line = new StringBuilder(String.format(Locale.ROOT, "%-36s %3.0f degrees:", asset, 60 * t));
            for (JointArtifacts.Report r : reports) {
                line.append(String.format(Locale.ROOT, "  %s volume %.4f ring %.4f bulge %+.4f", r.method().key(),
                        r.volume(), r.ringRadius(), r.bulge()));
            }
            System.out.println(line);
        }
    }
}
