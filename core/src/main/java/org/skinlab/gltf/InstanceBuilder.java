package org.skinlab.gltf;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.joml.Matrix4f;
import org.skinlab.model.Material;
import org.skinlab.model.MaterialBinding;
import org.skinlab.model.Mesh;
import org.skinlab.model.MeshInstance;
import org.skinlab.model.Morph;
import org.skinlab.model.Skin;

/**
 * Places meshes at the scene's nodes: a node's {@code mesh} becomes a {@link MeshInstance}; its
 * {@code weights} (else the mesh's) give the {@link Morph} (RELATIVE: targets are offsets) whose
 * result it draws, one morph per mesh and distinct weights; its {@code skin} gives a
 * {@link Skin} of the mesh it draws (one per skin and drawn mesh), with joints anywhere in the
 * scene and the skin's {@code skeleton} as the instance's skeleton root.
 *
 * <p>The specification ignores a skinned mesh node's own transform: joints place the vertices.
 * The model's skinning path does the same (a skinned instance is placed by
 * {@code world(joint) * inverseBind * bindShape} only, never by its node), so the skin's bind
 * shape matrix is the identity and the node is recorded only as where the instance is.
 * Without {@code inverseBindMatrices} every inverse bind matrix is the identity; with them each
 * must be affine. A node with a skin or weights but no mesh is refused (the specification requires
 * the mesh).
 */
final class InstanceBuilder {
    /** Weight sums further than this from 1 are reported (8-bit normalised weights round by 1/255 each). */
    private static final float WEIGHT_SUM_TOLERANCE = 0.01f;

    private final GltfContext ctx;
    private final JsonNode nodes;
    private final JsonNode skins;
    private final Accessors accessors;
    private final SceneReader scene;
    private final MeshData[] meshes;
    private final MaterialReader materials;
    private final Map<String, Morph> morphs = new LinkedHashMap<>();
    private final Map<String, Skin> skinsByKey = new LinkedHashMap<>();
    private final Map<Integer, float[]> inverseBinds = new HashMap<>();
    private final List<MeshInstance> instances = new ArrayList<>();

    InstanceBuilder(GltfContext ctx, JsonNode root, Accessors accessors, SceneReader scene, MeshData[] meshes,
            MaterialReader materials) throws GltfException {
        this.ctx = ctx;
        this.nodes = root.get("nodes");
        this.skins = root.get("skins").arrayOrMissing();
        this.accessors = accessors;
        this.scene = scene;
        this.meshes = meshes;
        this.materials = materials;
    }

    /** Per glTF node, whether some skin lists it as a joint. */
    static boolean[] jointFlags(JsonNode root) throws GltfException {
        JsonNode nodes = root.get("nodes");
        boolean[] joint = new boolean[nodes.size()];
        JsonNode skins = root.get("skins").arrayOrMissing();
        for (int s = 0; s < skins.size(); s++) {
            JsonNode joints = skins.get(s).get("joints");
            if (joints.size() == 0) {
                throw joints.error("a skin needs at least one joint");
            }
            for (int j = 0; j < joints.size(); j++) {
                joint[joints.get(j).index(joint.length, "nodes")] = true;
            }
        }
        return joint;
    }

    void build() throws GltfException {
        checkSkins();
        for (int i = 0; i < scene.result.size(); i++) {
            int g = scene.gltfIndex.get(i);
            JsonNode node = nodes.get(g);
            JsonNode meshRef = node.get("mesh");
            if (meshRef.isMissing()) {
                for (String needsMesh : new String[] {"skin", "weights"}) {
                    if (node.has(needsMesh)) {
                        throw node.get(needsMesh).error("a node with " + needsMesh + " must have a mesh");
                    }
                }
                continue;
            }
            MeshData data = meshes[meshRef.index(meshes.length, "meshes")];
            if (data == null) {
                continue; // nothing drawable: the mesh reader warned
            }
            Mesh drawn = morphed(node, data);
            Skin skin = null;
            int[] jointNodes = new int[0];
            int[] skeleton = new int[0];
            JsonNode skinRef = node.get("skin");
            if (!skinRef.isMissing()) {
                int s = skinRef.index(skins.size(), "skins");
                skin = skin(s, data, drawn, skinRef);
                jointNodes = jointNodes(s);
                JsonNode skeletonRef = skins.get(s).get("skeleton");
                if (!skeletonRef.isMissing()) {
                    int root = scene.modelIndex[skeletonRef.index(nodes.size(), "nodes")];
                    skeleton = root < 0 ? skeleton : new int[] {root};
                }
            }
            instances.add(new MeshInstance(i, drawn, skin, jointNodes, skeleton, bindings(data, drawn)));
        }
    }

