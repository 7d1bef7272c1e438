package org.skinlab.internal.scene;

import java.util.List;

import org.skinlab.model.Mesh;
import org.skinlab.model.MeshPart;
import org.skinlab.skinning.SkinnedGeometry;

/**
 * Where each triangle run of a geometry is, for drawing blended parts back to front: per part the
 * centre of its vertices in bind space and the joint that weighs most on them, so a frame places
 * the centre with that joint's skinning matrix (one point per part: exact for rigid parts, close
 * enough to order translucent parts of a character). Built once per geometry; {@link #posed}
 * allocates nothing.
 */
public final class PartCentres {
    private final float[] centres;
    private final int[] joints;

    private PartCentres(float[] centres, int[] joints) {
        this.centres = centres;
        this.joints = joints;
    }

    /** The centres of {@code geometry}'s mesh parts, in {@link Mesh#parts()} order. */
    public static PartCentres of(SkinnedGeometry geometry) {
        Mesh mesh = geometry.mesh();
        List<MeshPart> parts = mesh == null ? List.of() : mesh.parts();
        float[] centres = new float[3 * parts.size()];
        int[] joints = new int[parts.size()];
        float[] positions = geometry.positionArray();
        int[] jointArray = geometry.jointArray();
        float[] weights = geometry.weightArray();
        int k = geometry.influencesPerPoint();
        float[] weightOfJoint = new float[Math.max(1, geometry.jointCount())];
        for (int i = 0; i < parts.size(); i++) {
            MeshPart part = parts.get(i);
            java.util.Arrays.fill(weightOfJoint, 0f);
            int corners = 3 * part.triangleCount();
            for (int c = 0; c < corners; c++) {
                int v = mesh.triangleVertex(part.firstTriangle() + c / 3, c % 3);
                for (int a = 0; a < 3; a++) {
                    centres[3 * i + a] += positions[3 * v + a] / corners;
                }
                for (int s = 0; s < k; s++) {
                    weightOfJoint[jointArray[k * v + s]] += weights[k * v + s];
                }
            }
            joints[i] = heaviest(weightOfJoint);
        }
        return new PartCentres(centres, joints);
    }

    private static int heaviest(float[] weights) {
        int best = 0;
        for (int j = 1; j < weights.length; j++) {
            if (weights[j] > weights[best]) {
                best = j;
            }
        }
        return best;
    }

    public int partCount() {
        return joints.length;
    }

    /**
     * Writes part {@code i}'s centre, moved by its joint's skinning matrix in
     * {@code skinningMatrices} (the frame's rows, {@code Frame.skinningMatrices}), into
     * {@code dest[3i..3i+2]}.
     */
    public void posed(int i, float[] skinningMatrices, float[] dest) {
        int m = 12 * joints[i];
        float x = centres[3 * i];
        float y = centres[3 * i + 1];
        float z = centres[3 * i + 2];
        for (int row = 0; row < 3; row++) {
            int r = m + 4 * row;
            dest[3 * i + row] = skinningMatrices[r] * x + skinningMatrices[r + 1] * y + skinningMatrices[r + 2] * z
                    + skinningMatrices[r + 3];
        }
    }

    /**
     * Whether the first joint's skinning matrix mirrors (negative determinant): the triangles then
     * reach the screen with their winding reversed, so a renderer culling back faces flips its
     * front face (glTF 2.0, 3.7.2.1: a node's negative determinant reverses the winding). For a
     * static mesh that joint is its node; a skin's matrices are rigid unless its joints mirror.
     */
    public static boolean firstJointMirrors(float[] skinningMatrices) {
        float[] m = skinningMatrices;
        float det = m[0] * (m[5] * m[10] - m[6] * m[9]) - m[1] * (m[4] * m[10] - m[6] * m[8])
                + m[2] * (m[4] * m[9] - m[5] * m[8]);
        return det < 0f;
    }
}
