package org.skinlab.animation;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import org.joml.Matrix4f;
import org.joml.Quaternionf;
import org.joml.Vector3f;
import org.skinlab.model.AnimationChannel;
import org.skinlab.model.AnimationClip;
import org.skinlab.model.Interpolation;
import org.skinlab.model.KeyframeTrack;
import org.skinlab.model.TransformElement;

/**
 * Samples one {@link AnimationClip} at any time into a {@link Pose}: writes the value of every
 * channel into the transform values it drives. Immutable and thread-safe; all scratch space lives
 * in the pose.
 *
 * <p>How a channel's keys are blended:
 * <ul>
 * <li><b>Whole matrices</b> (a channel that drives all 16 values of a {@code <matrix>}, as
 *     Blender, the thesis and most exporters write): each key is decomposed once, here, into
 *     translation, rotation and scale ({@link AnimationHelper#decompose}, robust to slightly
 *     non-orthonormal keys). Between LINEAR keys translation and scale are interpolated
 *     linearly and rotation by the caller's {@link RotationInterpolation}, along the shortest
 *     arc; the result is recomposed. On a key time, and for STEP keys, the key's own matrix is
 *     written unchanged (shear included), so sampling at a key reproduces the file exactly.</li>
 * <li><b>Rotation quaternions</b> (a channel that drives all 4 values of a
 *     {@link TransformElement.Kind#QUATERNION}, glTF's rotation): LINEAR keys are blended by the
 *     caller's {@link RotationInterpolation} along the shortest arc (the glTF specification's
 *     slerp when it is SLERP); BEZIER keys (glTF's CUBICSPLINE, see below) per value, then
 *     renormalised as the specification says; STEP holds.</li>
 * <li><b>Everything else</b> (a single value or a partial matrix, a {@code <rotate>} angle, a
 *     {@code <translate>} vector), and BEZIER/HERMITE matrices: each value on its own, by the key's
 *     interpolation: STEP holds, LINEAR blends, BEZIER and HERMITE follow the cubic Bezier through
 *     the two keys and their 2-D control points, solved for the parameter whose time is the sample
 *     time. HERMITE needs no path of its own: the importer already turned its derivative tangents
 *     into the equivalent Bezier control points ({@link KeyframeTrack}; exact, see
 *     docs/animation.md).</li>
 * </ul>
 * Before the first key a channel holds the first key, after the last the last. Channels apply in
 * clip order, so when two drive the same value the later wins.
 */
public final class AnimationSampler {
    private final AnimationClip clip;
    private final Skeleton skeleton;
    private final Channel[] channels;
    /** Per node, whether a channel drives one of its values. */
    private final boolean[] animated;
    /**
     * The nodes {@link #sampleLocal} turns from transform values into T, R and S after the
     * channels ran: those driven by channels other than a whole-matrix one on a one-matrix stack.
     */
    private final int[] valueNodes;

