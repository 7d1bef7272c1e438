package org.skinlab.skinning;

import java.util.Arrays;
import java.util.List;

import org.skinlab.model.Mesh;
import org.skinlab.model.MeshInstance;
import org.skinlab.model.Node;

/**
 * The runtime form of one placed mesh, built once from a {@link MeshInstance}: flat arrays a
 * skinning kernel can stream through, nothing else (the ozz-animation split between offline data
 * and runtime data).
 *
 * <p><b>Points.</b> The kernels deform <em>points</em>: first the mesh's render vertices in
 * vertex order (each with its position, its normal and the influences of its position), then
 * every position no triangle uses (normal zero), so that every entry of the {@code <vertices>}
 * POSITION source is deformed somewhere: {@link #pointOfPosition(int)} says where.
 *
 * <p><b>Influences.</b> A fixed number {@link #influencesPerPoint()} per point (the most any
 * position of the skin has: all influences are kept), sorted by decreasing weight so the first is
 * the dominant one (the DQS antipodality pivot), padded with weight 0 on the dominant joint.
 * Weights are divided by their sum, as Blender's armature deform does, so files whose weights do
 * not add up to one still deform rigidly. A position without weight (or with weights summing to
 * zero) stays where the bind shape puts it ({@code SkinRows}).
 *
 * <p><b>Joints.</b> {@link #jointCount()} palette entries: the skin's joints in skin order, plus,
 * when needed, one pseudo-joint for COLLADA's joint index -1 (the bind shape itself) and for
 * unweighted positions. Each has a scene node ({@link #jointNode}, -1 for the pseudo-joint) and a
 * bind matrix (INV_BIND_MATRIX; the pseudo-joint's is the identity), so that the skinning matrix is
 * {@code world(node) * bind}, applied to the points' positions, which already hold the bind shape
 * matrix (positions moved by it, normals by its inverse-transpose, once, when the geometry is
 * built). When every bind frame mirrors, that common mirror is moved into the points too (see
 * {@link #windingMirrored()} and {@code BindSpace}), so the skinning matrices stay rigid for DQS.
 * A static mesh becomes a geometry with one joint, its own node, and identity bind: the same code
 * places it.
 *
 * <p><b>Shared positions.</b> A point's deformed position depends only on its POSITION entry, and
 * exporters split a position into several render vertices wherever normals or texture coordinates
 * differ (the thesis' cowboy has 740 positions in 4252 vertices). When points share positions,
 * {@link #sharedPositions()} is a second geometry whose points are the mesh's positions (in source
 * order, normals zero); a skinner may then deform those once into per-position deformations
 * ({@link Skinner#skinDeformations}) and derive every point from the deformation of its position
 * ({@link #deformationOfPointArray()}) and its own rest normal. Whether that pays depends on the method
 * and is decided where skinners are made ({@link Skinners}). Either way the points, their order
 * and the arrays below stay the same for callers.
 *
 * <p>{@code MeshGeometry} builds a geometry from a placed mesh; {@link #fromArrays} takes the
 * arrays as they are.
 */
public final class SkinnedGeometry {
    private final MeshInstance instance;
    private final int vertexCount;
    private final int pointCount;
    private final float[] positions;
    private final float[] normals;
    private final int influences;
    private final int[] joints;
    private final float[] weights;
    private final int[] jointNodes;
    private final float[] bindMatrices;
    private final int[] pointOfPosition;
    /** Per point, its position in {@link #sharedPositions}; null when points are skinned one by one. */
    private final int[] deformationOfPoint;
    private final SkinnedGeometry sharedPositions;
    private final boolean windingMirrored;
    /** Per palette joint, the palette joint of its nearest ancestor node that is one, else -1. */
    private final int[] jointParents;
    /** The bones of the palette's joints, for the methods that read them ({@link Bones}). */
    private final Bones bones;
    /** CoR skinning's centre per point, or null when the geometry was not bound for CoR. */
    private final float[] centres;
    /**
     * The arrays as they are, without copying or checking them beyond the palette's parents;
     * {@code deformationOfPoint} and {@code sharedPositions} are both null or both set (see the
     * class comment).
     */
    SkinnedGeometry(MeshInstance instance, int vertexCount, float[] positions, float[] normals,
            int influences, int[] joints, float[] weights, int[] jointNodes, float[] bindMatrices,
            int[] pointOfPosition, int[] deformationOfPoint, SkinnedGeometry sharedPositions, boolean windingMirrored,
            int[] jointParents) {
        if (jointParents.length != jointNodes.length) {
            throw new IllegalArgumentException("need one parent per palette joint");
        }
        this.instance = instance;
        this.jointParents = jointParents;
        this.vertexCount = vertexCount;
        this.pointCount = positions.length / 3;
        this.positions = positions;
        this.normals = normals;
        this.influences = influences;
        this.joints = joints;
        this.weights = weights;
        this.jointNodes = jointNodes;
        this.bindMatrices = bindMatrices;
        this.pointOfPosition = pointOfPosition;
        this.deformationOfPoint = deformationOfPoint;
        this.sharedPositions = sharedPositions;
        this.windingMirrored = windingMirrored;
        this.centres = null;
        // Last: the bones read the fields above.
        this.bones = Bones.of(this);
    }

