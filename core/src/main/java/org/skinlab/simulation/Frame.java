package org.skinlab.simulation;

import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;

import org.joml.Matrix4f;

import org.skinlab.animation.RotationInterpolation;
import org.skinlab.skinning.JointPalette;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinningMethod;

/**
 * One complete simulation step as published by a {@link SkeletalAnimatedMesh}: per geometry the
 * joint palette the step posed (for skinning on the GPU) and, unless the step was palette-only,
 * the deformed positions and normals; and what produced them (sequence number, playback and clip
 * time, method, interpolation).
 *
 * <p>A frame is one of the mesh's reusable buffers, lent to a reader by
 * {@link SkeletalAnimatedMesh#acquire()} and given back with {@link #close()}: between the two its
 * contents never change, because the simulation only writes into buffers no reader holds (see
 * the mesh's class comment). Palette, mesh and description are written in the same step, so a
 * renderer may skin on the GPU from the palette, draw the CPU-skinned mesh, or both side by side,
 * and always shows one time step. The arrays are handed out without copying, so a renderer can
 * upload them straight to the GPU; readers must not modify them, and must not touch the frame
 * after closing it. Use try-with-resources:
 *
 * <pre>{@code
 * try (Frame frame = mesh.acquire()) {
 *     if (frame.hasSkinnedMesh()) {
 *         upload(frame.positions(0), frame.normals(0));
 *     } else {
 *         uploadPalette(frame.palette(0).matrices()); // skin on the GPU
 *     }
 * }
 * }</pre>
 *
 * <p><b>The palette.</b> Per geometry {@code g}, {@link #palette(int) palette(g)}: the
 * {@link JointPalette} this step posed, with everything it can derive prepared
 * ({@link JointPalette#prepareAll()}): the skinning matrices, the dual quaternions and scale parts,
 * and the bone rows, whatever {@link #method()} says, so a split view may draw two methods from one
 * frame. Its joints are indexed as the geometry's influences index them
 * ({@link org.skinlab.skinning.SkinnedGeometry#jointArray()}); each array's layout is on its
 * getter in {@link JointPalette}, and docs/skinning.md shows how a shader reads them. The
 * matrices take a point in bind space (the geometry's
 * {@link org.skinlab.skinning.SkinnedGeometry#positionArray()}, not the file's mesh positions:
 * the bind shape matrix, and a mirror common to all bind frames, are already applied there) to
 * its posed place. The palette is read-only, like the arrays.
 *
 * <p><b>Palette-only frames.</b> With {@link AnimationConfig#setCpuSkinning} off, a step poses
 * the skeleton and fills the palette but skins nothing; its frame says so with
 * {@link #hasSkinnedMesh()} false, and {@link #positions(int)} and {@link #normals(int)} refuse
 * rather than hand out another step's mesh left in the reused buffer. A method the shaders have
 * no code for ({@link org.skinlab.skinning.SkinningGlsl#hasCode}) is skinned on the CPU even then,
 * so its frames carry the mesh ({@link #hasSkinnedMesh()} true) and a renderer draws them as they
 * are.
 */
public final class Frame implements AutoCloseable {
    private final float[][] positions;
    private final float[][] normals;
    private final JointPalette[] palettes;
    /** Per geometry, the morphed rest positions of this step, or null where the rest shape does not morph. */
    private final float[][] restPositions;
    /** Per geometry, the rest normals that go with them, or null likewise. */
    private final float[][] restNormals;
    /** Readers holding this buffer; the simulation writes only into buffers with none. */
    final AtomicInteger leases = new AtomicInteger();

    private long sequence = -1;
    private double playbackTime;
    private float clipTime;
    private SkinningMethod method;
    private RotationInterpolation interpolation;
    private long skinningNanos;
    private long meshSkinningNanos;
    private boolean skinnedMesh;
    /** Root motion's placement of the model, column-major. */
    private final float[] placement = new float[16];