    /**
     * A sampler of {@code clip} for poses of {@code skeleton}. Resolves every channel to its place in the
     * pose's value array and pre-decomposes whole-matrix keys, so it allocates; build it once per clip.
     *
     * @param skeleton the skeleton of the model the clip belongs to; its nodes are what the channels name
     * @param clip the clip to sample
     * @throws IndexOutOfBoundsException when a channel names a node or transform element the skeleton lacks
     */
    public AnimationSampler(Skeleton skeleton, AnimationClip clip) {
        this.clip = clip;
        this.skeleton = skeleton;
        List<AnimationChannel> list = clip.channels();
        channels = new Channel[list.size()];
        List<float[]> timelines = new ArrayList<>();
        int nodes = skeleton.nodeCount();
        animated = new boolean[nodes];
        int[] channelsPerNode = new int[nodes];
        for (AnimationChannel c : list) {
            if (c.node() >= 0 && c.node() < nodes) {
                channelsPerNode[c.node()]++;
            }
        }
        boolean[] byValues = new boolean[nodes];
        for (int i = 0; i < channels.length; i++) {
            AnimationChannel c = list.get(i);
            int slot = skeleton.valueOffset(c.node(), c.transformIndex()) + c.valueOffset();
            TransformElement.Kind kind = skeleton.kind(c.node(), c.transformIndex());
            boolean matrix = kind == TransformElement.Kind.MATRIX && c.valueOffset() == 0 && c.valueCount() == 16;
            boolean quaternion = kind == TransformElement.Kind.QUATERNION && c.valueOffset() == 0
                    && c.valueCount() == 4;
            // A whole matrix that is its node's only transform and only channel goes to T, R, S directly,
            // and so does a whole translation, rotation or scale of a glTF stack.
            boolean localMatrix = matrix && channelsPerNode[c.node()] == 1
                    && skeleton.node(c.node()).transforms().size() == 1;
            int part = !skeleton.isTrsStack(c.node()) || c.valueOffset() != 0 || c.valueCount() != kind.size() ? -1
                    : kind == TransformElement.Kind.TRANSLATE ? 0 : kind == TransformElement.Kind.QUATERNION ? 3 : 7;
            int localSlot = localMatrix || part >= 0 ? LocalPose.STRIDE * c.node() + Math.max(part, 0) : -1;
            channels[i] = new Channel(slot, c.track(), sharedTimes(c.track().times(), timelines), matrix,
                    quaternion, localSlot);
            animated[c.node()] = true;
            byValues[c.node()] |= localSlot < 0;
        }
        int count = 0;
        for (boolean b : byValues) {
            count += b ? 1 : 0;
        }
        valueNodes = new int[count];
        for (int i = 0, k = 0; i < nodes; i++) {
            if (byValues[i]) {
                valueNodes[k++] = i;
            }
        }
    }

    /**
     * Whether the clip animates node {@code node} (a channel drives one of its transform values).
     *
     * @param node the node index, in [0, {@link Skeleton#nodeCount()})
     * @return true when a channel of the clip drives the node
     */
    public boolean animates(int node) {
        return animated[node];
    }

    /**
     * The skeleton this sampler samples poses of.
     *
     * @return the skeleton given to the constructor
     */
    public Skeleton skeleton() {
        return skeleton;
    }

    /**
     * One array per distinct list of key times: exporters key every channel of a clip at the same
     * times, and channels that share the array share one key search per sample.
     */
    static float[] sharedTimes(float[] times, List<float[]> timelines) {
        for (float[] t : timelines) {
            if (Arrays.equals(t, times)) {
                return t;
            }
        }
        timelines.add(times);
        return times;
    }

    /**
     * A sampler over no channels: every pose stays at rest.
     *
     * @param skeleton the skeleton whose poses it samples
     * @return a sampler of an empty clip named "rest", from 0 to 0 seconds
     */
    public static AnimationSampler rest(Skeleton skeleton) {
        return new AnimationSampler(skeleton, new AnimationClip(null, "rest", 0f, 0f, List.of()));
    }

    /**
     * The clip this sampler plays.
     *
     * @return the clip given to the constructor
     */
    public AnimationClip clip() {
        return clip;
    }

    /**
     * Clip start (seconds).
     *
     * @return the clip's start time in seconds, on the timeline of its keys
     */
    public float start() {
        return clip.start();
    }

    /**
     * Clip end (seconds).
     *
     * @return the clip's end time in seconds, never before {@link #start()}
     */
    public float end() {
        return clip.end();
    }

    /**
     * The clip time reached {@code elapsed} seconds of playback after the clip's start: wrapped
     * into {@code [start, end)} for {@link WrapMode#LOOP} (negative elapsed time plays backwards
     * from the end), held at the ends for {@link WrapMode#CLAMP}. A clip of zero length is
     * always at its start.
     *
     * @param elapsed seconds of playback since the clip's start, any sign
     * @param mode how time past either end is brought back into the clip
     * @return the clip time in seconds, in [{@link #start()}, {@link #end()}], for {@link #sample}
     */
    public float clipTime(double elapsed, WrapMode mode) {
        return (float) Math.min(clip.start() + wrapElapsed(elapsed, mode), clip.end());
    }

