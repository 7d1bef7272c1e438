package org.skinlab.simd;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.nio.file.Path;
import java.util.Arrays;

import org.junit.jupiter.api.Test;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.collada.ColladaImporter;
import org.skinlab.skinning.JointPalette;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.PositionSharing;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinnedModel;
import org.skinlab.skinning.Skinner;
import org.skinlab.skinning.Skinners;
import org.skinlab.skinning.SkinningMethod;

/**
 * The spline Vector API kernel against core's scalar one on our assets, in poses of their clips.
 *
 * <p>Tolerance: |vector - scalar| <= 2e-5 * max(1, |scalar|), as for the other kernels
 * (VectorSkinnerTest): the same formulas in float, the vector kernel with fused multiply-adds and
 * the Vector API's sine; a wrong lane, sign or curve is off by 1e-2 or more.
 */
class VectorSplineSkinnerTest {
    private static final float TOLERANCE = 2e-5f;

    private static SkinnedModel model(String asset) throws Exception {
        Path root = Path.of(System.getProperty("skinlab.root", "..")).toAbsolutePath().normalize();
        return SkinnedModel.of(ColladaImporter.read(root.resolve("assets").resolve(asset)));
    }

    @Test
    void agreesWithTheScalarKernelOnTheAssets() throws Exception {
        for (String asset : new String[] {"cylinders/cylinder-bend.dae", "characters/humanoid-walk.dae",
            "creatures/tentacle-wave.dae"}) {
            SkinnedModel skinned = model(asset);
            SkinnedGeometry g = skinned.geometries().get(0);
            float duration = skinned.model().clips().get(0).duration();
            for (NormalTransform normals : new NormalTransform[] {NormalTransform.BLENDED_MATRIX,
                NormalTransform.INVERSE_TRANSPOSE}) {
                Skinner vector = new VectorSkinnerProvider().create(SkinningMethod.SPLINE, g, normals);
                assertTrue(vector != null, "the test JVM has the incubator module and AVX2");
                assertEquals("vector-256", vector.implementation());
                Skinner scalar = Skinners.scalar(SkinningMethod.SPLINE, g, normals, PositionSharing.NEVER);
                for (int step = 0; step < 5; step++) {
                    skinned.pose(duration * step / 5f, RotationInterpolation.SLERP);
                    JointPalette palette = skinned.palette(0).prepareAll();
                    int n = g.pointCount();
                    assertAgrees(asset, vector, scalar, palette, 0, n);
                    assertAgrees(asset, vector, scalar, palette, 3, n - 5);
                    assertDeformationsAgree(asset, vector, scalar, palette, 3, n - 5);
                }
            }
        }
    }

    private static void assertAgrees(String asset, Skinner vector, Skinner scalar, JointPalette palette, int from,
            int to) {
        int n = vector.geometry().pointCount();
        float[] vp = nanFilled(3 * n), vn = nanFilled(3 * n), sp = nanFilled(3 * n), sn = nanFilled(3 * n);
        vector.skin(palette, vp, vn, from, to);
        scalar.skin(palette, sp, sn, from, to);
        for (int i = 0; i < 3 * n; i++) {
            if (i < 3 * from || i >= 3 * to) {
                if (!Float.isNaN(vp[i]) || !Float.isNaN(vn[i])) {
                    fail(asset + ": float " + i + " outside [" + from + ", " + to + ") was written");
                }
                continue;
            }
            check(asset + " position", i, vp[i], sp[i]);
            check(asset + " normal", i, vn[i], sn[i]);
        }
    }

    private static void assertDeformationsAgree(String asset, Skinner vector, Skinner scalar, JointPalette palette,
            int from, int to) {
        int n = vector.geometry().pointCount();
        float[] vf = nanFilled(Skinner.DEFORMATION_FLOATS * n), sf = nanFilled(Skinner.DEFORMATION_FLOATS * n);
        vector.skinDeformations(palette, vf, from, to);
        scalar.skinDeformations(palette, sf, from, to);
        for (int i = Skinner.DEFORMATION_FLOATS * from; i < Skinner.DEFORMATION_FLOATS * to; i++) {
            check(asset + " deformation", i, vf[i], sf[i]);
        }
    }

    private static void check(String what, int i, float actual, float expected) {
        if (!(Math.abs(actual - expected) <= TOLERANCE * Math.max(1f, Math.abs(expected)))) {
            fail(what + " float " + i + " (point " + i / 3 + "): vector " + actual + ", scalar " + expected);
        }
    }

    private static float[] nanFilled(int n) {
        float[] a = new float[n];
        Arrays.fill(a, Float.NaN);
        return a;
    }
}
