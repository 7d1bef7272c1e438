package org.skinlab.simd;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Random;

import org.joml.Matrix4f;
import org.joml.Quaternionf;
import org.skinlab.collada.ColladaImporter;
import org.skinlab.model.MeshInstance;
import org.skinlab.model.Model;
import org.skinlab.skinning.JointPalette;
import org.skinlab.skinning.SkinnedGeometry;

/** Test inputs: random geometries and palettes, and the default asset's skinned meshes. */
final class Geometries {
    private Geometries() {
    }

    /**
     * {@code points} random points with {@code width} distinct random joints of {@code joints}
     * each and positive weights summing to 1 (the first not always the largest: the kernels must
     * take the order as given); normals unit, or zero for every 5th point.
     */
    static SkinnedGeometry random(long seed, int points, int width, int joints) {
        Random r = new Random(seed);
        float[] pos = new float[3 * points];
        float[] nrm = new float[3 * points];
        int[] jnt = new int[width * points];
        float[] w = new float[width * points];
        for (int i = 0; i < points; i++) {
            for (int c = 0; c < 3; c++) {
                pos[3 * i + c] = 4 * r.nextFloat() - 2;
            }
            if (i % 5 != 4) {
                float x = r.nextFloat() - 0.5f;
                float y = r.nextFloat() - 0.5f;
                float z = r.nextFloat() - 0.5f;
                float n = (float) Math.sqrt(x * x + y * y + z * z);
                nrm[3 * i] = x / n;
                nrm[3 * i + 1] = y / n;
                nrm[3 * i + 2] = z / n;
            }
            float sum = 0;
            for (int k = 0; k < width; k++) {
                int j;
                boolean taken;
                do {
                    j = r.nextInt(joints);
                    taken = false;
                    for (int m = 0; m < k; m++) {
                        taken |= jnt[width * i + m] == j;
                    }
                } while (taken);
                jnt[width * i + k] = j;
                w[width * i + k] = 0.05f + r.nextFloat();
                sum += w[width * i + k];
            }
            for (int k = 0; k < width; k++) {
                w[width * i + k] /= sum;
            }
        }
        float[] bind = new float[16 * joints];
        for (int j = 0; j < joints; j++) {
            new Matrix4f().translation(r.nextFloat() - 0.5f, r.nextFloat(), 0).get(bind, 16 * j);
        }
        return SkinnedGeometry.fromArrays(pos, nrm, width, jnt, w, bind);
    }

    /**
     * A palette for {@code geometry}: per joint a random rotation (any angle, so that neighbouring
     * joints often lie in opposite hemispheres) and translation, times a scale when {@code scaled}
     * (non-uniform, 0.5 to 2, on every other joint).
     */
    static JointPalette pose(SkinnedGeometry geometry, long seed, boolean scaled) {
        Random r = new Random(seed);
        JointPalette palette = geometry.newPalette();
        Matrix4f m = new Matrix4f();
        for (int j = 0; j < palette.jointCount(); j++) {
            Quaternionf q = new Quaternionf(r.nextFloat() - 0.5f, r.nextFloat() - 0.5f, r.nextFloat() - 0.5f,
                    r.nextFloat() - 0.5f).normalize();
            m.translationRotate(r.nextFloat() - 0.5f, r.nextFloat() - 0.5f, r.nextFloat() - 0.5f, q);
            if (scaled && j % 2 == 1) {
                m.scale(0.5f + 1.5f * r.nextFloat(), 0.5f + 1.5f * r.nextFloat(), 0.5f + 1.5f * r.nextFloat());
            }
            palette.setMatrix(j, m);
        }
        palette.prepareAll();
        return palette;
    }

    /** The skinned meshes of the default asset, assets/characters/humanoid-walk.dae. */
    static SkinnedGeometry humanoid() throws Exception {
        Path root = Path.of(System.getProperty("skinlab.root", "..")).toAbsolutePath().normalize();
        Path file = root.resolve("assets/characters/humanoid-walk.dae");
        if (!Files.isRegularFile(file)) {
            throw new IllegalStateException("default asset missing: " + file);
        }
        Model model = ColladaImporter.read(file);
        for (MeshInstance instance : model.instances()) {
            if (instance.isSkinned()) {
                return SkinnedGeometry.of(instance);
            }
        }
        throw new IllegalStateException(file + " has no skinned mesh");
    }
}
