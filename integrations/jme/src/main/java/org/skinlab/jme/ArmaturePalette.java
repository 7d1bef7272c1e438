package org.skinlab.jme;

import java.util.List;

import com.jme3.anim.Armature;
import com.jme3.anim.Joint;
import com.jme3.math.Matrix4f;
import org.skinlab.skinning.JointPalette;

/**
 * How a jME {@link Armature}'s joints sit in skinlab's joint palette: skinlab wants every joint's
 * parent before it ({@code SkinnedGeometry.fromArrays} checks it, the bone methods walk the
 * hierarchy that way), while jME keeps the glTF skin's order, where a child may come first. So the
 * palette lists the joints depth first from the armature's roots, and {@link #paletteIndex} maps
 * a jME joint index (what a mesh's BoneIndex buffer holds) to its palette entry.
 *
 * <p>Each frame {@link #fill} copies jME's own skinning matrices
 * ({@link Armature#computeSkinningMatrices()}: joint model transform times inverse model bind) into
 * a palette, so skinlab's kernels deform the mesh in the same space as jME's SkinningControl does.
 */
final class ArmaturePalette {
    private final Armature armature;
    /** Per jME joint index, its palette index. */
    private final int[] paletteIndex;
    /** Per palette index, its jME joint index. */
    private final int[] jmeIndex;
    private final int[] parents;
    /** Per palette joint, the inverse model bind matrix, 16 floats column-major. */
    private final float[] bindMatrices;

    ArmaturePalette(Armature armature) {
        this.armature = armature;
        int n = armature.getJointCount();
        paletteIndex = new int[n];
        jmeIndex = new int[n];
        parents = new int[n];
        int[] next = {0};
        for (Joint root : armature.getRoots()) {
            visit(root, -1, next);
        }
        if (next[0] != n) {
            throw new IllegalArgumentException("armature with " + n + " joints reaches only " + next[0]
                    + " of them from its roots");
        }
        bindMatrices = new float[16 * n];
        for (int p = 0; p < n; p++) {
            Matrix4f m = armature.getJoint(jmeIndex[p]).getInverseModelBindMatrix();
            for (int c = 0; c < 4; c++) {
                for (int r = 0; r < 4; r++) {
                    bindMatrices[16 * p + 4 * c + r] = m.get(r, c);
                }
            }
        }
    }

    private void visit(Joint joint, int parent, int[] next) {
        int p = next[0]++;
        int j = armature.getJointIndex(joint);
        paletteIndex[j] = p;
        jmeIndex[p] = j;
        parents[p] = parent;
        List<Joint> children = joint.getChildren();
        for (Joint child : children) {
            visit(child, p, next);
        }
    }

    Armature armature() {
        return armature;
    }

    int jointCount() {
        return paletteIndex.length;
    }

    int paletteIndex(int jmeJoint) {
        return paletteIndex[jmeJoint];
    }

    /** Per palette joint its parent's palette index, -1 for a root; a copy. */
    int[] parents() {
        return parents.clone();
    }

    /** Per palette joint the inverse model bind matrix, 16 floats column-major; a copy. */
    float[] bindMatrices() {
        return bindMatrices.clone();
    }

    /**
     * Writes the armature's current skinning matrices into {@code palette} (row-major 3x4 per
     * joint, palette order). Allocation-free; the armature must be updated for this frame.
     */
    void fill(JointPalette palette) {
        Matrix4f[] offsets = armature.computeSkinningMatrices();
        float[] dest = palette.writableMatrices();
        for (int p = 0; p < jmeIndex.length; p++) {
            Matrix4f m = offsets[jmeIndex[p]];
            int o = 12 * p;
            dest[o] = m.m00;
            dest[o + 1] = m.m01;
            dest[o + 2] = m.m02;
            dest[o + 3] = m.m03;
            dest[o + 4] = m.m10;
            dest[o + 5] = m.m11;
            dest[o + 6] = m.m12;
            dest[o + 7] = m.m13;
            dest[o + 8] = m.m20;
            dest[o + 9] = m.m21;
            dest[o + 10] = m.m22;
            dest[o + 11] = m.m23;
        }
    }
}
