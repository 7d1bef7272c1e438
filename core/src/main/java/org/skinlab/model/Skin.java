package org.skinlab.model;

import java.util.List;

import org.joml.Matrix4f;
import org.joml.Matrix4fc;

/**
 * One {@code <controller><skin>}: which mesh it deforms, the bind shape matrix, its joints with
 * their inverse bind matrices, and every influence of every position, as written in the file.
 *
 * <p>Influences are stored per <em>position</em> of the mesh (compressed rows: position
 * {@code p} owns entries {@code influenceStart(p)} to {@code influenceStart(p+1)-1}), all of
 * them, in file order, with weights as written (not renormalised: the importer warns when sums
 * differ from one), except that negative weights are read as 0 (warned). A joint index of -1 is
 * COLLADA's reference to the bind shape itself.
 *
 * <p>Joints are stored by the names the file gives ({@code Name_array}: usually sids;
 * {@code IDREF_array}: node ids). Which scene node each joint is depends on the instance's
 * {@code <skeleton>} roots and is resolved per {@link MeshInstance}.
 */
public final class Skin {
    private final String controllerId;
    private final String name;
    private final Mesh mesh;
    private final Matrix4f bindShapeMatrix;
    private final List<String> jointNames;
    private final boolean jointsAreIdrefs;
    private final float[] inverseBindMatrices;
    private final int[] influenceStart;
    private final int[] influenceJoints;
    private final float[] influenceWeights;
    private final int maxInfluences;

    /**
     * @param controllerId        the controller's id (for glTF, the skin's JSON path, e.g. {@code /skins/0})
     * @param name                the controller's name, or null
     * @param mesh                the mesh the skin deforms, whose positions the influences belong to
     * @param bindShapeMatrix     the bind shape matrix
     * @param jointNames          one name per joint, as the file gives them
     * @param jointsAreIdrefs     true when the names come from an {@code IDREF_array} (node ids), false for a
     *                            {@code Name_array}
     * @param inverseBindMatrices 16 floats per joint, column-major (JOML/OpenGL order)
     * @param influenceStart      positionCount + 1 offsets into the influence arrays
     * @param influenceJoints     per influence entry, its joint index (0 to joints - 1, or -1 for the bind shape)
     * @param influenceWeights    per influence entry, its weight as written (0 for a negative one)
     * @throws IllegalArgumentException when an array's length disagrees with the joints or the mesh's positions,
     *         the offsets decrease, or a joint index is out of range
     */
    public Skin(String controllerId, String name, Mesh mesh, Matrix4fc bindShapeMatrix, List<String> jointNames,
            boolean jointsAreIdrefs, float[] inverseBindMatrices, int[] influenceStart, int[] influenceJoints,
            float[] influenceWeights) {
        int joints = jointNames.size();
        if (inverseBindMatrices.length != 16 * joints) {
            throw new IllegalArgumentException("need 16 floats per joint for the inverse bind matrices");
        }
        if (influenceStart.length != mesh.positionCount() + 1 || influenceStart[0] != 0
                || influenceStart[mesh.positionCount()] != influenceJoints.length
                || influenceJoints.length != influenceWeights.length) {
            throw new IllegalArgumentException("influence arrays do not match the mesh's positions");
        }
        int max = 0;
        for (int p = 0; p < mesh.positionCount(); p++) {
            int n = influenceStart[p + 1] - influenceStart[p];
            if (n < 0) {
                throw new IllegalArgumentException("influence offsets must not decrease");
            }
            max = Math.max(max, n);
        }
        for (int j : influenceJoints) {
            if (j < -1 || j >= joints) {
                throw new IllegalArgumentException("influence joint " + j + " out of range");
            }
        }
        this.controllerId = controllerId;
        this.name = name;
        this.mesh = mesh;
        this.bindShapeMatrix = new Matrix4f(bindShapeMatrix);
        this.jointNames = List.copyOf(jointNames);
        this.jointsAreIdrefs = jointsAreIdrefs;
        this.inverseBindMatrices = inverseBindMatrices.clone();
        this.influenceStart = influenceStart.clone();
        this.influenceJoints = influenceJoints.clone();
        this.influenceWeights = influenceWeights.clone();
        this.maxInfluences = max;
    }