    /** {@code g} with centres of rotation, and {@code shared} as its shared positions. */
    private SkinnedGeometry(SkinnedGeometry g, float[] centres, SkinnedGeometry shared) {
        this.instance = g.instance;
        this.jointParents = g.jointParents;
        this.vertexCount = g.vertexCount;
        this.pointCount = g.pointCount;
        this.positions = g.positions;
        this.normals = g.normals;
        this.influences = g.influences;
        this.joints = g.joints;
        this.weights = g.weights;
        this.jointNodes = g.jointNodes;
        this.bindMatrices = g.bindMatrices;
        this.pointOfPosition = g.pointOfPosition;
        this.deformationOfPoint = g.deformationOfPoint;
        this.sharedPositions = shared;
        this.windingMirrored = g.windingMirrored;
        this.bones = g.bones;
        this.centres = centres;
    }

    /**
     * The runtime geometry of a placed mesh, skinned or static, without the scene's node tree: no
     * joint has a parent ({@link #jointParent}), so each bone of {@link #bones()} is a leaf.
     *
     * @param instance the placed mesh; a static one gives a geometry with one joint, its own node
     * @return a new geometry, without centres of rotation
     */
    public static SkinnedGeometry of(MeshInstance instance) {
        return of(instance, List.of());
    }

    /**
     * The runtime geometry of a placed mesh of a model whose nodes are {@code nodes}
     * ({@link org.skinlab.model.Model#nodes()}): each joint's parent is the palette joint of its
     * nearest ancestor node that is one.
     *
     * @param instance the placed mesh; a static one gives a geometry with one joint, its own node
     * @param nodes    the model's nodes, indexed as the instance's node indices; empty for no hierarchy
     * @return a new geometry, without centres of rotation
     */
    public static SkinnedGeometry of(MeshInstance instance, List<Node> nodes) {
        return MeshGeometry.build(instance, nodes);
    }

    /**
     * What takes a position of the instance's mesh to its point in bind space: the skin's bind
     * shape matrix, then the common mirror of the bind frames when they all mirror (see the class
     * comment); the identity for a static mesh. An exporter that writes bind-space points maps
     * other per-position data (morph offsets) with it.
     *
     * @param instance a placed mesh
     * @return a new matrix
     */
    public static org.joml.Matrix4f bindSpaceTransform(MeshInstance instance) {
        return BindSpace.pointTransform(instance);
    }

    /**
     * A geometry straight from arrays, without a mesh (synthetic benchmark data, tests). Influences
     * are taken in the order given, so the first one is the DQS pivot; weights are used as given.
     *
     * @param positions    3 floats per point
     * @param normals      3 floats per point
     * @param influences   influences per point
     * @param joints       palette joint per influence
     * @param weights      weight per influence
     * @param bindMatrices 16 floats column-major per joint (identity where there is no bind frame)
     * @return a new geometry using these arrays, not copies; every joint is a root, no point shares a position
     * @throws IllegalArgumentException when the array sizes disagree, a weight is negative or not finite,
     *                                  or a joint index is outside the palette
     */
    public static SkinnedGeometry fromArrays(float[] positions, float[] normals, int influences, int[] joints,
            float[] weights, float[] bindMatrices) {
        int[] roots = new int[bindMatrices.length / 16];
        Arrays.fill(roots, -1);
        return fromArrays(positions, normals, influences, joints, weights, bindMatrices, roots);
    }