    /**
     * @param geometries the geometries, for their point counts and palettes
     * @param morphing   per geometry, whether its rest shape morphs (animated morph weights)
     */
    Frame(List<SkinnedGeometry> geometries, boolean[] morphing) {
        int n = geometries.size();
        if (morphing.length != n) {
            throw new IllegalArgumentException(n + " geometries but " + morphing.length + " morph flags");
        }
        restPositions = new float[n][];
        restNormals = new float[n][];
        positions = new float[n][];
        normals = new float[n][];
        palettes = new JointPalette[n];
        for (int g = 0; g < n; g++) {
            SkinnedGeometry geometry = geometries.get(g);
            int points = geometry.pointCount();
            positions[g] = new float[3 * points];
            normals[g] = new float[3 * points];
            palettes[g] = geometry.newPalette();
            restPositions[g] = morphing[g] ? new float[3 * points] : null;
            restNormals[g] = morphing[g] ? new float[3 * points] : null;
        }
    }

    /** The writer's arrays for geometry {@code g} (simulation side only). */
    float[] positionsForWriting(int g) {
        return positions[g];
    }

    float[] normalsForWriting(int g) {
        return normals[g];
    }

    /** Copies geometry {@code g}'s palette, everything prepared, into this buffer (simulation side only). */
    void copyPalette(int g, JointPalette palette) {
        palettes[g].set(palette);
    }

    /** Copies geometry {@code g}'s morphed rest positions and normals of this step (simulation side only). */
    void copyRestShape(int g, float[] positions, float[] normals) {
        System.arraycopy(positions, 0, restPositions[g], 0, restPositions[g].length);
        System.arraycopy(normals, 0, restNormals[g], 0, restNormals[g].length);
    }

    /**
     * The rest positions geometry {@code g}'s palette applies to in this step, 3 floats per point
     * in bind space, when its morph weights animate: the base morphed with this step's weights,
     * which a GPU skinner uploads in place of the bind positions. Null for a geometry whose rest
     * shape does not morph (its {@link org.skinlab.skinning.SkinnedGeometry#positionArray()}
     * never changes). Read-only.
     *
     * @param g the geometry, an index in [0, {@link #geometryCount()})
     * @return the morphed rest positions (3 × the geometry's point count floats, x y z per point),
     *         not a copy; or null when the geometry's rest shape does not morph
     */
    public float[] restPositions(int g) {
        return restPositions[g];
    }

    /**
     * The rest normals that go with {@link #restPositions(int)} (morphed too when the morph morphs
     * normals, else the geometry's), 3 floats per point; null where the rest shape does not morph.
     * Read-only.
     *
     * @param g the geometry, an index in [0, {@link #geometryCount()})
     * @return the rest normals (3 floats per point, as the positions), not a copy; or null when
     *         {@link #restPositions(int)} is null
     */
    public float[] restNormals(int g) {
        return restNormals[g];
    }

    void describe(long sequence, double playbackTime, float clipTime, SkinningMethod method,
            RotationInterpolation interpolation, boolean skinnedMesh, long skinningNanos, long meshSkinningNanos) {
        this.sequence = sequence;
        this.playbackTime = playbackTime;
        this.clipTime = clipTime;
        this.method = method;
        this.interpolation = interpolation;
        this.skinnedMesh = skinnedMesh;
        this.skinningNanos = skinningNanos;
        this.meshSkinningNanos = meshSkinningNanos;
    }

    void setPlacement(Matrix4f m) {
        m.get(placement);
    }

    /**
     * Where root motion has taken the model ({@link org.skinlab.mixer.Mixer#placement}): the
     * renderer multiplies the model matrix by it on the right. The identity while no clip with
     * root motion has played.
     *
     * @param dest receives the placement, in the model's space
     * @return {@code dest}
     */
    public Matrix4f placement(Matrix4f dest) {
        return dest.set(placement);
    }

    /**
     * Number of geometries, in {@link SkeletalAnimatedMesh#geometries()} order.
     *
     * @return the geometry count, the same for every frame of a mesh
     */
    public int geometryCount() {
        return positions.length;
    }

    /**
     * Whether this step skinned the mesh on the CPU: false for a frame published with
     * {@link AnimationConfig#setCpuSkinning CPU skinning} off, which carries only the palette.
     *
     * @return true when {@link #positions(int)} and {@link #normals(int)} may be read, false for a
     *         palette-only frame
     */
    public boolean hasSkinnedMesh() {
        return skinnedMesh;
    }