    /**
     * The controller's id.
     *
     * @return the id (for glTF, the skin's JSON path)
     */
    public String controllerId() {
        return controllerId;
    }

    /**
     * The controller's name, or null.
     *
     * @return the name, or null when the file gives none
     */
    public String name() {
        return name;
    }

    /**
     * The mesh this skin deforms (its {@code source} geometry).
     *
     * @return the mesh, whose positions the influences belong to
     */
    public Mesh mesh() {
        return mesh;
    }

    /**
     * The bind shape matrix (read-only view).
     *
     * @return the matrix applied to the mesh's positions before the joints' (the identity when the file gives
     *         none, and for glTF)
     */
    public Matrix4fc bindShapeMatrix() {
        return bindShapeMatrix;
    }

    /**
     * Number of joints.
     *
     * @return the joint count, the size of {@link #jointNames()}
     */
    public int jointCount() {
        return jointNames.size();
    }

    /**
     * Joint names as the file gives them (sids, ids or names; see {@link #jointsAreIdrefs()}).
     *
     * @return an unmodifiable list, one name per joint index
     */
    public List<String> jointNames() {
        return jointNames;
    }

    /**
     * True when the joints came from an {@code IDREF_array} (node ids), false for {@code Name_array}.
     *
     * @return whether the joint names are node ids
     */
    public boolean jointsAreIdrefs() {
        return jointsAreIdrefs;
    }

    /**
     * Joint {@code j}'s inverse bind matrix, written into {@code dest}.
     *
     * @param j    the joint index, 0 to {@link #jointCount()} - 1
     * @param dest the matrix to overwrite
     * @return {@code dest}
     */
    public Matrix4f inverseBindMatrix(int j, Matrix4f dest) {
        return dest.set(inverseBindMatrices, 16 * j);
    }

    /**
     * A copy of all inverse bind matrices, 16 floats per joint, column-major.
     *
     * @return a new array of 16 * {@link #jointCount()} floats
     */
    public float[] inverseBindMatrices() {
        return inverseBindMatrices.clone();
    }

    /**
     * First influence entry of position {@code p}; {@code influenceStart(p + 1)} ends it.
     *
     * @param p the position index, 0 to the mesh's {@link Mesh#positionCount()} (which gives
     *          {@link #influenceTotal()})
     * @return the index of the position's first influence entry
     */
    public int influenceStart(int p) {
        return influenceStart[p];
    }

    /**
     * Number of influences of position {@code p} (may be zero).
     *
     * @param p the position index, 0 to the mesh's {@link Mesh#positionCount()} - 1
     * @return the number of the position's influence entries
     */
    public int influenceCount(int p) {
        return influenceStart[p + 1] - influenceStart[p];
    }

    /**
     * Joint index of influence entry {@code i} (-1: the bind shape).
     *
     * @param i the influence entry, 0 to {@link #influenceTotal()} - 1
     * @return the joint index, 0 to {@link #jointCount()} - 1, or -1 for the bind shape
     */
    public int influenceJoint(int i) {
        return influenceJoints[i];
    }

    /**
     * Weight of influence entry {@code i}, as written (0 for a negative one).
     *
     * @param i the influence entry, 0 to {@link #influenceTotal()} - 1
     * @return the weight; a position's weights need not sum to one
     */
    public float influenceWeight(int i) {
        return influenceWeights[i];
    }

    /**
     * Total number of influence entries.
     *
     * @return the number of entries over all positions
     */
    public int influenceTotal() {
        return influenceJoints.length;
    }

    /**
     * The largest number of influences of any position.
     *
     * @return the largest {@link #influenceCount(int)}, 0 when no position has any
     */
    public int maxInfluences() {
        return maxInfluences;
    }

    @Override
    public String toString() {
        return "Skin[" + controllerId + " on " + mesh.id() + ", " + jointCount() + " joints, max "
                + maxInfluences + " influences]";
    }
}
