package org.skinlab.skinning;

import org.joml.Matrix4f;
import org.skinlab.animation.AnimationHelper;

/**
 * LBS and DQS side by side on one geometry and one pose: where the two methods place each point
 * apart, the largest distance relative to the model's size, and the volume each keeps (for a
 * closed mesh). What the desktop's difference view colours and prints.
 *
 * <p>The pose comes as the skinning matrices a {@code Frame} carries (12 floats per joint,
 * row-major 3x4); the dual quaternions and scale parts are derived from them by the same
 * {@link JointPalette} code the simulation uses, so both methods run exactly as the simulation
 * would run them. Both skins use core's scalar kernels ({@link Skinners#scalar}). One instance per geometry;
 * {@link #compare} allocates nothing; not thread-safe.
 */
public final class MethodComparison {
    private final SkinnedGeometry geometry;
    private final JointPalette palette;
    private final Skinner lbs;
    private final Skinner dqs;
    private final float[] lbsPositions;
    private final float[] dqsPositions;
    private final float[] normals;
    private final float[] distances;
    private final Matrix4f matrix = new Matrix4f();
    private final int[] triangles;
    private final double restVolume;
    private final double size;
    private double maxDistance;
    private double lbsVolume = Double.NaN;
    private double dqsVolume = Double.NaN;

    public MethodComparison(SkinnedGeometry geometry) {
        this.geometry = geometry;
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
        boolean closed = ArtifactMetrics.isClosed(geometry);
        triangles = closed ? geometry.mesh().triangles() : null;
        restVolume = closed ? ArtifactMetrics.signedVolume(geometry.positionArray(), triangles) : Double.NaN;
        size = ArtifactMetrics.boundsDiagonal(geometry.positionArray(), geometry.vertexCount());
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
        palette.prepareDualQuaternions();
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
        if (triangles != null && restVolume != 0) {
            lbsVolume = ArtifactMetrics.signedVolume(lbsPositions, triangles) / restVolume;
            dqsVolume = ArtifactMetrics.signedVolume(dqsPositions, triangles) / restVolume;
        }
    }

    public SkinnedGeometry geometry() {
        return geometry;
    }

    /** The model's size: the diagonal of its bind-pose bounding box (render vertices). */
    public double size() {
        return size;
    }

    /** The largest |LBS - DQS| over the points, in model units. */
    public double maxDistance() {
        return maxDistance;
    }

    /** {@link #maxDistance()} over {@link #size()}; 0 for a model of no size. */
    public double maxRelative() {
        return size > 0 ? maxDistance / size : 0;
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

    /** LBS's volume over the rest volume; NaN when the mesh is not closed. */
    public double lbsVolume() {
        return lbsVolume;
    }

    /** DQS's volume over the rest volume; NaN when the mesh is not closed. */
    public double dqsVolume() {
        return dqsVolume;
    }

    /** Whether the mesh is closed, so that volumes mean something. */
    public boolean closed() {
        return triangles != null;
    }
}
