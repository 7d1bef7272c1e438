package org.skinlab.gltf;

import org.skinlab.model.Mesh;

/**
 * One glTF mesh as read by {@link MeshReader}: the model's base {@link Mesh} (its primitives'
 * vertices one after another, welded into positions by {@link PositionWelder}) and what a node
 * still needs to place it: the morph targets' offsets, the default weights, each part's material,
 * and the skin influences of every position (joint numbers index the joints of whichever skin the
 * node uses).
 */
final class MeshData {
    final int index;
    final Mesh mesh;
    /** Per morph target, 3 offsets per position. */
    final float[][] targetPositions;
    /** Per morph target, 3 normal offsets per vertex, or null when the target has none. */
    final float[][] targetNormals;
    /** {@code mesh.weights}, one per target (0 where the file gives none). */
    final float[] weights;
    /** Per {@link Mesh#parts()} entry, the glTF material index, or -1. */
    final int[] partMaterials;
    /** Influences per position (compressed rows), zero weights dropped. */
    final int[] influenceStart;
    final int[] influenceJoints;
    final float[] influenceWeights;
    /** The largest joint number any influence uses (-1: none), and the JSON path it came from. */
    final int maxJoint;
    final String maxJointPath;
    /** The path of a primitive without JOINTS_0/WEIGHTS_0, or null when all have them. */
    final String primitiveWithoutJoints;

    MeshData(int index, Mesh mesh, float[][] targetPositions, float[][] targetNormals, float[] weights,
            int[] partMaterials, int[] influenceStart, int[] influenceJoints, float[] influenceWeights, int maxJoint,
            String maxJointPath, String primitiveWithoutJoints) {
        this.index = index;
        this.mesh = mesh;
        this.targetPositions = targetPositions;
        this.targetNormals = targetNormals;
        this.weights = weights;
        this.partMaterials = partMaterials;
        this.influenceStart = influenceStart;
        this.influenceJoints = influenceJoints;
        this.influenceWeights = influenceWeights;
        this.maxJoint = maxJoint;
        this.maxJointPath = maxJointPath;
        this.primitiveWithoutJoints = primitiveWithoutJoints;
    }

    int targetCount() {
        return targetPositions.length;
    }
}
