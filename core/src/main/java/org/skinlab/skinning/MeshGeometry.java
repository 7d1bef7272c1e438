package org.skinlab.skinning;

import java.util.Arrays;
import java.util.List;

import org.joml.Matrix4f;
import org.skinlab.model.Mesh;
import org.skinlab.model.MeshInstance;
import org.skinlab.model.Node;
import org.skinlab.model.Skin;

/**
 * Builds the {@link SkinnedGeometry} of a placed mesh, once: lays out its points
 * ({@link PointLayout}), gives them the influences of their positions ({@link SkinRows}) in bind
 * space ({@link BindSpace}), and adds the shared-position twin when points share positions. A
 * static mesh becomes a geometry with one joint, its own node, and identity bind.
 */
final class MeshGeometry {
    private MeshGeometry() {
    }

    /** See {@link SkinnedGeometry#of(MeshInstance, List)}. */
    static SkinnedGeometry build(MeshInstance instance, List<Node> nodes) {
        Mesh mesh = instance.mesh();
        PointLayout layout = PointLayout.of(mesh);
        float[] positions = layout.positions(mesh);
        float[] normals = layout.normals(mesh);
        Skin skin = instance.skin();
        if (skin == null) {
            return unskinned(instance, layout, positions, normals);
        }
        SkinRows rows = SkinRows.of(skin, layout.positionOfPoint);
        boolean mirrorBindFrames = BindSpace.mirrorsBindFrames(skin);
        boolean mirrored = BindSpace.movePoints(skin, mirrorBindFrames, positions, normals);
        float[] bind = BindSpace.bindMatrices(skin, rows.needsBindShapeJoint, mirrorBindFrames);
        int[] jointNodes = jointNodes(instance, skin.jointCount(), rows.needsBindShapeJoint);
        int[] jointParents = Bones.jointParents(jointNodes, nodes);
        if (!layout.sharesPositions()) {
            // One point per position: nothing to share.
            return new SkinnedGeometry(instance, layout.vertexCount, positions, normals, rows.width, rows.joints,
                    rows.weights, jointNodes, bind, layout.pointOfPosition, null, null, mirrored, jointParents);
        }
        SkinnedGeometry shared = sharedPositions(instance, layout, positions, rows, jointNodes, bind, mirrored,
                jointParents);
        return new SkinnedGeometry(instance, layout.vertexCount, positions, normals, rows.width, rows.joints,
                rows.weights, jointNodes, bind, layout.pointOfPosition, layout.positionOfPoint, shared, mirrored,
                jointParents);
    }

    /** A static mesh: every point fully on one joint, the instance's node, with identity bind. */
    private static SkinnedGeometry unskinned(MeshInstance instance, PointLayout layout, float[] positions,
            float[] normals) {
        int points = layout.pointCount();
        float[] weights = new float[points];
        Arrays.fill(weights, 1f);
        return new SkinnedGeometry(instance, layout.vertexCount, positions, normals, 1, new int[points], weights,
                new int[] {instance.node()}, new Matrix4f().get(new float[16]), layout.pointOfPosition, null, null,
                false, new int[] {-1});
    }

    /** Scene node per palette joint: the skin's joints' nodes, then -1 for the bind-shape pseudo-joint. */
    private static int[] jointNodes(MeshInstance instance, int skinJoints, boolean bindShapeJoint) {
        int[] jointNodes = new int[skinJoints + (bindShapeJoint ? 1 : 0)];
        for (int j = 0; j < skinJoints; j++) {
            jointNodes[j] = instance.jointNode(j);
        }
        if (bindShapeJoint) {
            jointNodes[skinJoints] = -1;
        }
        return jointNodes;
    }

    /**
     * The position-level twin for kernels that skin each position once: its points are the mesh's
     * positions in source order, with zero normals and the same influences, joints and bind
     * matrices.
     */
    private static SkinnedGeometry sharedPositions(MeshInstance instance, PointLayout layout, float[] positions,
            SkinRows rows, int[] jointNodes, float[] bind, boolean mirrored, int[] jointParents) {
        int positionCount = layout.pointOfPosition.length;
        int w = rows.width;
        int[] rowJoints = new int[w * positionCount];
        float[] rowWeights = new float[w * positionCount];
        float[] sourcePositions = new float[3 * positionCount];
        int[] identity = new int[positionCount];
        for (int p = 0; p < positionCount; p++) {
            int point = layout.pointOfPosition[p];
            System.arraycopy(positions, 3 * point, sourcePositions, 3 * p, 3);
            // A position's influences are those of any point that carries it (they are per position).
            System.arraycopy(rows.joints, w * point, rowJoints, w * p, w);
            System.arraycopy(rows.weights, w * point, rowWeights, w * p, w);
            identity[p] = p;
        }
        return new SkinnedGeometry(instance, 0, sourcePositions, new float[3 * positionCount], w, rowJoints,
                rowWeights, jointNodes, bind, identity, null, null, mirrored, jointParents);
    }
}
