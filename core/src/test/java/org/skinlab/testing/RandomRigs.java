package org.skinlab.testing;

import java.util.Random;

import org.joml.Matrix4f;
import org.joml.Quaternionf;
import org.skinlab.skinning.JointPalette;
import org.skinlab.skinning.SkinnedGeometry;

/**
 * Random rigs for the kernels' tests in core and simd: geometries with random points, influences
 * and bind frames, and palettes of random joints, the same for a seed on every run.
 */
public final class RandomRigs {
    /** What the joints of {@link #palette(SkinnedGeometry, long, Joints)} are. */
    public enum Joints {
        /** Rotations and translations only. */
        RIGID,
        /** Every other joint also scaled non-uniformly (0.5 to 2 per axis). */
        SCALED,
        /** Every other joint also mirrored (x to -x). */
        MIRRORED
    }

    private RandomRigs() {
    }

    /**
     * {@code points} random points with {@code width} distinct random joints of {@code joints}
     * each and positive weights summing to 1 (the first not always the largest: the kernels must
     * take the order as given); normals unit, or zero for every 5th point.
     */
    public static SkinnedGeometry geometry(long seed, int points, int width, int joints) {
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
     * A palette for {@code geometry}, prepared for every method: per joint a random rotation (any
     * angle, so that neighbouring joints often lie in opposite hemispheres) and translation, and
     * what {@code kind} adds.
     */
    public static JointPalette palette(SkinnedGeometry geometry, long seed, Joints kind) {
        Random r = new Random(seed);
        JointPalette palette = geometry.newPalette();
        Matrix4f m = new Matrix4f();
        for (int j = 0; j < palette.jointCount(); j++) {
            Quaternionf q = new Quaternionf(r.nextFloat() - 0.5f, r.nextFloat() - 0.5f, r.nextFloat() - 0.5f,
                    r.nextFloat() - 0.5f).normalize();
            m.translationRotate(r.nextFloat() - 0.5f, r.nextFloat() - 0.5f, r.nextFloat() - 0.5f, q);
            if (kind == Joints.SCALED && j % 2 == 1) {
                m.scale(0.5f + 1.5f * r.nextFloat(), 0.5f + 1.5f * r.nextFloat(), 0.5f + 1.5f * r.nextFloat());
            } else if (kind == Joints.MIRRORED && j % 2 == 0) {
                m.scale(-1f, 1f, 1f);
            }
            palette.setMatrix(j, m);
        }
        palette.prepareAll();
        return palette;
    }

    /** As {@link #palette(SkinnedGeometry, long, Joints)}, {@link Joints#SCALED} or {@link Joints#RIGID}. */
    public static JointPalette palette(SkinnedGeometry geometry, long seed, boolean scaled) {
        return palette(geometry, seed, scaled ? Joints.SCALED : Joints.RIGID);
    }
}