    /**
     * As {@link #fromArrays(float[], float[], int, int[], float[], float[])} with a joint
     * hierarchy: {@code jointParents[j]} is joint j's parent joint, or -1 for a root.
     *
     * @param positions    3 floats per point
     * @param normals      3 floats per point
     * @param influences   influences per point
     * @param joints       palette joint per influence
     * @param weights      weight per influence
     * @param bindMatrices 16 floats column-major per joint (identity where there is no bind frame)
     * @param jointParents per joint, its parent joint (an earlier one), or -1 for a root; copied
     * @return a new geometry using the other arrays, not copies; no point shares a position
     * @throws IllegalArgumentException when the array sizes disagree, a parent is not -1 or an earlier
     *                                  joint, a weight is negative or not finite, or a joint index is
     *                                  outside the palette
     */
    public static SkinnedGeometry fromArrays(float[] positions, float[] normals, int influences, int[] joints,
            float[] weights, float[] bindMatrices, int[] jointParents) {
        checkArrays(positions, normals, influences, joints, weights, bindMatrices);
        int jointCount = bindMatrices.length / 16;
        checkHierarchy(jointParents, jointCount);
        checkInfluences(joints, weights, jointCount);
        int points = positions.length / 3;
        int[] identity = new int[points];
        for (int i = 0; i < points; i++) {
            identity[i] = i;
        }
        int[] nodes = new int[jointCount];
        Arrays.fill(nodes, -1);
        return new SkinnedGeometry(null, points, positions, normals, influences, joints, weights, nodes,
                bindMatrices, identity, null, null, false, jointParents.clone());
    }

    private static void checkArrays(float[] positions, float[] normals, int influences, int[] joints,
            float[] weights, float[] bindMatrices) {
        int points = positions.length / 3;
        if (positions.length != 3 * points || normals.length != 3 * points || influences < 1
                || joints.length != influences * points || weights.length != influences * points
                || bindMatrices.length % 16 != 0) {
            throw new IllegalArgumentException("array sizes disagree");
        }
    }

    private static void checkHierarchy(int[] jointParents, int jointCount) {
        if (jointParents.length != jointCount) {
            throw new IllegalArgumentException("need one parent per palette joint");
        }
        for (int j = 0; j < jointCount; j++) {
            // Parents before children keeps the hierarchy acyclic.
            if (jointParents[j] < -1 || jointParents[j] >= j) {
                throw new IllegalArgumentException("joint " + j + "'s parent " + jointParents[j]
                        + " must be -1 or an earlier joint");
            }
        }
    }

    private static void checkInfluences(int[] joints, float[] weights, int jointCount) {
        for (float w : weights) {
            if (!(w >= 0f) || Float.isInfinite(w)) {
                throw new IllegalArgumentException("weight " + w + ": weights must be finite and not negative");
            }
        }
        for (int j : joints) {
            if (j < 0 || j >= jointCount) {
                throw new IllegalArgumentException("joint " + j + " outside the palette of " + jointCount);
            }
        }
    }

    /**
     * Whether the points are mirrored against the file's mesh (by a bind shape matrix with a
     * negative determinant, or by the common mirror of the bind frames moved into them, not by
     * both): the triangles' winding in bind space is then reversed against their (outward)
     * normals, so a renderer that culls back faces by winding must flip its front face for this
     * geometry (when the skinning matrices do not mirror it back).
     *
     * @return true when the bind-space winding is reversed against the file's
     */
    public boolean windingMirrored() {
        return windingMirrored;
    }

    /**
     * The placed mesh this geometry was built from, or null for {@link #fromArrays}.
     *
     * @return the instance, or null
     */
    public MeshInstance instance() {
        return instance;
    }

    /**
     * The mesh, or null for {@link #fromArrays}.
     *
     * @return the instance's mesh, or null
     */
    public Mesh mesh() {
        return instance == null ? null : instance.mesh();
    }

    /**
     * Whether the placed mesh has a skin. A static mesh's geometry has one joint, its own node with
     * the identity bind matrix; a geometry {@link #fromArrays} counts as skinned.
     *
     * @return false only for a geometry built from a static mesh instance
     */
    public boolean isSkinned() {
        return instance == null || instance.isSkinned();
    }

    /**
     * Number of points (render vertices, then unused positions).
     *
     * @return the point count: a third of the length of {@link #positionArray()}
     */
    public int pointCount() {
        return pointCount;
    }

