package org.skinlab.mixer;

import org.joml.Quaternionf;
import org.skinlab.animation.AnimationHelper;

/**
 * The two operations poses are blended with, on one node's translation, rotation and scale in
 * {@link org.skinlab.animation.LocalPose}'s layout. Holds scratch quaternions: one per thread.
 */
final class Blend {
    private final Quaternionf q1 = new Quaternionf();
    private final Quaternionf q2 = new Quaternionf();

    /**
     * {@code dest = a + t (b - a)} for translation and scale, the slerp from a to b along the
     * shortest arc for rotation ({@link AnimationHelper#slerp}); {@code dest} may be {@code a}.
     */
    void mix(float[] a, int ao, float[] b, int bo, double t, float[] dest, int d) {
        if (t >= 1) {
            System.arraycopy(b, bo, dest, d, 10);
            return;
        }
        float u = (float) t;
        for (int c = 0; c < 3; c++) {
            dest[d + c] = a[ao + c] + u * (b[bo + c] - a[ao + c]);
            dest[d + 7 + c] = a[ao + 7 + c] + u * (b[bo + 7 + c] - a[ao + 7 + c]);
        }
        q1.set(a[ao + 3], a[ao + 4], a[ao + 5], a[ao + 6]);
        q2.set(b[bo + 3], b[bo + 4], b[bo + 5], b[bo + 6]);
        AnimationHelper.slerp(q1, q2, u, q1);
        dest[d + 3] = q1.x;
        dest[d + 4] = q1.y;
        dest[d + 5] = q1.z;
        dest[d + 6] = q1.w;
    }

    /**
     * Adds the difference of {@code value} from {@code reference} to {@code dest} by weight w:
     * {@code dest.r = dest.r * slerp(identity, conj(ref.r) * value.r, w)},
     * {@code dest.t += w (value.t - ref.t)}, {@code dest.s += w (value.s - ref.s)}.
     */
    void add(float[] value, int vo, float[] reference, int ro, double w, float[] dest, int d) {
        float u = (float) w;
        for (int c = 0; c < 3; c++) {
            dest[d + c] += u * (value[vo + c] - reference[ro + c]);
            dest[d + 7 + c] += u * (value[vo + 7 + c] - reference[ro + 7 + c]);
        }
        // delta = conj(ref) * value
        q1.set(-reference[ro + 3], -reference[ro + 4], -reference[ro + 5], reference[ro + 6])
                .mul(value[vo + 3], value[vo + 4], value[vo + 5], value[vo + 6]);
        if (u != 1f) {
            AnimationHelper.slerp(q2.identity(), q1, u, q1);
        }
        q2.set(dest[d + 3], dest[d + 4], dest[d + 5], dest[d + 6]).mul(q1);
        dest[d + 3] = q2.x;
        dest[d + 4] = q2.y;
        dest[d + 5] = q2.z;
        dest[d + 6] = q2.w;
    }
}
