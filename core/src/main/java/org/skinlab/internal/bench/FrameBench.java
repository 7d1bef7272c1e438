package org.skinlab.internal.bench;

import java.util.Arrays;
import java.util.EnumSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

import org.skinlab.animation.RotationInterpolation;
import org.skinlab.animation.WrapMode;
import org.skinlab.model.Model;
import org.skinlab.skinning.InfluenceView;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.PositionSharing;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinnedModel;
import org.skinlab.skinning.Skinner;
import org.skinlab.skinning.Skinners;
import org.skinlab.skinning.SkinningMethod;

/**
 * One character's frame, end to end on the CPU, timed for {@code skinlab bench frame}: sample the
 * first clip (slerp), evaluate the skeleton, compute every geometry's skinning matrices (and, for
 * DQS, its dual quaternions), and skin every placed mesh, positions and normals, on one thread.
 * Each frame advances the clip by 1/60 s (looping), so the sampler's key search moves as it does
 * when playing. Warm-up (the platform's {@link Warmup}), then timed frames for a given time (at
 * least 5). The desktop's {@code bench frame} and {@code eval} and the Android app's measurement
 * run this same frame.
 */
public final class FrameBench {
    /** What one frame deforms, summed over the placed meshes (influences: the most per position). */
    public record Shape(int positionsSkinned, int renderVertices, int joints, int influences) {
    }

    /** One method's frames: the kernels that ran and the time per frame in microseconds. */
    public record Timing(SkinningMethod method, String kernel, int frames, double minMicros, double medianMicros) {
    }

    private final SkinnedModel skinned;
    /** Per geometry and method, the skinner this bench runs (its own choice of position sharing). */
    private final Skinner[][] skinners;
    private final float[][] positions;
    private final float[][] normals;
    private final Shape shape;
    private final Warmup warmup;
    /** Per method (by ordinal): whether it has been warmed up by {@link #warmup} in this bench. */
    private final boolean[] compiled = new boolean[SkinningMethod.values().length];

    /** A bench of {@code methods} (their skinners made here, the others never), warmed up by {@code warmup}. */
    public FrameBench(Model model, NormalTransform rule, PositionSharing sharing, List<SkinningMethod> methods,
            Warmup warmup) {
        this(model, rule, sharing, false, 0, methods, warmup);
    }

    /**
     * As above; {@code scalar}: core's scalar kernels instead of the fastest available;
     * {@code influenceCap} above 0: each geometry with more influences per point than that cut to
     * its heaviest ones, renormalised ({@link InfluenceView}, what a GPU's fixed slots see).
     */
    public FrameBench(Model model, NormalTransform rule, PositionSharing sharing, boolean scalar, int influenceCap,
            List<SkinningMethod> methods, Warmup warmup) {
        this.warmup = warmup;
        skinned = new SkinnedModel(model, model.clips().isEmpty() ? null : model.clips().get(0), rule,
                EnumSet.copyOf(methods));
        int n = skinned.geometries().size();
        skinners = new Skinner[n][SkinningMethod.values().length];
        SkinnedGeometry[] used = new SkinnedGeometry[n];
        for (int g = 0; g < n; g++) {
            SkinnedGeometry original = skinned.geometries().get(g);
            used[g] = capped(original, influenceCap);
            for (SkinningMethod m : methods) {
                skinners[g][m.ordinal()] = scalar ? Skinners.scalar(m, used[g], rule)
                        : sharing == PositionSharing.AUTO && used[g] == original ? skinned.skinner(g, m)
                        : Skinners.create(m, used[g], rule, sharing);
            }
        }
        positions = new float[n][];
        normals = new float[n][];
        int skinnedPositions = 0;
        int vertices = 0;
        int joints = 0;
        int influences = 0;
        for (int g = 0; g < n; g++) {
            SkinnedGeometry geometry = used[g];
            positions[g] = new float[outputFloats(geometry)];
            normals[g] = new float[outputFloats(geometry)];
            skinnedPositions += positionsSkinned(geometry, skinners[g]);
            vertices += geometry.vertexCount();
            joints += geometry.jointCount();
            influences = Math.max(influences, geometry.influencesPerPoint());
        }
        shape = new Shape(skinnedPositions, vertices, joints, influences);
    }