    /**
     * Number of render vertices: points {@code [0, vertexCount)} are the mesh's vertices in order.
     *
     * @return the vertex count, at most {@link #pointCount()}; equal to it for {@link #fromArrays}
     */
    public int vertexCount() {
        return vertexCount;
    }

    /**
     * The point that carries position {@code p} of the mesh's POSITION source.
     *
     * @param p an index in the POSITION source, {@code [0, positionCount())}
     * @return the point carrying it (the first render vertex using it, or a point past the vertices when
     *         no vertex does); {@code p} itself for {@link #fromArrays}
     */
    public int pointOfPosition(int p) {
        return pointOfPosition[p];
    }

    /**
     * Number of entries of the mesh's POSITION source, each carried by at least one point
     * ({@link #pointOfPosition(int)}).
     *
     * @return the position count, at most {@link #pointCount()}; equal to it for {@link #fromArrays}
     */
    public int positionCount() {
        return pointOfPosition.length;
    }

    /**
     * Influences per point (fixed width, zero-weight padded).
     *
     * @return the stride of {@link #jointArray()} and {@link #weightArray()}, at least 1
     */
    public int influencesPerPoint() {
        return influences;
    }

    /**
     * Palette size: skin joints plus the bind-shape pseudo-joint when used.
     *
     * @return the number of skinning matrices a palette for this geometry holds
     */
    public int jointCount() {
        return jointNodes.length;
    }

    /**
     * Scene node of palette joint {@code j}, -1 for the bind-shape pseudo-joint.
     *
     * @param j a palette joint, {@code [0, jointCount())}
     * @return the node's index in the model's nodes, or -1 (also for every joint of {@link #fromArrays})
     */
    public int jointNode(int j) {
        return jointNodes[j];
    }

    // The arrays below are handed out without copying: they are read by every kernel every
    // frame. Callers must not modify them (only MorphedRestShape rewrites the positions of the
    // geometry it owns, between frames).

    /**
     * Positions in bind space (after the bind shape matrix), 3 per point. Read-only.
     *
     * @return x, y, z per point, not a copy
     */
    public float[] positionArray() {
        return positions;
    }

    /**
     * Normals in bind space, 3 per point (zero where the mesh has none). Read-only.
     *
     * @return x, y, z per point, not a copy
     */
    public float[] normalArray() {
        return normals;
    }

    /**
     * Palette joint of each influence, {@link #influencesPerPoint()} per point. Read-only.
     *
     * @return the joints, point-major, dominant influence first; not a copy
     */
    public int[] jointArray() {
        return joints;
    }

    /**
     * Normalised weight of each influence, {@link #influencesPerPoint()} per point. Read-only.
     *
     * @return the weights, point-major and parallel to {@link #jointArray()}; not a copy
     */
    public float[] weightArray() {
        return weights;
    }

    /**
     * Scene node per palette joint (-1: no node, identity world). Read-only.
     *
     * @return {@link #jointCount()} node indices, not a copy
     */
    public int[] jointNodeArray() {
        return jointNodes;
    }

    /**
     * Per palette joint, 16 floats column-major: INV_BIND_MATRIX (the identity for the bind-shape
     * pseudo-joint; the bind shape matrix is in the points already). Read-only.
     *
     * @return {@code 16 * jointCount()} floats, not a copy
     */
    public float[] bindMatrixArray() {
        return bindMatrices;
    }

    /**
     * The geometry whose points are this one's positions (source order, zero normals, the same
     * influences, joints and bind matrices), when some position is carried by more than one point;
     * null when every position has its own point. See the class comment.
     *
     * @return the per-position geometry, or null
     */
    public SkinnedGeometry sharedPositions() {
        return sharedPositions;
    }

    /**
     * Per point, the point of {@link #sharedPositions()} whose deformation it takes its position
     * and normal matrix from; null when positions are not shared. Read-only.
     *
     * @return one index into {@link #sharedPositions()}'s points per point, not a copy; or null
     */
    public int[] deformationOfPointArray() {
        return deformationOfPoint;
    }

    /**
     * Whether this geometry carries CoR's centres of rotation ({@link #withCentresOfRotation()}).
     *
     * @return true when {@link #centresOfRotation()} has them
     */
    public boolean hasCentresOfRotation() {
        return centres != null;
    }

