package org.skinlab.skinning;

import java.util.Random;

import org.joml.Matrix4f;
import org.joml.Quaternionf;
import org.joml.Vector3f;

/**
 * A synthetic chain for the stretchable-bones tests: a tube of radius {@link #RADIUS} along +Y from
 * y = 0 to 3, rings every 0.05, joints 0, 1, 2 at y = 0, 1, 2 (each the previous one's child, bind
 * frames unrotated, so bone Y = world Y), three influences per point, weights by smoothstep within
 * {@link #BAND} of each joint (heaviest first). Poses are made joint by joint like a rig's: a local
 * rotation and scale under the parent's world matrix.
 */
final class StbsChain {
    static final float RADIUS = 0.2f;
    static final float BAND = 0.25f;
    static final int AROUND = 16;
    static final int RINGS = 61;

    private StbsChain() {
    }

    static float ringY(int ring) {
        return 0.05f * ring;
    }

    static SkinnedGeometry geometry() {
        int points = RINGS * AROUND;
        float[] positions = new float[3 * points];
        float[] normals = new float[3 * points];
        int[] joints = new int[3 * points];
        float[] weights = new float[3 * points];
        for (int r = 0; r < RINGS; r++) {
            float y = ringY(r);
            float[] w = weights(y);
            Integer[] order = {0, 1, 2};
            java.util.Arrays.sort(order, (a, b) -> Float.compare(w[b], w[a]));
            for (int a = 0; a < AROUND; a++) {
                int i = r * AROUND + a;
                double angle = 2 * Math.PI * a / AROUND;
                normals[3 * i] = (float) Math.cos(angle);
                normals[3 * i + 2] = (float) Math.sin(angle);
                positions[3 * i] = RADIUS * normals[3 * i];
                positions[3 * i + 1] = y;
                positions[3 * i + 2] = RADIUS * normals[3 * i + 2];
                for (int k = 0; k < 3; k++) {
                    joints[3 * i + k] = order[k];
                    weights[3 * i + k] = w[order[k]];
                }
            }
        }
        float[] bind = new float[48];
        for (int j = 0; j < 3; j++) {
            new Matrix4f().translation(0, -j, 0).get(bind, 16 * j);
        }
        return SkinnedGeometry.fromArrays(positions, normals, 3, joints, weights, bind, new int[] {-1, 0, 1});
    }

    /** Joint weights at height y: the child's rises by smoothstep across each joint's band. */
    static float[] weights(float y) {
        float s1 = smoothstep((y - 1 + BAND) / (2 * BAND));
        float s2 = smoothstep((y - 2 + BAND) / (2 * BAND));
        return new float[] {1 - s1, s1 - s2, s2};
    }

    private static float smoothstep(float u) {
        float c = Math.max(0f, Math.min(1f, u));
        return c * c * (3 - 2 * c);
    }

    /**
     * Sets the palette's skinning matrices for local rotations and scales (per joint, the scale in
     * the joint's own frame after its rotation), children inheriting everything, and prepares
     * dual quaternions and bone rows.
     */
    static void pose(JointPalette palette, Quaternionf[] rotations, Vector3f[] scales, Vector3f rootOffset) {
        Matrix4f world = new Matrix4f();
        for (int j = 0; j < 3; j++) {
            Matrix4f local = new Matrix4f().translation(j == 0 ? rootOffset : new Vector3f(0, 1, 0))
                    .rotate(rotations[j]).scale(scales[j]);
            world.mul(local);
            palette.setMatrix(j, new Matrix4f(world).translate(0, -j, 0));
        }
        palette.prepareAll();
    }

    /** A random pose: rotations up to {@code maxAngle} about random axes, scales in [0.7, 1.4]. */
    static void randomPose(JointPalette palette, Random random, float maxAngle, boolean scaled) {
        Quaternionf[] rotations = new Quaternionf[3];
        Vector3f[] scales = new Vector3f[3];
        for (int j = 0; j < 3; j++) {
            Vector3f axis = new Vector3f(random.nextFloat() - 0.5f, random.nextFloat() - 0.5f, random.nextFloat() - 0.5f)
                    .normalize();
            rotations[j] = new Quaternionf().rotateAxis(maxAngle * random.nextFloat(), axis);
            scales[j] = scaled ? new Vector3f(0.7f + 0.7f * random.nextFloat(), 0.7f + 0.7f * random.nextFloat(),
                    0.7f + 0.7f * random.nextFloat()) : new Vector3f(1, 1, 1);
        }
        pose(palette, rotations, scales, new Vector3f(random.nextFloat(), random.nextFloat(), random.nextFloat()));
    }
}
