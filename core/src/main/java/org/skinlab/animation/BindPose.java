package org.skinlab.animation;

import org.joml.Matrix4f;
import org.skinlab.model.MeshInstance;
import org.skinlab.model.Model;
import org.skinlab.model.Skin;

/**
 * The skeleton as its skins were bound: every joint at the world transform its INV_BIND_MATRIX
 * (glTF's inverse bind matrix) is the inverse of, every other node at its parent's world times its
 * own transforms as the file writes them (so a static mesh or a helper below a joint moves with
 * that joint's bind frame). Skinning with this pose gives each skinned mesh its bind shape, whatever
 * the clip does: {@code world(joint) * INV_BIND = identity}, so every point lands where the bind
 * shape matrix put it, whatever its weights. A clip's first key is often another pose (a walk
 * cycle's first step; our humanoid's A-pose bind against its first key).
 *
 * <p>A node that is a joint of several skins takes the bind frame of the first skin that names it
 * (model order); a skin bound at another moment then shows its joints at that skin's frames rather
 * than its own. A joint whose inverse bind matrix cannot be inverted (zero scale) is placed as a
 * plain node. Built once per model (the inverses); {@link #apply} allocates nothing.
 */
public final class BindPose {
    /** Per node, whether a skin gives its world matrix. */
    private final boolean[] bound;
    /** Per bound node, its world matrix at bind time: 16 floats column-major. */
    private final float[] worlds;

    private BindPose(boolean[] bound, float[] worlds) {
        this.bound = bound;
        this.worlds = worlds;
    }

    /**
     * The bind pose of {@code model}'s nodes (those of {@link Skeleton#of(Model)}).
     *
     * @param model the model whose skins' inverse bind matrices give the joints' bind frames
     * @return a new bind pose, to {@link #apply} to poses of that model's skeleton
     */
    public static BindPose of(Model model) {
        int n = model.nodes().size();
        boolean[] bound = new boolean[n];
        float[] worlds = new float[16 * n];
        Matrix4f m = new Matrix4f();
        for (MeshInstance instance : model.instances()) {
            Skin skin = instance.skin();
            if (skin == null) {
                continue;
            }
            for (int j = 0; j < skin.jointCount(); j++) {
                int node = instance.jointNode(j);
                if (node < 0 || node >= n || bound[node]) {
                    continue;
                }
                skin.inverseBindMatrix(j, m);
                float det = m.determinant3x3();
                if (!(Math.abs(det) > 1e-20f) || !Float.isFinite(det)) {
                    continue;
                }
                m.invertAffine().get(worlds, 16 * node);
                bound[node] = true;
            }
        }
        return new BindPose(bound, worlds);
    }

    /**
     * Whether node {@code node} is placed by a skin's bind frame (else by its parent and its own transforms).
     *
     * @param node the node index, in [0, {@link Skeleton#nodeCount()})
     * @return true for a joint of some skin with an invertible inverse bind matrix
     */
    public boolean bound(int node) {
        return bound[node];
    }

    /**
     * Sets {@code pose} to the bind pose of {@code skeleton} (the skeleton of the model this was
     * made from): the transform values back at rest, then every world matrix.
     *
     * @param skeleton the skeleton of the model this bind pose was made from
     * @param pose a pose of {@code skeleton}; its values and world matrices are overwritten
     * @throws IllegalArgumentException when {@code skeleton} has another number of nodes than the model
     */
    public void apply(Skeleton skeleton, Pose pose) {
        if (skeleton.nodeCount() != bound.length) {
            throw new IllegalArgumentException("a skeleton of " + skeleton.nodeCount() + " nodes, a bind pose of "
                    + bound.length);
        }
        skeleton.reset(pose);
        skeleton.evaluate(pose, bound, worlds);
    }
}