    /**
     * Playback time brought back into the clip, measured from its start: {@code [0, duration)}
     * for {@link WrapMode#LOOP}, {@code [0, duration]} for {@link WrapMode#CLAMP}, 0 for a clip of
     * zero length. A player keeps its clock in this form so it never grows without bound.
     *
     * @param elapsed seconds of playback since the clip's start, any sign
     * @param mode how time past either end is brought back into the clip
     * @return the seconds since the clip's start, in the range {@code mode} gives
     */
    public double wrapElapsed(double elapsed, WrapMode mode) {
        double duration = (double) clip.end() - clip.start();
        if (!(duration > 0)) {
            return 0;
        }
        if (mode == WrapMode.LOOP) {
            double t = elapsed % duration;
            if (t < 0) {
                t += duration;
            }
            return t < duration ? t : 0; // -tiny + duration can round up to duration
        }
        return Math.max(0, Math.min(duration, elapsed));
    }

    /**
     * Time {@code t} clamped to the clip: what the command line's times mean.
     *
     * @param t a clip time in seconds
     * @return {@code t} limited to [{@link #start()}, {@link #end()}]
     */
    public float clamp(float t) {
        return Math.max(clip.start(), Math.min(clip.end(), t));
    }

    /**
     * Writes every channel's value at clip time {@code time} into {@code pose.values()}. Values no
     * channel drives are left as they are (at rest for a fresh or reset pose). Allocation-free.
     * Call {@link Skeleton#evaluate} afterwards.
     *
     * @param time the clip time in seconds (the keys' timeline, not time since {@link #start()}); before the
     *     first key a channel holds that key, after the last the last
     * @param rotations how rotations of whole-matrix and quaternion channels are blended between LINEAR keys
     * @param pose a pose of the skeleton this sampler was made for; its values are written
     * @throws IllegalArgumentException when {@code time} is NaN
     */
    public void sample(float time, RotationInterpolation rotations, Pose pose) {
        if (Float.isNaN(time)) {
            throw new IllegalArgumentException("sample time is NaN");
        }
        float[] values = pose.values();
        float[] searched = null;
        int k = 0;
        for (Channel c : channels) {
            if (c.times != searched) {
                searched = c.times;
                k = segment(searched, time);
            }
            c.sample(k, time, rotations, values, c.slot, pose);
        }
    }

    /**
     * Samples the clip at {@code time} into local translation, rotation and scale: the form poses
     * are blended in. Every node the clip animates is written; the others are left as they are
     * (at rest for a fresh {@link LocalPose}). Whole-matrix keys are interpolated as in
     * {@link #sample} and written without being composed (on a key, its decomposition: shear
     * dropped); other transform stacks are sampled into {@code values}' transform values and
     * split into T, R and S. Allocation-free.
     *
     * @param time the clip time in seconds, as for {@link #sample}
     * @param rotations how rotations are blended between LINEAR keys
     * @param values a pose of this sampler's skeleton used for the transform values of nodes not written
     *     directly; it must always be the same pose for the same destination (its values persist)
     * @param dest receives the animated nodes' transforms
     * @throws IllegalArgumentException when {@code time} is NaN
     */
    public void sampleLocal(float time, RotationInterpolation rotations, Pose values, LocalPose dest) {
        if (Float.isNaN(time)) {
            throw new IllegalArgumentException("sample time is NaN");
        }
        float[] v = values.values();
        float[] trs = dest.array();
        float[] searched = null;
        int k = 0;
        for (Channel c : channels) {
            if (c.times != searched) {
                searched = c.times;
                k = segment(searched, time);
            }
            if (c.localSlot < 0) {
                c.sample(k, time, rotations, v, c.slot, values, true);
            } else if (!c.isMatrix()) {
                c.sample(k, time, rotations, trs, c.localSlot, values, true);
            } else if (!c.sampleLocal(k, time, rotations, trs, values)) {
                // A BEZIER/HERMITE matrix segment: per value, then split.
                c.sample(k, time, rotations, v, c.slot, values, true);
                skeleton.toLocal(c.localSlot / LocalPose.STRIDE, v, values.local, values.scratch, values.q1, trs);
            }
        }
        for (int node : valueNodes) {
            skeleton.toLocal(node, v, values.local, values.scratch, values.q1, trs);
        }
    }