    /** Every skin's references, used by a node or not: skeleton, joints and inverse bind matrices. */
    private void checkSkins() throws GltfException {
        for (int s = 0; s < skins.size(); s++) {
            JsonNode skeleton = skins.get(s).get("skeleton");
            if (!skeleton.isMissing()) {
                skeleton.index(nodes.size(), "nodes");
            }
            JsonNode ibm = skins.get(s).get("inverseBindMatrices");
            if (!ibm.isMissing()) {
                accessors.resolve(ibm);
            }
        }
    }

    List<MeshInstance> instances() {
        return instances;
    }

    List<Morph> morphs() {
        return new ArrayList<>(morphs.values());
    }

    List<Skin> skins() {
        return new ArrayList<>(skinsByKey.values());
    }

    /** The mesh a node draws: the base, or the result of its morph with the node's weights. */
    private Mesh morphed(JsonNode node, MeshData data) throws GltfException {
        if (data.targetCount() == 0) {
            return data.mesh;
        }
        JsonNode weightsNode = node.get("weights");
        float[] weights = data.weights;
        if (!weightsNode.isMissing()) {
            if (weightsNode.size() != data.targetCount()) {
                throw weightsNode.error(weightsNode.size() + " weights for the " + data.targetCount()
                        + " morph targets of mesh " + data.index);
            }
            weights = weightsNode.floats();
        }
        String key = data.index + Arrays.toString(weights);
        Morph morph = morphs.get(key);
        if (morph == null) {
            Mesh base = data.mesh;
            long meshValues = 6L * base.positionCount() + 3L * base.triangleCount()
                    + (base.hasNormals() ? 3L : 0) * base.vertexCount() + (base.hasColors() ? 4L : 0) * base.vertexCount()
                    + 2L * base.texCoordSetCount() * base.vertexCount();
            // Each target is a mesh (the base's arrays copied) and the morph keeps its positions.
            ctx.charge((data.targetCount() + 1) * (meshValues + 3L * base.positionCount()), node.path());
            String id = weights == data.weights ? data.mesh.id() + "/weights" : node.path() + "/weights";
            // Targets are offsets (RELATIVE): positions, and normals when some target has NORMAL
            // (zero for the others); without any, targets have no normals and the base's stay.
            boolean normals = data.mesh.hasNormals() && Arrays.stream(data.targetNormals).anyMatch(n -> n != null);
            List<Mesh> targets = new ArrayList<>();
            for (int t = 0; t < data.targetCount(); t++) {
                float[] n = !normals ? null : data.targetNormals[t] != null ? data.targetNormals[t]
                        : new float[3 * data.mesh.vertexCount()];
                targets.add(data.mesh.withPositionsAndNormals(data.mesh.id() + "/targets/" + t, null,
                        data.targetPositions[t], n));
            }
            morph = new Morph(id, data.mesh.name(), data.mesh, Morph.Method.RELATIVE, targets, weights);
            morphs.put(key, morph);
        }
        return morph.result();
    }

