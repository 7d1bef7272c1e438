package org.skinlab.jme;

import java.nio.FloatBuffer;

import com.jme3.scene.Geometry;
import com.jme3.scene.Mesh;
import com.jme3.scene.VertexBuffer;
import com.jme3.scene.VertexBuffer.Type;
import com.jme3.scene.mesh.IndexBuffer;
import org.skinlab.skinning.CentresOfRotation;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinningMethod;

/**
 * A jME skinned mesh as skinlab's runtime geometry, built once when the control is attached: its
 * bind buffers (BindPosePosition, BindPoseNormal, which jME keeps beside the Position and Normal it
 * renders) become the points, one per jME vertex in vertex order; BoneIndex and BoneWeight the
 * influences, remapped to the palette's joint order ({@link ArmaturePalette}), sorted heaviest
 * first (the DQS pivot) and divided by their sum, as skinlab's importers do.
 *
 * <p>CoR's centres come from the {@link #CENTRES} buffer when the mesh has one (put there by
 * {@link SkinlabGltfExtension} from a skinlab-exported glb's {@code _COR_CENTER}), else they are
 * computed here over the mesh's triangles ({@link CentresOfRotation}) and stored in that buffer, where
 * the GPU path's shader reads them.
 */
final class MeshBinding {
    /** The vertex buffer that holds CoR's centre per vertex (3 floats, bind space). */
    static final Type CENTRES = Type.TexCoord8;

    private MeshBinding() {
    }

    /**
     * The runtime geometry of {@code geometry}'s mesh for {@code method}.
     *
     * @throws IllegalArgumentException naming the geometry when its mesh is not skinned, or a
     *                                  vertex has no weight
     */
    static SkinnedGeometry bind(Geometry geometry, ArmaturePalette palette, SkinningMethod method) {
        Mesh mesh = geometry.getMesh();
        String name = "geometry '" + geometry.getName() + "'";
        VertexBuffer positionBuffer = buffer(mesh, Type.BindPosePosition, Type.Position);
        VertexBuffer indexBuffer = mesh.getBuffer(Type.BoneIndex);
        VertexBuffer weightBuffer = mesh.getBuffer(Type.BoneWeight);
        if (positionBuffer == null || indexBuffer == null || weightBuffer == null) {
            throw new IllegalArgumentException(name + " is not skinned: it needs Position, BoneIndex and BoneWeight buffers");
        }
        int vertices = mesh.getVertexCount();
        float[] positions = floats((FloatBuffer) positionBuffer.getData(), 3 * vertices);
        VertexBuffer normalBuffer = buffer(mesh, Type.BindPoseNormal, Type.Normal);
        float[] normals = normalBuffer == null ? new float[3 * vertices]
                : floats((FloatBuffer) normalBuffer.getData(), 3 * vertices);
        int influences = Math.max(1, Math.min(4, mesh.getMaxNumWeights()));
        int[] joints = new int[influences * vertices];
        float[] weights = new float[influences * vertices];
        IndexBuffer jmeJoints = IndexBuffer.wrapIndexBuffer(indexBuffer.getData());
        FloatBuffer jmeWeights = (FloatBuffer) weightBuffer.getData();
        int[] slotJoint = new int[4];
        float[] slotWeight = new float[4];
        for (int v = 0; v < vertices; v++) {
            float sum = 0;
            for (int s = 0; s < 4; s++) {
                slotWeight[s] = jmeWeights.get(4 * v + s);
                slotJoint[s] = jmeJoints.get(4 * v + s);
                sum += slotWeight[s];
            }
            if (!(sum > 0)) {
                throw new IllegalArgumentException(name + ", vertex " + v + ": no skin weight"
                        + " (skinlab's control needs every vertex of a skinned mesh weighted)");
            }
            sortByWeight(slotJoint, slotWeight);
            for (int s = 0; s < influences; s++) {
                boolean used = slotWeight[s] > 0;
                int jmeJoint = used ? slotJoint[s] : slotJoint[0];
                if (jmeJoint < 0 || jmeJoint >= palette.jointCount()) {
                    throw new IllegalArgumentException(name + ", vertex " + v + ": joint " + jmeJoint
                            + " outside the armature's " + palette.jointCount());
                }
                joints[influences * v + s] = palette.paletteIndex(jmeJoint);
                weights[influences * v + s] = used ? slotWeight[s] / sum : 0f;
            }
        }
        SkinnedGeometry skinned = SkinnedGeometry.fromArrays(positions, normals, influences, joints, weights,
                palette.bindMatrices(), palette.parents());
        return method == SkinningMethod.COR ? skinned.withCentresOfRotation(centres(mesh, skinned)) : skinned;
    }

    /** The centres from {@link #CENTRES}, or computed and stored there. */
    private static float[] centres(Mesh mesh, SkinnedGeometry skinned) {
        VertexBuffer stored = mesh.getBuffer(CENTRES);
        int vertices = skinned.pointCount();
        if (stored != null && stored.getNumComponents() == 3 && stored.getData() instanceof FloatBuffer) {
            return floats((FloatBuffer) stored.getData(), 3 * vertices);
        }
        if (stored != null) {
            throw new IllegalArgumentException("the mesh uses " + CENTRES + " for something else than CoR's centres"
                    + " (" + stored.getNumComponents() + " components)");
        }
        float[] centres = CentresOfRotation.compute(skinned, triangles(mesh), CentresOfRotation.Parameters.DEFAULT,
                CentresOfRotation.Progress.NONE);
        mesh.setBuffer(CENTRES, 3, centres.clone());
        return centres;
    }

    private static int[] triangles(Mesh mesh) {
        if (mesh.getMode() != Mesh.Mode.Triangles) {
            return new int[0];
        }
        VertexBuffer index = mesh.getBuffer(Type.Index);
        if (index == null) {
            int[] t = new int[mesh.getVertexCount() / 3 * 3];
            for (int i = 0; i < t.length; i++) {
                t[i] = i;
            }
            return t;
        }
        IndexBuffer ib = IndexBuffer.wrapIndexBuffer(index.getData());
        int[] t = new int[ib.size() / 3 * 3];
        for (int i = 0; i < t.length; i++) {
            t[i] = ib.get(i);
        }
        return t;
    }

    /** Insertion sort of four slots by decreasing weight, stable (equal weights keep their order). */
    private static void sortByWeight(int[] joint, float[] weight) {
        for (int i = 1; i < 4; i++) {
            int j = joint[i];
            float w = weight[i];
            int k = i - 1;
            while (k >= 0 && weight[k] < w) {
                joint[k + 1] = joint[k];
                weight[k + 1] = weight[k];
                k--;
            }
            joint[k + 1] = j;
            weight[k + 1] = w;
        }
    }

    private static VertexBuffer buffer(Mesh mesh, Type preferred, Type fallback) {
        VertexBuffer b = mesh.getBuffer(preferred);
        return b != null ? b : mesh.getBuffer(fallback);
    }

    private static float[] floats(FloatBuffer buffer, int count) {
        float[] a = new float[count];
        for (int i = 0; i < count; i++) {
            a[i] = buffer.get(i);
        }
        return a;
    }
}
