package org.skinlab.simulation;

import java.util.concurrent.atomic.AtomicInteger;

import org.skinlab.animation.RotationInterpolation;
import org.skinlab.skinning.JointPalette;
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
 *         uploadPalette(frame.skinningMatrices(0)); // skin on the GPU
 *     }
 * }
 * }</pre>
 *
 * <p><b>The palette.</b> Per geometry {@code g}, {@link #jointCount(int) jointCount(g)} joints,
 * indexed as the geometry's influences index them
 * ({@link org.skinlab.skinning.SkinnedGeometry#jointArray()}), each with the data of
 * {@link JointPalette} for this step, in the same layouts:
 * <ul>
 * <li>{@link #skinningMatrices(int)}: 12 floats per joint, a 3x4 affine matrix M stored by rows
 *     {@code r00 r01 r02 tx, r10 r11 r12 ty, r20 r21 r22 tz}; it takes a point in bind space (the
 *     geometry's {@link org.skinlab.skinning.SkinnedGeometry#positionArray()} and
 *     {@link org.skinlab.skinning.SkinnedGeometry#normalArray()}, not the file's mesh positions:
 *     the bind shape matrix, and a mirror common to all bind frames, are already applied there)
 *     to its posed place, {@code p' = M (p, 1)}. LBS: {@code p' = (sum_k w_k M_(j_k)) (p, 1)},
 *     the normal by the inverse transpose of the blend's 3x3 part (the cofactor matrix, times
 *     the sign of its determinant when a joint mirrors). In GLSL, 12 floats per joint uploaded
 *     as-is to a {@code mat3x4} (three columns of four: the columns are our rows) apply as
 *     {@code vec4(p, 1.0) * m}.</li>
 * <li>{@link #dualQuaternions(int)}: 8 floats per joint, the unit dual quaternion {@code r + e d}
 *     of the joint's rigid part D: the rotation r as {@code x y z w}, then the dual part d as
 *     {@code x y z w}, with {@code d = (t, 0) r / 2} for the translation t, so
 *     {@code t = 2 (r.w d.xyz - d.w r.xyz + cross(r.xyz, d.xyz))}. DQS (Kavan et al. 2008):
 *     {@code b = sum_k s_k w_k q_(j_k)} with {@code s_k = sign(dot(r_(j_0), r_(j_k)))} against
 *     the dominant influence j_0 (the first: influences are sorted by decreasing weight), divide
 *     both parts of b by {@code |b.r|}, rotate the point by b's r and add b's t; the normal is
 *     only rotated. Filled in every frame, whatever {@link #method()} says.</li>
 * <li>{@link #scales(int)}: 12 floats per joint, row-major 3x4 like the matrices: the joint's
 *     scale/shear part S, with {@code M = D S}, centred on the joint's bind frame (so it may
 *     have a translation column); the identity for a joint without scale. DQS with scale runs a
 *     first phase before the dual quaternions: {@code p1 = (sum_k w_k S_(j_k)) (p, 1)} (a plain
 *     weighted sum, no sign flips), the normal by the inverse transpose of that blend's 3x3
 *     part, then the blended dual quaternion moves p1 and turns the normal. When
 *     {@link #hasScale(int) hasScale(g)} is false every S is the identity and a shader may
 *     skip the phase (a uniform flag).</li>
 * <li>{@link #boneRows(int)}: {@link JointPalette#BONE_FLOATS} floats per joint, six rows of four
 *     (posed head | twist, posed tail | stretch, the tail's stretch offset, the posed bone axis,
 *     rest head | length, rest tail | parent index; {@link JointPalette#boneRows()} defines them):
 *     what the methods that read bones ({@link SkinningMethod#usesBones()}) take of this step.
 *     Filled in every frame, whatever {@link #method()} says, as the dual quaternions are. A
 *     shader reads them as {@code boneRow(joint, row)} (skinning.glsl's header).</li>
 * </ul>
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
    private final float[][] matrices;
    private final float[][] dualQuaternions;
    private final float[][] scales;
    private final float[][] boneRows;
    private final boolean[] scaled;
    private final boolean[] matricesMirror;
    private final boolean[] scalesMirror;
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

    /**
     * @param pointCounts points per geometry
     * @param jointCounts palette joints per geometry
     * @param morphing    per geometry, whether its rest shape morphs (animated morph weights)
     */
    Frame(int[] pointCounts, int[] jointCounts, boolean[] morphing) {
        int n = pointCounts.length;
        if (jointCounts.length != n || morphing.length != n) {
            throw new IllegalArgumentException(n + " point counts but " + jointCounts.length + " joint counts and "
                    + morphing.length + " morph flags");
        }
        restPositions = new float[n][];
        restNormals = new float[n][];
        positions = new float[n][];
        normals = new float[n][];
        matrices = new float[n][];
        dualQuaternions = new float[n][];
        scales = new float[n][];
        boneRows = new float[n][];
        scaled = new boolean[n];
        matricesMirror = new boolean[n];
        scalesMirror = new boolean[n];
        for (int g = 0; g < n; g++) {
            positions[g] = new float[3 * pointCounts[g]];
            normals[g] = new float[3 * pointCounts[g]];
            matrices[g] = new float[12 * jointCounts[g]];
            dualQuaternions[g] = new float[8 * jointCounts[g]];
            scales[g] = new float[12 * jointCounts[g]];
            boneRows[g] = new float[JointPalette.BONE_FLOATS * jointCounts[g]];
            restPositions[g] = morphing[g] ? new float[3 * pointCounts[g]] : null;
            restNormals[g] = morphing[g] ? new float[3 * pointCounts[g]] : null;
        }
    }

    /** The writer's arrays for geometry {@code g} (simulation side only). */
    float[] positionsForWriting(int g) {
        return positions[g];
    }

    float[] normalsForWriting(int g) {
        return normals[g];
    }

    /**
     * Copies geometry {@code g}'s palette (its dual quaternions and bone rows prepared) into this
     * buffer (simulation side only).
     */
    void copyPalette(int g, JointPalette palette) {
        System.arraycopy(palette.matrices(), 0, matrices[g], 0, matrices[g].length);
        System.arraycopy(palette.boneRows(), 0, boneRows[g], 0, boneRows[g].length);
        System.arraycopy(palette.dualQuaternions(), 0, dualQuaternions[g], 0, dualQuaternions[g].length);
        System.arraycopy(palette.scales(), 0, scales[g], 0, scales[g].length);
        scaled[g] = palette.hasScale();
        matricesMirror[g] = palette.mirrorsMatrices();
        scalesMirror[g] = palette.mirrorsScales();
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
     */
    public float[] restPositions(int g) {
        return restPositions[g];
    }

    /**
     * The rest normals that go with {@link #restPositions(int)} (morphed too when the morph morphs
     * normals, else the geometry's), 3 floats per point; null where the rest shape does not morph.
     * Read-only.
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

    /** Number of geometries, in {@link SkeletalAnimatedMesh#geometries()} order. */
    public int geometryCount() {
        return positions.length;
    }

    /**
     * Whether this step skinned the mesh on the CPU: false for a frame published with
     * {@link AnimationConfig#setCpuSkinning CPU skinning} off, which carries only the palette.
     */
    public boolean hasSkinnedMesh() {
        return skinnedMesh;
    }

    /**
     * Deformed positions of geometry {@code g}: 3 floats per point, in the point order of its
     * {@link org.skinlab.skinning.SkinnedGeometry}. Read-only.
     *
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

    /** Palette joints of geometry {@code g} (skin joints, plus the bind-shape pseudo-joint when used). */
    public int jointCount(int g) {
        return matrices[g].length / 12;
    }

    /**
     * Skinning matrices of geometry {@code g} in this step: 12 floats per joint, a row-major 3x4
     * affine matrix (see the class comment). Read-only.
     */
    public float[] skinningMatrices(int g) {
        return matrices[g];
    }

    /**
     * Dual quaternions of geometry {@code g}'s joints in this step: 8 floats per joint, real part
     * x y z w then dual part x y z w (see the class comment). Filled whatever the method. Read-only.
     */
    public float[] dualQuaternions(int g) {
        return dualQuaternions[g];
    }

    /**
     * Scale/shear parts of geometry {@code g}'s joints in this step, for DQS: 12 floats per
     * joint, row-major 3x4, the identity for unscaled joints (see the class comment). Read-only.
     */
    public float[] scales(int g) {
        return scales[g];
    }

    /**
     * Bone rows of geometry {@code g}'s joints in this step, for the methods that read bones:
     * {@link JointPalette#BONE_FLOATS} floats per joint, six rows of four (see the class comment
     * and {@link JointPalette#boneRows()}). Filled whatever the method. Read-only.
     */
    public float[] boneRows(int g) {
        return boneRows[g];
    }

    /** Whether some joint of geometry {@code g} has a scale part in this step (DQS needs its first phase). */
    public boolean hasScale(int g) {
        return scaled[g];
    }

    /**
     * Whether some joint's skinning matrix of geometry {@code g} mirrors in this step
     * ({@link JointPalette#mirrorsMatrices()}): LBS's normals then carry the sign of the blend's
     * determinant, in the CPU kernels and so in a shader.
     */
    public boolean mirrorsMatrices(int g) {
        return matricesMirror[g];
    }

    /** As {@link #mirrorsMatrices(int)} for the scale parts ({@link JointPalette#mirrorsScales()}). */
    public boolean mirrorsScales(int g) {
        return scalesMirror[g];
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

    /**
     * The method the configuration asked for in this step: what every geometry was skinned with,
     * or, in a palette-only frame, what a GPU renderer should apply.
     */
    public SkinningMethod method() {
        return method;
    }

    /** The rotation interpolation the pose was sampled with. */
    public RotationInterpolation interpolation() {
        return interpolation;
    }

    /**
     * Wall time this step spent posing, preparing the palette and skinning (nanoseconds): the
     * thesis' "time per deformed mesh"; in a palette-only frame, posing and the palette alone.
     */
    public long skinningNanos() {
        return skinningNanos;
    }

    /**
     * The part of {@link #skinningNanos()} the skinning kernels took to deform the mesh (positions
     * and normals of every geometry): 0 in a palette-only frame. The rest posed the skeleton and
     * prepared the palette, which GPU skinning needs too.
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
