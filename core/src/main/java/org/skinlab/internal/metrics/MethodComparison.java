package org.skinlab.internal.metrics;

import org.joml.Matrix4f;
import org.skinlab.animation.AnimationHelper;
import org.skinlab.skinning.JointPalette;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.Skinner;
import org.skinlab.skinning.Skinners;
import org.skinlab.skinning.SkinningMethod;

/**
 * LBS and DQS side by side on one part of a model in one pose: where the two methods place each
 * point apart, the largest distance relative to the model's size, and the volume each keeps (for
 * a part that is closed by itself). Both against the model's {@link RestPose}: the size is the
 * whole placed model's in the document's units, the distances' units; the volume is the part's
 * own rest volume measured by the same kernel in the same space. What the desktop's difference
 * view colours and prints (summed over the parts by {@link RestPose#relativeVolume(float[][])}).
 *
 * <p>The pose comes as the skinning matrices a {@code Frame} carries (12 floats per joint,
 * row-major 3x4); the dual quaternions and scale parts are derived from them by the same
 * {@link JointPalette} code the simulation uses, so both methods run exactly as the simulation
 * would run them. Both skins use core's scalar kernels ({@link Skinners#scalar}). One instance per part;
 * {@link #compare} allocates nothing; not thread-safe.
 */
public final class MethodComparison {
    private final RestPose rest;
    private final int part;
    private final SkinnedGeometry geometry;
    private final JointPalette palette;
    private final Skinner lbs;
    private final Skinner dqs;
    private final float[] lbsPositions;
    private final float[] dqsPositions;
    private final float[] normals;
    private final float[] distances;
    private final Matrix4f matrix = new Matrix4f();
    private double maxDistance;
    private double lbsVolume = Double.NaN;
    private double dqsVolume = Double.NaN;

    /** Compares part {@code part} (a {@link RestPose#geometries()} index) of the model at rest in {@code rest}. */
    public MethodComparison(RestPose rest, int part) {
        this.rest = rest;
        this.part = part;
        this.geometry = rest.geometries().get(part);
        palette = geometry.newPalette();
        // Core's scalar kernels: a probe that runs a few times a second never gets the JIT to
        // compile SIMD kernels (which allocate until it has), and needs no threads.
        lbs = Skinners.scalar(SkinningMethod.LBS, geometry, NormalTransform.INVERSE_TRANSPOSE);
        dqs = Skinners.scalar(SkinningMethod.DQS, geometry, NormalTransform.INVERSE_TRANSPOSE);
        int n = geometry.pointCount();
        lbsPositions = new float[3 * n];
        dqsPositions = new float[3 * n];
        normals = new float[3 * n];
        distances = new float[n];
    }

    /**
     * Skins the pose with both methods and measures them.
     *
     * @param skinningMatrices 12 floats per palette joint, row-major 3x4 (a frame's palette)
     */
    public void compare(float[] skinningMatrices) {
        int joints = palette.jointCount();
        for (int j = 0; j < joints; j++) {
            AnimationHelper.getRowMajor3x4(skinningMatrices, 12 * j, matrix);
            palette.setMatrix(j, matrix);
        }
        palette.prepare(SkinningMethod.DQS);
        lbs.skinAll(palette, lbsPositions, normals);
        dqs.skinAll(palette, dqsPositions, normals);
        double max = 0;
        for (int i = 0; i < distances.length; i++) {
            float dx = lbsPositions[3 * i] - dqsPositions[3 * i];
            float dy = lbsPositions[3 * i + 1] - dqsPositions[3 * i + 1];
            float dz = lbsPositions[3 * i + 2] - dqsPositions[3 * i + 2];
            float d = (float) Math.sqrt(dx * dx + dy * dy + dz * dz);
            distances[i] = d;
            max = Math.max(max, d);
        }
        maxDistance = max;
        lbsVolume = rest.relativeVolume(part, lbsPositions);
        dqsVolume = rest.relativeVolume(part, dqsPositions);
    }

    public SkinnedGeometry geometry() {
        return geometry;
    }

    /** The model's size: the diagonal of its rest pose's bounds over every part ({@link RestPose#size()}). */
    public double size() {
        return rest.size();
    }

    /** The largest |LBS - DQS| over the points, in model units. */
    public double maxDistance() {
        return maxDistance;
    }

    /** {@link #maxDistance()} over {@link #size()}; 0 for a model of no size. */
    public double maxRelative() {
        return rest.size() > 0 ? maxDistance / rest.size() : 0;
    }

    /** Per point, |LBS - DQS|. Read-only; overwritten by the next compare. */
    public float[] distances() {
        return distances;
    }

    public float[] lbsPositions() {
        return lbsPositions;
    }

    public float[] dqsPositions() {
        return dqsPositions;
    }

    /** LBS's volume of the part over its rest volume; NaN unless the part is closed by itself. */
    public double lbsVolume() {
        return lbsVolume;
    }

    /** DQS's volume of the part over its rest volume; NaN unless the part is closed by itself. */
    public double dqsVolume() {
        return dqsVolume;
    }

    /** Whether the part is closed by itself ({@link RestPose.PartVolume#CLOSED}), so that its volumes are numbers. */
    public boolean closed() {
        return rest.partVolume(part) == RestPose.PartVolume.CLOSED;
    }
}
