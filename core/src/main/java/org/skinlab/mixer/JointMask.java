package org.skinlab.mixer;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;

import org.skinlab.animation.Skeleton;
import org.skinlab.model.Node;

/**
 * How much a {@link Layer} counts at each joint: a weight from 0 to 1 per node of a skeleton.
 * Immutable. Joints are named by their node's name, id or sid (what {@link #find} accepts).
 */
public final class JointMask {
    private final Skeleton skeleton;
    private final float[] weights;
    private final String description;

    private JointMask(Skeleton skeleton, float[] weights, String description) {
        this.skeleton = skeleton;
        this.weights = weights;
        this.description = description;
    }

    /**
     * Every node at weight 1: no mask.
     *
     * @param skeleton the skeleton the mask is for
     * @return a mask of ones
     */
    public static JointMask all(Skeleton skeleton) {
        float[] w = new float[skeleton.nodeCount()];
        Arrays.fill(w, 1f);
        return new JointMask(skeleton, w, "all joints");
    }

    /**
     * A joint and everything below it at weight 1, every other node at 0 (e.g. "upper body only":
     * the spine's first joint).
     *
     * @param skeleton the skeleton the mask is for
     * @param joint the name, id or sid of the top node of the subtree
     * @return the mask
     * @throws IllegalArgumentException when the skeleton has no such node (the message lists its joints)
     */
    public static JointMask subtree(Skeleton skeleton, String joint) {
        int top = find(skeleton, joint);
        float[] w = new float[skeleton.nodeCount()];
        for (int i = 0; i < w.length; i++) {
            w[i] = below(skeleton, i, top) ? 1f : 0f;
        }
        return new JointMask(skeleton, w, "below " + joint);
    }

    /**
     * Explicit weights per joint; a node not named takes the weight of its nearest named ancestor,
     * 0 when it has none (so naming a joint covers its subtree unless a descendant is named too).
     *
     * @param skeleton the skeleton the mask is for
     * @param weights per joint name (name, id or sid), a weight in [0, 1]
     * @return the mask
     * @throws IllegalArgumentException for an unknown joint, or a weight that is NaN or outside [0, 1]
     */
    public static JointMask of(Skeleton skeleton, Map<String, Float> weights) {
        float[] given = new float[skeleton.nodeCount()];
        Arrays.fill(given, Float.NaN);
        for (Map.Entry<String, Float> e : weights.entrySet()) {
            float v = e.getValue();
            if (!(v >= 0f && v <= 1f)) {
                throw new IllegalArgumentException("mask weight of joint \"" + e.getKey() + "\" is " + v
                        + " (need a value from 0 to 1)");
            }
            given[find(skeleton, e.getKey())] = v;
        }
        float[] w = new float[given.length];
        for (int i = 0; i < w.length; i++) {
            int p = skeleton.parent(i);
            w[i] = !Float.isNaN(given[i]) ? given[i] : p >= 0 ? w[p] : 0f;
        }
        return new JointMask(skeleton, w, weights.toString());
    }

    /**
     * The node named {@code joint}: by name first, then id, then sid.
     *
     * @param skeleton the skeleton searched
     * @param joint the name, id or sid
     * @return the node index
     * @throws IllegalArgumentException when no node has it (the message lists the joints)
     */
    public static int find(Skeleton skeleton, String joint) {
        for (int pass = 0; pass < 3; pass++) {
            for (int i = 0; i < skeleton.nodeCount(); i++) {
                Node n = skeleton.node(i);
                String key = pass == 0 ? n.name() : pass == 1 ? n.id() : n.sid();
                if (joint.equals(key)) {
                    return i;
                }
            }
        }
        List<String> joints = new ArrayList<>();
        for (int i = 0; i < skeleton.nodeCount(); i++) {
            if (skeleton.node(i).isJoint()) {
                joints.add(skeleton.node(i).label());
            }
        }
        throw new IllegalArgumentException("no joint \"" + joint + "\" in this model (joints: "
                + String.join(", ", joints) + ")");
    }

    private static boolean below(Skeleton skeleton, int node, int top) {
        for (int i = node; i >= 0; i = skeleton.parent(i)) {
            if (i == top) {
                return true;
            }
        }
        return false;
    }

    /**
     * The skeleton the mask is for.
     *
     * @return the skeleton given when it was made
     */
    public Skeleton skeleton() {
        return skeleton;
    }

    /**
     * The weight at node {@code node}.
     *
     * @param node the node index
     * @return the weight, in [0, 1]
     */
    public float weight(int node) {
        return weights[node];
    }

    float[] weights() {
        return weights;
    }

    @Override
    public String toString() {
        return description;
    }
}
