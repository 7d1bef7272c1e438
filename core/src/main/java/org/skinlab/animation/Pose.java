package org.skinlab.animation;

import org.joml.Matrix4f;
import org.joml.Quaternionf;

/**
 * One state of a {@link Skeleton}: the transform values of every node (rest values where nothing
 * animates them) and, after {@link Skeleton#evaluate}, every node's world matrix. Also holds the
 * scratch matrices evaluation needs, so evaluating allocates nothing and different threads can
 * evaluate the same skeleton into their own poses.
 */
public final class Pose {
    private final Skeleton skeleton;
    private final float[] values;
    private final float[] world;
    final Matrix4f local = new Matrix4f();
    final Matrix4f scratch = new Matrix4f();
    /** One column-major 4x4 matrix of scratch for {@link Skeleton#skinningMatrices}. */
    final float[] product = new float[16];
    /** One row-major local matrix of scratch for {@link Skeleton#evaluate(LocalPose, Pose)}. */
    final float[] localRows = new float[16];
    // Scratch for AnimationSampler's rotation blending other than slerp.
    final Quaternionf q1 = new Quaternionf();
    final Quaternionf q2 = new Quaternionf();

    Pose(Skeleton skeleton) {
        this.skeleton = skeleton;
        this.values = skeleton.restValues().clone();
        this.world = new float[16 * skeleton.nodeCount()];
    }

    /**
     * The skeleton this pose belongs to; its arrays are laid out for that skeleton only.
     *
     * @return the skeleton that made this pose
     */
    public Skeleton skeleton() {
        return skeleton;
    }

    /**
     * The transform values, laid out per node and element as {@link Skeleton#valueOffset} says,
     * each element in its {@link org.skinlab.model.TransformElement} layout. Animation writes here.
     *
     * @return the live array (not a copy), {@link Skeleton#valueCount()} floats
     */
    public float[] values() {
        return values;
    }

    /**
     * World matrices, 16 floats column-major per node. Valid after {@link Skeleton#evaluate}.
     *
     * @return the live array (not a copy), 16 times {@link Skeleton#nodeCount()} floats; node i's matrix starts
     *     at {@code 16 i}
     */
    public float[] worldArray() {
        return world;
    }

    /**
     * Node {@code node}'s world matrix.
     *
     * @param node the node index, in [0, {@link Skeleton#nodeCount()})
     * @param dest receives the world matrix as of the last {@link Skeleton#evaluate}
     * @return {@code dest}
     */
    public Matrix4f world(int node, Matrix4f dest) {
        return dest.set(world, 16 * node);
    }
}
