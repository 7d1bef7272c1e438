package org.skinlab.skinning;

import java.util.Arrays;

import org.skinlab.model.Skin;

/**
 * A skin's influences as a geometry's fixed-width rows, one per point, as
 * {@link SkinnedGeometry}'s class comment gives them ("Influences"): all influences of the point's
 * position, heaviest first, divided by their sum, padded with weight 0 on the dominant joint. A
 * position without weight (or with weights summing to zero) and COLLADA's joint index -1 take the
 * bind-shape pseudo-joint, palette index {@code skin.jointCount()}.
 */
final class SkinRows {
    final int width;
    /** Palette joint of each influence, {@link #width} per point. */
    final int[] joints;
    /** Normalised weight of each influence, {@link #width} per point. */
    final float[] weights;
    /** Whether some influence takes the bind-shape pseudo-joint. */
    boolean needsBindShapeJoint;

    private final Skin skin;
    /** The pseudo-joint's palette index, used only if needed. */
    private final int bindShapeJoint;

    private SkinRows(Skin skin, int points) {
        this.skin = skin;
        this.bindShapeJoint = skin.jointCount();
        this.width = Math.max(1, skin.maxInfluences());
        this.joints = new int[width * points];
        this.weights = new float[width * points];
    }

    /** The rows of the points whose positions are {@code positionOfPoint}. */
    static SkinRows of(Skin skin, int[] positionOfPoint) {
        SkinRows rows = new SkinRows(skin, positionOfPoint.length);
        int[] order = new int[rows.width];
        for (int i = 0; i < positionOfPoint.length; i++) {
            rows.fill(positionOfPoint[i], rows.width * i, order);
        }
        return rows;
    }

    /** Fills the row at {@code o} with position {@code p}'s influences. */
    private void fill(int p, int o, int[] order) {
        int start = skin.influenceStart(p);
        int n = skin.influenceCount(p);
        float sum = 0f;
        for (int k = 0; k < n; k++) {
            sum += weightOf(start + k);
            order[k] = start + k;
        }
        if (n == 0 || !(Math.abs(sum) > 1e-12f)) {
            needsBindShapeJoint = true;
            Arrays.fill(joints, o, o + width, bindShapeJoint);
            weights[o] = 1f;
            return;
        }
        sortByDecreasingWeight(order, n);
        for (int k = 0; k < width; k++) {
            if (k < n) {
                int j = skin.influenceJoint(order[k]);
                if (j < 0) {
                    needsBindShapeJoint = true;
                    j = bindShapeJoint;
                }
                joints[o + k] = j;
                weights[o + k] = weightOf(order[k]) / sum;
            } else {
                joints[o + k] = joints[o];
                weights[o + k] = 0f;
            }
        }
    }

    /** Insertion sort of the first {@code n} influences (n is small): the dominant one goes first. */
    private void sortByDecreasingWeight(int[] order, int n) {
        for (int a = 1; a < n; a++) {
            int e = order[a];
            int b = a - 1;
            while (b >= 0 && weightOf(order[b]) < weightOf(e)) {
                order[b + 1] = order[b];
                b--;
            }
            order[b + 1] = e;
        }
    }

    /**
     * An influence's weight as the kernels use it: a negative weight (the importer clamps and
     * warns; a skin built in code may still hold one) counts as 0, so a sum is never reduced or
     * cancelled to zero by it, and no point is pulled away from the joints it names.
     */
    private float weightOf(int influence) {
        return Math.max(0f, skin.influenceWeight(influence));
    }
}
