package org.skinlab.desktop.bench;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;

import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.importer.ModelImporter;
import org.skinlab.model.Model;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinnedModel;
import org.skinlab.skinning.SkinningMethod;

/**
 * The generated .glb is the generated .dae's character (what makes {@code bench parse}'s
 * comparison of our two imports fair): same triangles, and every glTF point, posed with LBS at a
 * key and between keys, lands where the COLLADA point at its bind position lands (both brought to
 * Y-up), within 1e-5 of the grid's size. Deterministic bytes, too.
 */
class SyntheticGltfTest {
    @Test
    void glbIsTheSameCharacterAsTheDae(@TempDir Path dir) throws Exception {
        Path glb = dir.resolve("grid.glb");
        Path dae = dir.resolve("grid.dae");
        long triangles = SyntheticGltf.write(glb, 300);
        assertEquals(triangles, SyntheticCollada.write(dae, 300));
        Model gltf = ModelImporter.read(glb);
        Model collada = ModelImporter.read(dae);
        assertEquals(triangles, gltf.meshes().get(0).triangleCount());
        assertEquals(triangles, collada.meshes().get(0).triangleCount());

        SkinnedModel a = SkinnedModel.of(gltf);
        SkinnedModel b = SkinnedModel.of(collada);
        SkinnedGeometry ga = a.geometries().get(0);
        SkinnedGeometry gb = b.geometries().get(0);
        Matrix4f upA = gltf.asset().toYUpMeters(new Matrix4f());
        Matrix4f upB = collada.asset().toYUpMeters(new Matrix4f());
        float[] bindA = upright(upA, ga.positionArray());
        float[] bindB = upright(upB, gb.positionArray());
        int[] twin = new int[bindA.length / 3];
        for (int i = 0; i < twin.length; i++) {
            twin[i] = nearest(bindA, i, bindB);
            assertTrue(distance(bindA, i, bindB, twin[i]) < 1e-6, "glTF point " + i + " is at a COLLADA point");
        }
        float[] posA = new float[bindA.length];
        float[] posB = new float[bindB.length];
        float[] normals = new float[Math.max(bindA.length, bindB.length)];
        double worst = 0;
        for (float t : new float[] {0.25f, 0.4f, 0.5f, 0.875f}) {
            a.pose(t, RotationInterpolation.SLERP);
            b.pose(t, RotationInterpolation.SLERP);
            a.skin(0, SkinningMethod.LBS, posA, normals);
            b.skin(0, SkinningMethod.LBS, posB, normals);
            float[] pa = upright(upA, posA);
            float[] pb = upright(upB, posB);
            for (int i = 0; i < twin.length; i++) {
                worst = Math.max(worst, distance(pa, i, pb, twin[i]));
            }
        }
        assertTrue(worst < 1e-5 * 4, "posed alike (the grid is 4 m wide): " + worst);

        Path again = dir.resolve("again.glb");
        SyntheticGltf.write(again, 300);
        assertArrayEquals(Files.readAllBytes(glb), Files.readAllBytes(again), "the same bytes every time");
    }

    private static int nearest(float[] a, int i, float[] b) {
        int best = 0;
        for (int j = 1; j < b.length / 3; j++) {
            if (distance(a, i, b, j) < distance(a, i, b, best)) {
                best = j;
            }
        }
        return best;
    }

    private static float[] upright(Matrix4f m, float[] xyz) {
        float[] out = new float[xyz.length];
        Vector3f p = new Vector3f();
        for (int i = 0; i < xyz.length; i += 3) {
            m.transformPosition(p.set(xyz[i], xyz[i + 1], xyz[i + 2]));
            out[i] = p.x;
            out[i + 1] = p.y;
            out[i + 2] = p.z;
        }
        return out;
    }

    private static double distance(float[] a, int i, float[] b, int j) {
        double dx = a[3 * i] - b[3 * j];
        double dy = a[3 * i + 1] - b[3 * j + 1];
        double dz = a[3 * i + 2] - b[3 * j + 2];
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }
}