    /**
     * The segment [k, k+1] of the keys that holds {@code time}: the last key at or before it, 0
     * before the first key (and for no keys), the last key from it on.
     */
    static int segment(float[] times, float time) {
        int last = times.length - 1;
        if (last <= 0 || time <= times[0]) {
            return 0;
        }
        if (time >= times[last]) {
            return last;
        }
        int lo = 0;
        int hi = last;
        while (hi - lo > 1) {
            int mid = (lo + hi) >>> 1;
            if (times[mid] <= time) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        return lo;
    }

    /**
     * One channel as flat arrays, with whole-matrix keys pre-decomposed; also what
     * {@link MorphWeightSampler} samples weights with (neither matrix nor quaternion, so no pose).
     */
    static final class Channel {
        /** Where the channel's values go in a pose's value array. */
        final int slot;
        private final int width;
        /** Key times, the same array for every channel with the same times (see sharedTimes). */
        final float[] times;
        private final float[] values;
        private final Interpolation[] interpolations;
        private final float[] in;
        private final float[] out;
        /** Per key translation (3), rotation (4), scale (3), or null when not a whole matrix. */
        private final float[] trs;
        /**
         * Per segment of a whole-matrix or rotation quaternion channel, what {@link AnimationHelper#slerp} derives from
         * the two keys alone: the angle between them (NaN where slerp falls back to nlerp) and its
         * sine, negated when the keys lie in opposite hemispheres (the shortest arc). Computed
         * once here, the per-frame slerp is two sines instead of an arc cosine and three sines,
         * with the same operations on the same values, so the same result to the bit.
         */
        private final double[] slerpAngles;
        private final double[] slerpSines;
        /** Whether the channel drives a whole rotation quaternion (x y z w). */
        private final boolean quaternion;
        /**
         * Whether every key holds the same values (exporters key every bone's scale, and often its
         * translation, whether it changes or not): the blend path copies them.
         */
        private final boolean constant;
        /**
         * Where {@link AnimationSampler#sampleLocal} writes the channel straight into a
         * {@link LocalPose}'s array (a whole matrix: its node's 10 floats; a glTF translation, rotation
         * or scale: its part of them), or -1 when it goes through the transform values.
         */
        final int localSlot;

        Channel(int slot, KeyframeTrack track, float[] times, boolean matrix, boolean quaternion) {
            this(slot, track, times, matrix, quaternion, -1);
        }

        Channel(int slot, KeyframeTrack track, float[] times, boolean matrix, boolean quaternion, int localSlot) {
            this.localSlot = localSlot;
            this.slot = slot;
            this.width = track.width();
            this.times = times;
            this.values = track.values();
            int keys = times.length;
            this.interpolations = new Interpolation[keys];
            for (int k = 0; k < keys; k++) {
                interpolations[k] = track.interpolation(k);
            }
            this.in = track.inTangents();
            this.out = track.outTangents();
            this.quaternion = quaternion;
            boolean same = true;
            for (int i = width; i < values.length && same; i++) {
                same = Float.floatToRawIntBits(values[i]) == Float.floatToRawIntBits(values[i % width]);
            }
            this.constant = same && !matrix;
            this.trs = matrix ? decomposeKeys(values, keys) : null;
            boolean rotations = matrix || quaternion;
            this.slerpAngles = rotations ? new double[keys] : null;
            this.slerpSines = rotations ? new double[keys] : null;
            float[] q = matrix ? trs : values;
            int stride = matrix ? 10 : 4;
            for (int k = 0; rotations && k + 1 < keys; k++) {
                int a = stride * k + (matrix ? 3 : 0);
                int b = a + stride;
                double dot = (double) q[a] * q[b] + (double) q[a + 1] * q[b + 1]
                        + (double) q[a + 2] * q[b + 2] + (double) q[a + 3] * q[b + 3];
                double cos = Math.min(1.0, Math.abs(dot));
                if (cos > AnimationHelper.SLERP_NLERP_THRESHOLD) {
                    slerpAngles[k] = Double.NaN;
                } else {
                    slerpAngles[k] = Math.acos(cos);
                    double sin = Math.sin(slerpAngles[k]);
                    slerpSines[k] = dot < 0 ? -sin : sin;
                }
            }
        }

        private static float[] decomposeKeys(float[] values, int keys) {
            float[] trs = new float[10 * keys];
            Matrix4f m = new Matrix4f();
            Matrix4f scratch = new Matrix4f();
            Vector3f t = new Vector3f();
            Quaternionf r = new Quaternionf();
            Vector3f s = new Vector3f();
            for (int k = 0; k < keys; k++) {
                TransformElement.multiply(TransformElement.Kind.MATRIX, values, 16 * k, m.identity(), scratch);
                AnimationHelper.decompose(m, t, r, s);
                int o = 10 * k;
                trs[o] = t.x;
                trs[o + 1] = t.y;
                trs[o + 2] = t.z;
                trs[o + 3] = r.x;
                trs[o + 4] = r.y;
                trs[o + 5] = r.z;
                trs[o + 6] = r.w;
                trs[o + 7] = s.x;
                trs[o + 8] = s.y;
                trs[o + 9] = s.z;
            }
            return trs;
        }

        boolean isMatrix() {
            return trs != null;
        }

        /**
         * Writes this channel's value at {@code time}, which lies in segment {@code k} of its keys,
         * into {@code dest} from {@code slot} on.
         */
        void sample(int k, float time, RotationInterpolation rotations, float[] dest, int slot, Pose pose) {
            sample(k, time, rotations, dest, slot, pose, false);
        }

        /**
         * As above; {@code fast}: slerps take their sines from {@link AnimationHelper#sinFast} (the
         * blend path, where they are most of the cost) rather than {@code Math.sin} (the one-clip
         * path, which keeps {@link AnimationHelper#slerp}'s floats exactly).
         */
        void sample(int k, float time, RotationInterpolation rotations, float[] dest, int slot, Pose pose,
                boolean fast) {
            // pose: scratch for matrices and quaternions only (null for morph weights)
            int keys = times.length;
            if (keys == 0) {
                return;
            }
            if (fast && constant) {
                System.arraycopy(values, 0, dest, slot, width);
                return;
            }
            Interpolation how = interpolations[k];
            // On key k (or before the first key, where k = 0), after the last one, or holding a STEP.
            if (k == keys - 1 || time <= times[k] || how == Interpolation.STEP) {
                System.arraycopy(values, k * width, dest, slot, width);
                return;
            }
            float t0 = times[k];
            float t1 = times[k + 1];
            if (how == Interpolation.LINEAR) {
                float u = t1 > t0 ? (time - t0) / (t1 - t0) : 1f;
                if (trs != null) {
                    blendMatrix(k, u, rotations, dest, slot, pose, fast);
                } else if (quaternion && rotations == RotationInterpolation.SLERP && !Double.isNaN(slerpAngles[k])) {
                    // AnimationHelper.slerp with the constants of this pair of keys (see slerpAngles).
                    double angle = slerpAngles[k];
                    double wa = sine((1 - u) * angle, fast) / Math.abs(slerpSines[k]);
                    double wb = sine(u * angle, fast) / slerpSines[k];
                    int a = 4 * k;
                    for (int c = 0; c < 4; c++) {
                        dest[slot + c] = (float) (wa * values[a + c] + wb * values[a + 4 + c]);
                    }
                } else if (quaternion) {
                    int a = 4 * k;
                    Quaternionf q = AnimationHelper.interpolate(rotations,
                            pose.q1.set(values[a], values[a + 1], values[a + 2], values[a + 3]),
                            pose.q2.set(values[a + 4], values[a + 5], values[a + 6], values[a + 7]), u, pose.q1);
                    dest[slot] = q.x;
                    dest[slot + 1] = q.y;
                    dest[slot + 2] = q.z;
                    dest[slot + 3] = q.w;
                } else {
                    int a = k * width;
                    int b = a + width;
                    for (int c = 0; c < width; c++) {
                        dest[slot + c] = values[a + c] + u * (values[b + c] - values[a + c]);
                    }
                }
                return;
            }
            // BEZIER / HERMITE: per value, the cubic Bezier through (t0, v0), out[k], in[k+1], (t1, v1)
            // (HERMITE tangents arrive as the equivalent control points, see KeyframeTrack).
            for (int c = 0; c < width; c++) {
                int oa = 2 * (k * width + c);
                int ob = 2 * ((k + 1) * width + c);
                dest[slot + c] = (float) bezier(time, t0, values[k * width + c], out[oa], out[oa + 1], in[ob],
                        in[ob + 1], t1, values[(k + 1) * width + c]);
            }
            if (quaternion) {
                normalize(dest, slot);
            }
        }

        /**
         * Writes this whole-matrix channel's T, R, S at {@code time} (segment {@code k}) into
         * {@code trs} at its node. False for a BEZIER or HERMITE segment, which it leaves to
         * {@link #sample}.
         */
        boolean sampleLocal(int k, float time, RotationInterpolation rotations, float[] trs, Pose pose) {
            int keys = times.length;
            if (keys == 0) {
                return true;
            }
            int o = localSlot;
            Interpolation how = interpolations[k];
            if (k == keys - 1 || time <= times[k] || how == Interpolation.STEP) {
                System.arraycopy(this.trs, 10 * k, trs, o, 10);
                return true;
            }
            if (how != Interpolation.LINEAR) {
                return false;
            }
            float t0 = times[k];
            float t1 = times[k + 1];
            float u = t1 > t0 ? (time - t0) / (t1 - t0) : 1f;
            int a = 10 * k;
            int b = a + 10;
            double angle = slerpAngles[k];
            if (rotations == RotationInterpolation.SLERP && !Double.isNaN(angle)) {
                double wa = AnimationHelper.sinFast((1 - u) * angle) / Math.abs(slerpSines[k]);
                double wb = AnimationHelper.sinFast(u * angle) / slerpSines[k];
                for (int c = 3; c < 7; c++) {
                    trs[o + c] = (float) (wa * this.trs[a + c] + wb * this.trs[b + c]);
                }
            } else {
                Quaternionf q = AnimationHelper.interpolate(rotations,
                        pose.q1.set(this.trs[a + 3], this.trs[a + 4], this.trs[a + 5], this.trs[a + 6]),
                        pose.q2.set(this.trs[b + 3], this.trs[b + 4], this.trs[b + 5], this.trs[b + 6]), u, pose.q1);
                trs[o + 3] = q.x;
                trs[o + 4] = q.y;
                trs[o + 5] = q.z;
                trs[o + 6] = q.w;
            }
            for (int c : TRANSLATION_AND_SCALE) {
                trs[o + c] = lerp(this.trs[a + c], this.trs[b + c], u);
            }
            return true;
        }

        private static final int[] TRANSLATION_AND_SCALE = {0, 1, 2, 7, 8, 9};

        private static void normalize(float[] q, int o) {
            double len = Math.sqrt((double) q[o] * q[o] + (double) q[o + 1] * q[o + 1]
                    + (double) q[o + 2] * q[o + 2] + (double) q[o + 3] * q[o + 3]);
            if (len > 0) {
                for (int c = 0; c < 4; c++) {
                    q[o + c] = (float) (q[o + c] / len);
                }
            }
        }

        private static double sine(double x, boolean fast) {
            return fast ? AnimationHelper.sinFast(x) : Math.sin(x);
        }

        private void blendMatrix(int k, float u, RotationInterpolation rotations, float[] dest, int slot, Pose pose,
                boolean fast) {
            int a = 10 * k;
            int b = a + 10;
            float qx;
            float qy;
            float qz;
            float qw;
            double angle = slerpAngles[k];
            if (rotations == RotationInterpolation.SLERP && !Double.isNaN(angle)) {
                // AnimationHelper.slerp with the constants of this pair of keys (see slerpAngles).
                double wa = sine((1 - u) * angle, fast) / Math.abs(slerpSines[k]);
                double wb = sine(u * angle, fast) / slerpSines[k];
                qx = (float) (wa * trs[a + 3] + wb * trs[b + 3]);
                qy = (float) (wa * trs[a + 4] + wb * trs[b + 4]);
                qz = (float) (wa * trs[a + 5] + wb * trs[b + 5]);
                qw = (float) (wa * trs[a + 6] + wb * trs[b + 6]);
            } else {
                Quaternionf q = AnimationHelper.interpolate(rotations,
                        pose.q1.set(trs[a + 3], trs[a + 4], trs[a + 5], trs[a + 6]),
                        pose.q2.set(trs[b + 3], trs[b + 4], trs[b + 5], trs[b + 6]), u, pose.q1);
                qx = q.x;
                qy = q.y;
                qz = q.z;
                qw = q.w;
            }
            AnimationHelper.composeRowMajor(lerp(trs[a], trs[b], u), lerp(trs[a + 1], trs[b + 1], u),
                    lerp(trs[a + 2], trs[b + 2], u), qx, qy, qz, qw, lerp(trs[a + 7], trs[b + 7], u),
                    lerp(trs[a + 8], trs[b + 8], u), lerp(trs[a + 9], trs[b + 9], u), dest, slot);
        }

        private static float lerp(float a, float b, float u) {
            return a + u * (b - a);
        }
    }

    /**
     * The value of the cubic Bezier with control points (x0,y0) .. (x3,y3) where its time
     * coordinate equals {@code x}: Newton's method on x(s), kept inside a shrinking bracket by
     * bisection so that control points which make x(s) non-monotonic still give an answer.
     */
    static double bezier(double x, double x0, double y0, double x1, double y1, double x2, double y2, double x3,
            double y3) {
        double lo = 0;
        double hi = 1;
        double s = x3 > x0 ? (x - x0) / (x3 - x0) : 0;
        for (int i = 0; i < 50; i++) {
            double f = cubic(s, x0, x1, x2, x3) - x;
            if (Math.abs(f) < 1e-9 * Math.max(1, Math.abs(x3 - x0))) {
                break;
            }
            if (f < 0) {
                lo = s;
            } else {
                hi = s;
            }
            double d = cubicDerivative(s, x0, x1, x2, x3);
            double next = d != 0 ? s - f / d : Double.NaN;
            s = next > lo && next < hi ? next : 0.5 * (lo + hi);
        }
        return cubic(s, y0, y1, y2, y3);
    }

    private static double cubic(double s, double p0, double p1, double p2, double p3) {
        double r = 1 - s;
        return r * r * r * p0 + 3 * r * r * s * p1 + 3 * r * s * s * p2 + s * s * s * p3;
    }

    private static double cubicDerivative(double s, double p0, double p1, double p2, double p3) {
        double r = 1 - s;
        return 3 * r * r * (p1 - p0) + 6 * r * s * (p2 - p1) + 3 * s * s * (p3 - p2);
    }
}
