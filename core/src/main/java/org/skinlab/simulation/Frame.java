package org.skinlab.simulation;

import java.util.concurrent.atomic.AtomicInteger;

import org.skinlab.animation.RotationInterpolation;
import org.skinlab.skinning.SkinningMethod;

/**
 * One complete simulation step as published by a {@link SkeletalAnimatedMesh}: per geometry the
 * deformed positions and normals, and what produced them (sequence number, playback and clip time,
 * method, interpolation).
 *
 * <p>A frame is one of the mesh's reusable buffers, lent to a reader by
 * {@link SkeletalAnimatedMesh#acquire()} and given back with {@link #close()}: between the two its
 * contents never change, because the simulation only writes into buffers no reader holds (see
 * the mesh's class comment). The arrays are handed out without copying, so a renderer can upload
 * them straight to the GPU; readers must not modify them, and must not touch the frame after
 * closing it. Use try-with-resources:
 *
 * <pre>{@code
 * try (Frame frame = mesh.acquire()) {
 *     upload(frame.positions(0), frame.normals(0));
 * }
 * }</pre>
 */
public final class Frame implements AutoCloseable {
    private final float[][] positions;
    private final float[][] normals;
    /** Readers holding this buffer; the simulation writes only into buffers with none. */
    final AtomicInteger leases = new AtomicInteger();

    private long sequence = -1;
    private double playbackTime;
    private float clipTime;
    private SkinningMethod method;
    private RotationInterpolation interpolation;
    private long skinningNanos;

    Frame(int[] pointCounts) {
        positions = new float[pointCounts.length][];
        normals = new float[pointCounts.length][];
        for (int g = 0; g < pointCounts.length; g++) {
            positions[g] = new float[3 * pointCounts[g]];
            normals[g] = new float[3 * pointCounts[g]];
        }
    }

    /** The writer's arrays for geometry {@code g} (simulation side only). */
    float[] positionsForWriting(int g) {
        return positions[g];
    }

    float[] normalsForWriting(int g) {
        return normals[g];
    }

    void describe(long sequence, double playbackTime, float clipTime, SkinningMethod method,
            RotationInterpolation interpolation, long skinningNanos) {
        this.sequence = sequence;
        this.playbackTime = playbackTime;
        this.clipTime = clipTime;
        this.method = method;
        this.interpolation = interpolation;
        this.skinningNanos = skinningNanos;
    }

    /** Number of geometries, in {@link SkeletalAnimatedMesh#geometries()} order. */
    public int geometryCount() {
        return positions.length;
    }

    /**
     * Deformed positions of geometry {@code g}: 3 floats per point, in the point order of its
     * {@link org.skinlab.skinning.SkinnedGeometry}. Read-only.
     */
    public float[] positions(int g) {
        return positions[g];
    }

    /** Deformed normals of geometry {@code g}, 3 floats per point. Read-only. */
    public float[] normals(int g) {
        return normals[g];
    }

    /**
     * Publication number: 0 for the frame published when the mesh was built, then one more per
     * published step. A reader never sees it go down.
     */
    public long sequence() {
        return sequence;
    }

    /** Seconds of playback since the clip's start (after wrapping) this frame shows. */
    public double playbackTime() {
        return playbackTime;
    }

    /** The clip time (seconds, in the clip's own time line) the skeleton was posed at. */
    public float clipTime() {
        return clipTime;
    }

    /** The method every geometry of this frame was skinned with. */
    public SkinningMethod method() {
        return method;
    }

    /** The rotation interpolation the pose was sampled with. */
    public RotationInterpolation interpolation() {
        return interpolation;
    }

    /** Wall time this step spent posing and skinning (nanoseconds): the thesis' "time per deformed mesh". */
    public long skinningNanos() {
        return skinningNanos;
    }

    /**
     * Gives the frame back to the simulation. Each {@link SkeletalAnimatedMesh#acquire()} must be
     * matched by exactly one close.
     *
     * @throws IllegalStateException when the frame is closed more often than it was acquired
     */
    @Override
    public void close() {
        while (true) {
            int n = leases.get();
            if (n <= 0) {
                throw new IllegalStateException("frame " + sequence + " closed more often than acquired");
            }
            if (leases.compareAndSet(n, n - 1)) {
                return;
            }
        }
    }

    @Override
    public String toString() {
        return "Frame[" + sequence + ", clip time " + clipTime + ", " + method + ", " + interpolation + "]";
    }
}