    /** The geometry with at most {@code cap} influences per point (itself when it has no more, or cap is 0). */
    private static SkinnedGeometry capped(SkinnedGeometry geometry, int cap) {
        if (cap <= 0 || geometry.influencesPerPoint() <= cap) {
            return geometry;
        }
        InfluenceView view = InfluenceView.of(geometry, cap);
        // The joints keep their hierarchy: the bone methods' bones are the frame's.
        int[] parents = new int[geometry.jointCount()];
        for (int j = 0; j < parents.length; j++) {
            parents[j] = geometry.jointParent(j);
        }
        SkinnedGeometry capped = SkinnedGeometry.fromArrays(geometry.positionArray(), geometry.normalArray(),
                view.influencesPerPoint(), view.jointIndicesAsInts(), view.weights(), geometry.bindMatrixArray(), parents);
        // CoR keeps the mesh's centres: the capped arrays have no triangles to integrate over.
        return geometry.hasCentresOfRotation() ? capped.withCentresOfRotation(geometry.centresOfRotation()) : capped;
    }

    /**
     * How many points one frame of this geometry deforms with the joints' blend: its positions when
     * a method's skinner skins each position once (then the render vertices are derived from them),
     * otherwise every point (render vertices, then unused positions).
     */
    static int positionsSkinned(SkinnedGeometry geometry, Skinner[] skinners) {
        for (Skinner s : skinners) {
            if (s != null && Skinners.sharesPositions(s)) {
                return geometry.sharedPositions().pointCount();
            }
        }
        return geometry.pointCount();
    }

    /** The floats of each output array of {@link SkinnedModel#skin}. */
    private static int outputFloats(SkinnedGeometry geometry) {
        return 3 * geometry.pointCount();
    }

    public Shape shape() {
        return shape;
    }

    /**
     * The kernels the geometries use for a method ({@code Skinner.implementation()}), each named
     * once in the order of the geometries and joined by '+' (a SIMD kernel may decline a geometry);
     * "none" without geometries.
     */
    public String kernel(SkinningMethod method) {
        Set<String> names = new LinkedHashSet<>();
        for (int g = 0; g < positions.length; g++) {
            names.add(skinners[g][method.ordinal()].implementation());
        }
        return names.isEmpty() ? "none" : String.join("+", names);
    }

    /**
     * Warms up for at least {@code warmupSeconds} (the first time per method as long as the bench's
     * {@link Warmup} waits beyond: what the compiler has to do is done once; a later warm-up only
     * brings the method's data back into the caches), then times frames for {@code seconds} (at
     * least 5 frames).
     */
    public Timing measure(SkinningMethod method, double warmupSeconds, double seconds) {
        long[] counter = {0};
        (compiled[method.ordinal()] ? Warmup.FOR_TIME : warmup).run(() -> step(method, counter[0]++), warmupSeconds);
        compiled[method.ordinal()] = true;
        long frame = counter[0];
        double[] micros = new double[1024];
        int n = 0;
        long end = System.nanoTime() + (long) (seconds * 1e9);
        while (n < 5 || System.nanoTime() < end) {
            long t0 = System.nanoTime();
            step(method, frame++);
            long t1 = System.nanoTime();
            if (n == micros.length) {
                micros = Arrays.copyOf(micros, 2 * n);
            }
            micros[n++] = (t1 - t0) / 1e3;
        }
        double[] sorted = Arrays.copyOf(micros, n);
        Arrays.sort(sorted);
        return new Timing(method, kernel(method), n, sorted[0], sorted[n / 2]);
    }

    private void step(SkinningMethod method, long frame) {
        frame(skinned, skinners, method, frame / 60.0, positions, normals);
    }

    /**
     * One character's frame (what this bench and the desktop's crowd bench time): sample its clip at
     * {@code elapsed} seconds of playback (looping), pose, and skin each geometry {@code g} with
     * {@code skinners[g][method.ordinal()]} into {@code positions[g]} and {@code normals[g]}.
     */
    public static void frame(SkinnedModel skinned, Skinner[][] skinners, SkinningMethod method, double elapsed,
            float[][] positions, float[][] normals) {
        float t = skinned.sampler().clipTime(elapsed, WrapMode.LOOP);
        skinned.pose(t, RotationInterpolation.SLERP);
        for (int g = 0; g < positions.length; g++) {
            // What the method reads: the dual quaternions (all but LBS), the bone rows (the bone methods).
            skinners[g][method.ordinal()].skinAll(skinned.palette(g).prepare(method), positions[g], normals[g]);
        }
    }
}