    /**
     * The centre of rotation of every point for CoR skinning: 3 floats per point, bind space.
     * Read-only.
     *
     * @return the centres, not a copy
     * @throws IllegalStateException when the geometry was not bound for CoR: a geometry has
     *                               centres only from {@link #withCentresOfRotation()}
     */
    public float[] centresOfRotation() {
        if (centres == null) {
            throw new IllegalStateException(this + " has no centres of rotation: bind it for CoR first"
                    + " (SkinnedGeometry.withCentresOfRotation(), or a SkinnedModel that skins with COR)");
        }
        return centres;
    }

    /**
     * This geometry with CoR's centres of rotation: computed now with the paper's parameters, in
     * parallel ({@link CentresOfRotation#computeOrLoad}, from its disk cache when one is set and
     * holds them). Bind-time work, up to a second for a large character: run it where a model is
     * loaded, not on a frame's thread.
     *
     * @return a geometry with the same arrays and the centres; this one when it has them already
     */
    public SkinnedGeometry withCentresOfRotation() {
        return centres != null ? this : withCentresOfRotation(CentresOfRotation.computeOrLoad(this,
                CentresOfRotation.Parameters.DEFAULT, CentresOfRotation.Progress.NONE));
    }

    /**
     * This geometry with the bind-time data {@code method}'s skinners read beyond the arrays: CoR's
     * centres of rotation ({@link #withCentresOfRotation()}) for {@link SkinningMethod#COR}; every
     * other method's bindings are made by its skinner. Bind-time work, like
     * {@link #withCentresOfRotation()}.
     *
     * @param method the method a skinner will be made for
     * @return a geometry ready for that method's skinners; this one when it is already
     */
    public SkinnedGeometry boundFor(SkinningMethod method) {
        return method == SkinningMethod.COR ? withCentresOfRotation() : this;
    }

    /**
     * This geometry with the given centres of rotation (e.g. computed with other parameters, or
     * those of the unmorphed rest shape of a morphing mesh). Its {@link #sharedPositions()}
     * get the centre of a point that carries each position.
     *
     * @param centres 3 floats per point, bind space; kept, not copied
     * @return a geometry with the same arrays and these centres
     */
    public SkinnedGeometry withCentresOfRotation(float[] centres) {
        if (centres.length != 3 * pointCount) {
            throw new IllegalArgumentException(centres.length + " floats of centres for " + pointCount + " points");
        }
        SkinnedGeometry shared = sharedPositions;
        if (shared != null) {
            // A position no point carries keeps itself.
            float[] perPosition = shared.positionArray().clone();
            for (int i = 0; i < pointCount; i++) {
                System.arraycopy(centres, 3 * i, perPosition, 3 * deformationOfPoint[i], 3);
            }
            shared = new SkinnedGeometry(shared, perPosition, null);
        }
        return new SkinnedGeometry(this, centres, shared);
    }

    /**
     * Palette joint {@code j}'s parent joint, or -1 (a root, or no node tree known).
     *
     * @param j a palette joint, {@code [0, jointCount())}
     * @return the parent's palette index, or -1
     */
    public int jointParent(int j) {
        return jointParents[j];
    }

    /**
     * The bones of the palette's joints (segments in bind space) for the methods that read them
     * ({@link SkinningMethod#usesBones()}), derived when the geometry was built.
     *
     * @return the bones
     */
    public Bones bones() {
        return bones;
    }

    /**
     * A palette sized for this geometry, with its DQS pivots and its bones.
     *
     * @return a new palette holding identity matrices
     */
    public JointPalette newPalette() {
        return new JointPalette(bindMatrices, bones);
    }

    /**
     * Copies the deformed positions of points into position order (3 floats per POSITION entry).
     *
     * @param pointPositions 3 floats per point, as a skinner writes them
     * @param dest           receives 3 floats per POSITION entry; at least {@code 3 * positionCount()} long
     * @return {@code dest}
     */
    public float[] positionsInSourceOrder(float[] pointPositions, float[] dest) {
        for (int p = 0; p < pointOfPosition.length; p++) {
            System.arraycopy(pointPositions, 3 * pointOfPosition[p], dest, 3 * p, 3);
        }
        return dest;
    }

    @Override
    public String toString() {
        return "SkinnedGeometry[" + (instance == null ? "arrays" : instance.mesh().id()) + ", " + pointCount + " points"
                + (sharedPositions == null ? "" : " over " + sharedPositions.pointCount + " shared positions") + ", "
                + jointCount() + " joints, " + influences + " influences per point]";
    }
}
