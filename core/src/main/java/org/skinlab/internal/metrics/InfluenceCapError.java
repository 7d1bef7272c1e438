package org.skinlab.internal.metrics;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import org.skinlab.animation.AnimationSampler;
import org.skinlab.animation.Pose;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.animation.Skeleton;
import org.skinlab.skinning.InfluenceView;
import org.skinlab.skinning.JointPalette;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.ScalarDqsSkinner;
import org.skinlab.skinning.ScalarLbsSkinner;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinnedModel;
import org.skinlab.skinning.Skinner;
import org.skinlab.skinning.SkinningMethod;

/**
 * How far an {@link InfluenceView}'s cap moves a model's positions over its clip: for each placed
 * geometry and cap {@code k}, the largest distance between a position skinned with all its
 * influences and skinned with the view's {@code k}, for LBS and for DQS, with where and when.
 *
 * <p><b>What is compared.</b> Every entry of the mesh's POSITION source (through
 * {@link SkinnedGeometry#pointOfPosition}), deformed by the scalar kernels (the same kernel for
 * both sides, so the difference is the cap's alone) with one palette per sample time: the
 * skinning matrices of {@link SkinnedModel#pose} with SLERP rotations, and for DQS the palette's
 * dual quaternions. A view that drops no weight (a cap at or above the geometry's influence
 * count, say) deforms exactly as the geometry, so it is not skinned and its error is 0.
 *
 * <p><b>When.</b> {@link #sampleTimes}: the clip's start and every {@code 1/}{@value #SAMPLES_PER_SECOND}
 * s after it before its end, then its end (a clip of zero length, or a model at rest: its start
 * only). Between samples the error is not looked at; 30 per second is a frame rate's worth.
 *
 * <p><b>Relative to what.</b> {@link Result#size()}: the diagonal of the axis-aligned bounding
 * box of the geometry's positions in the rest pose (every node's transforms as written in the
 * file, no clip applied, skinned with all influences), in the same world units as the distances.
 */
public final class InfluenceCapError {
    /** Sample times per second of clip. */
    public static final int SAMPLES_PER_SECOND = 30;

    private InfluenceCapError() {
    }

    /**
     * The largest distance one method's positions moved under the cap.
     *
     * @param distance the largest distance, in model (world) units
     * @param relative {@code distance / size}, NaN when the size is 0
     * @param position the POSITION entry that moved it, -1 when no position moved at all
     * @param time     the clip time (seconds) it happened at, NaN when no position moved
     */
    public record Worst(double distance, double relative, int position, float time) {
    }

    /**
     * One geometry under one cap.
     *
     * @param cap               influences kept per point
     * @param influences        the geometry's own influences per point
     * @param cappedPositions   POSITION entries that lose weight to the cap
     * @param maxDroppedWeight  the largest weight a position loses (before its kept weights are
     *                          renormalised; weights sum to 1)
     * @param size              the rest pose's bounding-box diagonal
     * @param samples           sample times looked at
     */
    public record Result(int cap, int influences, int cappedPositions, float maxDroppedWeight, double size, int samples,
            Worst lbs, Worst dqs) {
    }

    /**
     * The sample times of a clip from {@code start} to {@code end} seconds: {@code start + i / 30}
     * for every {@code i >= 0} whose time (as a float) is before {@code end}, then {@code end}.
     */
    public static float[] sampleTimes(float start, float end) {
        if (!(end > start)) {
            return new float[] {start};
        }
        int n = (int) Math.ceil(((double) end - start) * SAMPLES_PER_SECOND) + 1;
        float[] times = new float[n + 1];
        int count = 0;
        for (int i = 0; i < n; i++) {
            float t = (float) (start + (double) i / SAMPLES_PER_SECOND);
            if (t >= end) {
                break;
            }
            times[count++] = t;
        }
        times[count++] = end;
        return Arrays.copyOf(times, count);
    }