    private Skin skin(int s, MeshData data, Mesh drawn, JsonNode skinRef) throws GltfException {
        String key = s + "|" + drawn.id();
        Skin skin = skinsByKey.get(key);
        if (skin != null) {
            return skin;
        }
        JsonNode skinNode = skins.get(s);
        if (data.primitiveWithoutJoints != null) {
            throw ctx.error(data.primitiveWithoutJoints, "node " + skinRef.path() + " skins this mesh, but the"
                    + " primitive has no JOINTS_0 and WEIGHTS_0");
        }
        int jointCount = skinNode.get("joints").size();
        if (data.maxJoint >= jointCount) {
            throw ctx.error(data.maxJointPath, "joint " + data.maxJoint + " is weighted, but skin " + s + " has "
                    + jointCount + " joints");
        }
        List<String> names = new ArrayList<>(jointCount);
        int[] jointNodes = jointNodes(s);
        for (int j = 0; j < jointCount; j++) {
            names.add(scene.result.get(jointNodes[j]).label());
        }
        warnWeightSums(data, s);
        skin = new Skin("/skins/" + s, skinNode.get("name").string(null), drawn, new Matrix4f(), names, false,
                inverseBinds(s, jointCount), data.influenceStart, data.influenceJoints, data.influenceWeights);
        skinsByKey.put(key, skin);
        return skin;
    }

    private int[] jointNodes(int s) throws GltfException {
        JsonNode joints = skins.get(s).get("joints");
        int[] result = new int[joints.size()];
        boolean[] listed = new boolean[nodes.size()];
        for (int j = 0; j < result.length; j++) {
            int g = joints.get(j).index(nodes.size(), "nodes");
            result[j] = scene.modelIndex[g];
            if (result[j] < 0) {
                throw joints.get(j).error("joint node " + g + " is not in the scene");
            }
            if (listed[g]) {
                throw joints.get(j).error("node " + g + " is listed twice");
            }
            listed[g] = true;
        }
        return result;
    }

    private float[] inverseBinds(int s, int jointCount) throws GltfException {
        float[] cached = inverseBinds.get(s);
        if (cached != null) {
            return cached;
        }
        JsonNode ref = skins.get(s).get("inverseBindMatrices");
        float[] result = new float[16 * jointCount];
        if (ref.isMissing()) {
            for (int j = 0; j < jointCount; j++) {
                new Matrix4f().get(result, 16 * j);
            }
        } else {
            int acc = accessors.resolve(ref);
            accessors.expect(acc, ref.path(), "MAT4", "5126");
            if (accessors.elementCount(acc) < jointCount) {
                throw ref.error("accessor " + acc + " has " + accessors.elementCount(acc) + " matrices for "
                        + jointCount + " joints");
            }
            // glTF's column-major matrices are what the model stores (JOML order): copied as they are.
            System.arraycopy(accessors.floats(acc), 0, result, 0, result.length);
            for (int j = 0; j < jointCount; j++) {
                int o = 16 * j;
                if (result[o + 3] != 0f || result[o + 7] != 0f || result[o + 11] != 0f || result[o + 15] != 1f) {
                    throw ref.error("inverse bind matrix " + j + " is not affine (its last row is not 0 0 0 1)");
                }
            }
        }
        inverseBinds.put(s, result);
        return result;
    }

    private void warnWeightSums(MeshData data, int s) {
        int off = 0;
        for (int p = 0; p + 1 < data.influenceStart.length; p++) {
            float sum = 0f;
            for (int i = data.influenceStart[p]; i < data.influenceStart[p + 1]; i++) {
                sum += data.influenceWeights[i];
            }
            if (Math.abs(sum - 1f) > WEIGHT_SUM_TOLERANCE) {
                off++;
            }
        }
        if (off > 0) {
            ctx.warn(data.mesh.id(), off + " vertices skinned by skin " + s + " have weights that do not sum to 1;"
                    + " the skinning divides by the sum");
        }
    }

    private List<MaterialBinding> bindings(MeshData data, Mesh drawn) {
        List<MaterialBinding> result = new ArrayList<>();
        java.util.Set<Integer> bound = new java.util.HashSet<>();
        for (int m : data.partMaterials) {
            if (m < 0 || !bound.add(m)) {
                continue;
            }
            String symbol = GltfImporter.materialSymbol(m);
            Material material = materials.materials().get(m);
            int texCoord = materials.baseTexCoord(m);
            int set = material.baseTexture() == null || texCoord < 0 ? -1 : drawn.texCoordSetIndex(texCoord);
            result.add(new MaterialBinding(symbol, material, set));
        }
        return result;
    }
}