    /**
     * Deformed positions of geometry {@code g}: 3 floats per point, in the point order of its
     * {@link org.skinlab.skinning.SkinnedGeometry}. Read-only.
     *
     * @param g the geometry, an index in [0, {@link #geometryCount()})
     * @return the posed positions (3 × the geometry's point count floats, x y z per point), where
     *         this step's palette puts the bind-space points; the frame's own buffer, not a copy
     * @throws IllegalStateException for a palette-only frame ({@link #hasSkinnedMesh()} false):
     *                               its buffer holds some earlier step's mesh, if any
     */
    public float[] positions(int g) {
        requireSkinnedMesh("positions");
        return positions[g];
    }

    /**
     * Deformed normals of geometry {@code g}, 3 floats per point. Read-only.
     *
     * @param g the geometry, an index in [0, {@link #geometryCount()})
     * @return the posed normals (3 floats per point, in the order of {@link #positions(int)}); the
     *         frame's own buffer, not a copy
     * @throws IllegalStateException for a palette-only frame, as {@link #positions(int)}
     */
    public float[] normals(int g) {
        requireSkinnedMesh("normals");
        return normals[g];
    }

    private void requireSkinnedMesh(String what) {
        if (!skinnedMesh) {
            throw new IllegalStateException("frame " + sequence + " has no " + what
                    + ": it was published with CPU skinning off (palette only); skin on the GPU from its palette,"
                    + " or turn AnimationConfig.setCpuSkinning on");
        }
    }

    /**
     * The joint palette of geometry {@code g} in this step, everything prepared (see the class
     * comment). Read-only.
     *
     * @param g the geometry
     * @return its palette
     */
    public JointPalette palette(int g) {
        return palettes[g];
    }

    /**
     * Publication number: 0 for the frame published when the mesh was built, then one more per
     * published step. A reader never sees it go down.
     *
     * @return the sequence number, 0 or more ({@link SkeletalAnimatedMesh#latestSequence()} for the latest)
     */
    public long sequence() {
        return sequence;
    }

    /**
     * Seconds of playback since the clip's start (after wrapping) this frame shows.
     *
     * @return the playback time in seconds: in [0, duration) when looping, [0, duration] when
     *         clamped, 0 without a clip
     */
    public double playbackTime() {
        return playbackTime;
    }

    /**
     * The clip time (seconds, in the clip's own time line) the skeleton was posed at.
     *
     * @return the clip time in seconds, between the clip's start and end; in a frame showing the
     *         bind pose ({@link AnimationConfig#setBindPose}), the time the clip is at underneath
     */
    public float clipTime() {
        return clipTime;
    }

    /**
     * The method the configuration asked for in this step: what every geometry was skinned with,
     * or, in a palette-only frame, what a GPU renderer should apply.
     *
     * @return the method, never null
     */
    public SkinningMethod method() {
        return method;
    }

    /**
     * The rotation interpolation the pose was sampled with.
     *
     * @return the interpolation, never null
     */
    public RotationInterpolation interpolation() {
        return interpolation;
    }

    /**
     * Wall time this step spent posing, preparing the palette and skinning (nanoseconds): the
     * thesis' "time per deformed mesh"; in a palette-only frame, posing and the palette alone.
     *
     * @return the step's time in nanoseconds ({@link System#nanoTime()} differences)
     */
    public long skinningNanos() {
        return skinningNanos;
    }

    /**
     * The part of {@link #skinningNanos()} the skinning kernels took to deform the mesh (positions
     * and normals of every geometry): 0 in a palette-only frame. The rest posed the skeleton and
     * prepared the palette, which GPU skinning needs too.
     *
     * @return the skinning kernels' time in nanoseconds, at most {@link #skinningNanos()}
     */
    public long meshSkinningNanos() {
        return meshSkinningNanos;
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
        return "Frame[" + sequence + ", clip time " + clipTime + ", " + method + ", " + interpolation
                + (skinnedMesh ? "" : ", palette only") + "]";
    }
}