    /**
     * Measures every geometry of the model under each cap over the model's clip (the rest pose
     * alone when it has none). Leaves the model posed at the clip's end.
     *
     * @return per geometry ({@link SkinnedModel#geometries()} order) one result per cap, in the
     *         order given
     */
    public static List<List<Result>> measure(SkinnedModel model, int... caps) {
        List<SkinnedGeometry> geometries = model.geometries();
        int n = geometries.size();
        Side[] full = new Side[n];
        Capped[][] capped = new Capped[n][caps.length];
        double[] sizes = new double[n];
        Pose rest = model.skeleton().newPose();
        for (int g = 0; g < n; g++) {
            SkinnedGeometry geometry = geometries.get(g);
            full[g] = new Side(geometry);
            sizes[g] = restDiagonal(model.skeleton(), rest, geometry, full[g]);
            for (int c = 0; c < caps.length; c++) {
                capped[g][c] = new Capped(geometry, InfluenceView.of(geometry, caps[c]));
            }
        }
        AnimationSampler sampler = model.sampler();
        float[] times = sampleTimes(sampler.start(), sampler.end());
        for (float t : times) {
            model.pose(t, RotationInterpolation.SLERP);
            for (int g = 0; g < n; g++) {
                if (!anyInexact(capped[g])) {
                    continue;
                }
                JointPalette palette = model.palette(g);
                for (int m = 0; m < 2; m++) {
                    if (m == 1) {
                        palette.prepare(SkinningMethod.DQS);
                    }
                    full[g].skin(m, palette);
                    for (Capped c : capped[g]) {
                        if (c.side != null) {
                            c.side.skin(m, palette);
                            c.compare(m, geometries.get(g), full[g].positions, t);
                        }
                    }
                }
            }
        }
        List<List<Result>> results = new ArrayList<>(n);
        for (int g = 0; g < n; g++) {
            List<Result> perCap = new ArrayList<>(caps.length);
            SkinnedGeometry geometry = geometries.get(g);
            for (Capped c : capped[g]) {
                int cappedPositions = 0;
                float maxDropped = 0f;
                for (int p = 0; p < geometry.positionCount(); p++) {
                    float dropped = c.view.droppedWeight(geometry.pointOfPosition(p));
                    cappedPositions += dropped != 0f ? 1 : 0;
                    maxDropped = Math.max(maxDropped, dropped);
                }
                perCap.add(new Result(c.view.influencesPerPoint(), c.view.sourceInfluencesPerPoint(), cappedPositions,
                        maxDropped, sizes[g], times.length, c.worst(0, sizes[g]), c.worst(1, sizes[g])));
            }
            results.add(List.copyOf(perCap));
        }
        return List.copyOf(results);
    }

    private static boolean anyInexact(Capped[] caps) {
        for (Capped c : caps) {
            if (c.side != null) {
                return true;
            }
        }
        return false;
    }

    /** The diagonal of the bounding box of a geometry's positions in the rest pose. */
    private static double restDiagonal(Skeleton skeleton, Pose rest, SkinnedGeometry geometry, Side full) {
        JointPalette palette = geometry.newPalette();
        skeleton.skinningMatrices(rest, geometry.jointNodeArray(), geometry.bindMatrixArray(), palette.writableMatrices());
        full.skin(0, palette);
        double[] min = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY};
        double[] max = {Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
        for (int p = 0; p < geometry.positionCount(); p++) {
            int v = 3 * geometry.pointOfPosition(p);
            for (int a = 0; a < 3; a++) {
                min[a] = Math.min(min[a], full.positions[v + a]);
                max[a] = Math.max(max[a], full.positions[v + a]);
            }
        }
        double sum = 0;
        for (int a = 0; a < 3; a++) {
            double e = max[a] - min[a];
            sum += e * e;
        }
        return geometry.positionCount() == 0 ? 0 : Math.sqrt(sum);
    }

    /** One geometry with its two scalar skinners, positions only, and their output array. */
    private static final class Side {
        final Skinner[] skinners;
        final float[] positions;

        Side(SkinnedGeometry geometry) {
            // The per-point scalar kernels on both sides (never the shared-position route, which
            // the capped side, built from arrays, cannot take): equal inputs give equal bits.
            skinners = new Skinner[] {
                new ScalarLbsSkinner(geometry, NormalTransform.NONE),
                new ScalarDqsSkinner(geometry, NormalTransform.NONE)};
            positions = new float[3 * geometry.pointCount()];
        }

        /** Method 0 LBS, 1 DQS (the palette's dual quaternions prepared). */
        void skin(int method, JointPalette palette) {
            skinners[method].skinAll(palette, positions, null);
        }
    }

    /**
     * One cap of one geometry: its view, its skinners (none when the view drops no weight: its
     * weights are then the geometry's bit for bit and its other slots weigh 0, so it deforms
     * exactly as the geometry and there is nothing to measure), and the worst so far per method.
     */
    private static final class Capped {
        final InfluenceView view;
        final Side side;
        final double[] distance = new double[2];
        final int[] position = {-1, -1};
        final float[] time = {Float.NaN, Float.NaN};

        Capped(SkinnedGeometry geometry, InfluenceView view) {
            this.view = view;
            this.side = view.cappedPointCount() == 0 ? null
                    : new Side(SkinnedGeometry.fromArrays(geometry.positionArray(), geometry.normalArray(),
                            view.influencesPerPoint(), view.jointIndicesAsInts(), view.weights(),
                            geometry.bindMatrixArray()));
        }

        /** Compares this side's positions with the full ones, position by position. */
        void compare(int method, SkinnedGeometry geometry, float[] full, float t) {
            float[] capped = side.positions;
            for (int p = 0; p < geometry.positionCount(); p++) {
                int v = 3 * geometry.pointOfPosition(p);
                double dx = (double) full[v] - capped[v];
                double dy = (double) full[v + 1] - capped[v + 1];
                double dz = (double) full[v + 2] - capped[v + 2];
                double d = Math.sqrt(dx * dx + dy * dy + dz * dz);
                if (d > distance[method]) {
                    distance[method] = d;
                    position[method] = p;
                    time[method] = t;
                }
            }
        }

        Worst worst(int method, double size) {
            double d = distance[method];
            return new Worst(d, size > 0 ? d / size : Double.NaN, position[method], time[method]);
        }
    }
}
