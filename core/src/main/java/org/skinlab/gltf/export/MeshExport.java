package org.skinlab.gltf.export;

import java.io.IOException;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

import org.joml.Matrix3f;
import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.skinlab.model.MaterialBinding;
import org.skinlab.model.Mesh;
import org.skinlab.model.MeshInstance;
import org.skinlab.model.MeshPart;
import org.skinlab.model.Model;
import org.skinlab.model.Morph;
import org.skinlab.skinning.SkinnedGeometry;

import com.fasterxml.jackson.core.JsonGenerator;

/**
 * One glTF mesh (and skin) per placed mesh. glTF vertices are the mesh's vertices; each
 * {@link MeshPart} is a primitive over the same vertex accessors with its own indices and material.
 *
 * <p>A skinned mesh is written in bind space, as skinlab skins it ({@link SkinnedGeometry}): the
 * bind shape matrix (and the common mirror of the bind frames, when they all mirror) is baked into
 * POSITION and NORMAL, and the inverse bind matrices are the geometry's, so
 * {@code world(joint) * inverseBind * POSITION} is the skinned point. Influences are the
 * geometry's: heaviest first, divided by their sum, padded slots joint 0 weight 0, four per set
 * ({@code JOINTS_n}/{@code WEIGHTS_n}). A joint the skin lacks a node for (COLLADA's joint -1,
 * unweighted positions) is a node in the document's frame. With {@code cor}, {@code _COR_CENTER}
 * holds each vertex's centre of rotation, in the space of POSITION. A morphed mesh is its base with
 * the targets as offsets (a NORMALIZED morph's target minus the base) and the file's weights as
 * the mesh's {@code weights}, mapped into bind space alike.
 */
final class MeshExport {
    static final String EXTENSION = "SKINLAB_skinning";
    static final String COR_ATTRIBUTE = "_COR_CENTER";

    /** A primitive: its indices and material; attributes and targets are the mesh's. */
    private record Primitive(int indices, int material) {
    }

    /** A written mesh. */
    private record GltfMesh(String name, Map<String, Integer> attributes, List<Map<String, Integer>> targets,
            float[] weights, List<Primitive> primitives, boolean skinned) {
    }

    /** A written skin. */
    private record GltfSkin(String name, int[] joints, int inverseBindMatrices) {
    }

    private final BinaryChunk bin;
    private final MaterialExport materials;
    private final List<String> methodKeys;
    private final boolean cor;
    private final List<String> warnings;
    private final List<GltfMesh> meshes = new ArrayList<>();
    private final List<GltfSkin> skins = new ArrayList<>();
    private int vertices;

    MeshExport(BinaryChunk bin, MaterialExport materials, List<String> methodKeys, List<String> warnings) {
        this.bin = bin;
        this.materials = materials;
        this.methodKeys = methodKeys;
        this.cor = methodKeys.contains("cor");
        this.warnings = warnings;
    }

    int meshCount() {
        return meshes.size();
    }

    int vertexCount() {
        return vertices;
    }

    /**
     * Writes the mesh {@code instance} draws; {@code geometry} is its skinned geometry (null for a
     * static mesh), {@code centres} its centres of rotation per point (null without cor).
     *
     * @return the glTF mesh index
     */
    int mesh(Model model, MeshInstance instance, SkinnedGeometry geometry, float[] centres) {
        Mesh mesh = instance.mesh();
        int vc = mesh.vertexCount();
        vertices += vc;
        Optional<Morph> morph = model.morphOf(instance);
        Matrix4f bind = geometry != null ? SkinnedGeometry.bindSpaceTransform(instance) : new Matrix4f();
        float[] positions;
        float[] normals;
        Map<String, Integer> attributes = new LinkedHashMap<>();
        List<Map<String, Integer>> targets = new ArrayList<>();
        float[] weights = null;
        if (morph.isPresent()) {
            Morph m = morph.get();
            positions = perVertex(mesh, m.base().positions(), bind, false);
            normals = m.base().hasNormals() && mesh.hasNormals()
                    ? transformNormalOffsets(m.base().normals(), bind) : null;
            boolean relative = m.method() == Morph.Method.RELATIVE;
            float[] basePositions = m.base().positions();
            float[] baseNormals = m.base().normals();
            for (Mesh t : m.targets()) {
                float[] offsets = t.positions();
                if (!relative) {
                    for (int i = 0; i < basePositions.length; i++) {
                        offsets[i] -= basePositions[i];
                    }
                }
                Map<String, Integer> target = new LinkedHashMap<>();
                target.put("POSITION", bin.floats(perVertex(mesh, offsets, bind, true), "VEC3", 3, BinaryChunk.ARRAY_BUFFER,
                        true));
                if (m.morphsNormals() && normals != null) {
                    float[] n = t.normals();
                    if (!relative) {
                        for (int i = 0; i < n.length; i++) {
                            n[i] -= baseNormals[i];
                        }
                    }
                    target.put("NORMAL", bin.floats(transformNormalOffsets(n, bind), "VEC3", 3, BinaryChunk.ARRAY_BUFFER,
                            false));
                }
                targets.add(target);
            }
            weights = m.weights();
        } else if (geometry != null) {
            positions = java.util.Arrays.copyOf(geometry.positionArray(), 3 * vc);
            normals = mesh.hasNormals() ? java.util.Arrays.copyOf(geometry.normalArray(), 3 * vc) : null;
        } else {
            positions = perVertex(mesh, mesh.positions(), bind, false);
            normals = mesh.normals();
        }
        int[] triangles = mesh.triangles();
        if (geometry != null && geometry.windingMirrored()) {
            // Bind space mirrors the file's mesh: keep the triangles front-facing against their normals.
            for (int i = 0; i < triangles.length; i += 3) {
                int b = triangles[i + 1];
                triangles[i + 1] = triangles[i + 2];
                triangles[i + 2] = b;
            }
        }
        attributes.put("POSITION", bin.floats(positions, "VEC3", 3, BinaryChunk.ARRAY_BUFFER, true));
        if (normals != null) {
            attributes.put("NORMAL", bin.floats(unitNormals(normals, positions, triangles, mesh),
                    "VEC3", 3, BinaryChunk.ARRAY_BUFFER, false));
        }
        for (int s = 0; s < mesh.texCoordSetCount(); s++) {
            float[] uv = mesh.texCoords(s);
            for (int i = 1; i < uv.length; i += 2) {
                uv[i] = 1f - uv[i]; // the model's v runs up from the image's bottom, glTF's down from its top
            }
            attributes.put("TEXCOORD_" + s, bin.floats(uv, "VEC2", 2, BinaryChunk.ARRAY_BUFFER, false));
        }
        if (mesh.hasColors()) {
            attributes.put("COLOR_0", bin.floats(mesh.colors(), "VEC4", 4, BinaryChunk.ARRAY_BUFFER, false));
        }
        if (geometry != null) {
            new InfluenceSets(geometry, vc).write(bin, attributes);
            if (cor) {
                attributes.put(COR_ATTRIBUTE, bin.floats(java.util.Arrays.copyOf(centres, 3 * vc), "VEC3", 3,
                        BinaryChunk.ARRAY_BUFFER, false));
            }
        }
        List<Primitive> primitives = new ArrayList<>();
        int indexType = vc <= 0xffff ? BinaryChunk.UNSIGNED_SHORT : BinaryChunk.UNSIGNED_INT;
        for (MeshPart part : mesh.parts()) {
            if (part.triangleCount() == 0) {
                continue;
            }
            int[] indices = java.util.Arrays.copyOfRange(triangles, 3 * part.firstTriangle(),
                    3 * (part.firstTriangle() + part.triangleCount()));
            MaterialBinding binding = instance.material(part.material());
            primitives.add(new Primitive(bin.ints(indices, "SCALAR", 1, indexType, BinaryChunk.ELEMENT_ARRAY_BUFFER),
                    materials.material(binding.material(), binding.texCoordSet())));
        }
        meshes.add(new GltfMesh(mesh.name(), attributes, targets, weights, primitives, geometry != null));
        return meshes.size() - 1;
    }

    /** The mesh's weights (null without a morph) of mesh {@code m}, for its node. */
    float[] weights(int m) {
        return meshes.get(m).weights;
    }

    /** Writes the skin of {@code geometry} with the given joint nodes (one per palette joint). */
    int skin(String name, SkinnedGeometry geometry, int[] jointNodes) {
        // Joints past the geometry's are ancestors no vertex is bound to (NodeLayout.withTransformedAncestors).
        float[] matrices = java.util.Arrays.copyOf(geometry.bindMatrixArray(), 16 * jointNodes.length);
        for (int j = geometry.jointCount(); j < jointNodes.length; j++) {
            new Matrix4f().get(matrices, 16 * j);
        }
        int ibm = bin.floats(matrices, "MAT4", 16, 0, false);
        skins.add(new GltfSkin(name, jointNodes, ibm));
        return skins.size() - 1;
    }

    /** Per vertex the position given per mesh position, through {@code m} (a direction when {@code offset}). */
    private static float[] perVertex(Mesh mesh, float[] perPosition, Matrix4f m, boolean offset) {
        int[] vp = mesh.vertexPositions();
        float[] out = new float[3 * vp.length];
        Vector3f v = new Vector3f();
        for (int i = 0; i < vp.length; i++) {
            int p = 3 * vp[i];
            v.set(perPosition[p], perPosition[p + 1], perPosition[p + 2]);
            if (offset) {
                m.transformDirection(v);
            } else {
                m.transformPosition(v);
            }
            out[3 * i] = v.x;
            out[3 * i + 1] = v.y;
            out[3 * i + 2] = v.z;
        }
        return out;
    }

    /** Normals, or their morph offsets, by the inverse-transpose of {@code m} (cofactor, sign of the determinant). */
    private static float[] transformNormalOffsets(float[] normals, Matrix4f m) {
        Matrix3f c = new Matrix3f();
        m.get3x3(c).cofactor();
        if (m.determinant3x3() < 0f) {
            c.scale(-1f);
        }
        float[] out = normals.clone();
        Vector3f v = new Vector3f();
        for (int i = 0; i < out.length; i += 3) {
            c.transform(v.set(out[i], out[i + 1], out[i + 2]));
            out[i] = v.x;
            out[i + 1] = v.y;
            out[i + 2] = v.z;
        }
        return out;
    }

    /**
     * Normals of unit length, as glTF requires: each normalised, and a zero one (a primitive the
     * file gave none) replaced by the normalised sum of its triangles' normals.
     */
    private float[] unitNormals(float[] normals, float[] positions, int[] triangles, Mesh mesh) {
        float[] out = normals.clone();
        boolean[] zero = new boolean[out.length / 3];
        int zeros = 0;
        for (int i = 0; i < zero.length; i++) {
            double x = out[3 * i];
            double y = out[3 * i + 1];
            double z = out[3 * i + 2];
            double len = Math.sqrt(x * x + y * y + z * z);
            if (len > 1e-12 && Double.isFinite(len)) {
                out[3 * i] = (float) (x / len);
                out[3 * i + 1] = (float) (y / len);
                out[3 * i + 2] = (float) (z / len);
            } else {
                zero[i] = true;
                zeros++;
                out[3 * i] = 0f;
                out[3 * i + 1] = 0f;
                out[3 * i + 2] = 0f;
            }
        }
        if (zeros == 0) {
            return out;
        }
        Vector3f a = new Vector3f();
        Vector3f b = new Vector3f();
        for (int t = 0; t < triangles.length; t += 3) {
            int i0 = triangles[t];
            int i1 = triangles[t + 1];
            int i2 = triangles[t + 2];
            a.set(positions[3 * i1] - positions[3 * i0], positions[3 * i1 + 1] - positions[3 * i0 + 1],
                    positions[3 * i1 + 2] - positions[3 * i0 + 2]);
            b.set(positions[3 * i2] - positions[3 * i0], positions[3 * i2 + 1] - positions[3 * i0 + 1],
                    positions[3 * i2 + 2] - positions[3 * i0 + 2]);
            a.cross(b);
            for (int i : new int[] {i0, i1, i2}) {
                if (zero[i]) {
                    out[3 * i] += a.x;
                    out[3 * i + 1] += a.y;
                    out[3 * i + 2] += a.z;
                }
            }
        }
        for (int i = 0; i < zero.length; i++) {
            if (zero[i]) {
                Vector3f n = new Vector3f(out[3 * i], out[3 * i + 1], out[3 * i + 2]);
                if (!(n.lengthSquared() > 0f)) {
                    n.set(0f, 1f, 0f);
                }
                n.normalize();
                out[3 * i] = n.x;
                out[3 * i + 1] = n.y;
                out[3 * i + 2] = n.z;
            }
        }
        warnings.add(mesh.id() + ": " + zeros + " vertices have no normal; given their triangles' normal");
        return out;
    }

    /** {@code meshes} and {@code skins}. */
    void writeJson(JsonGenerator g) throws IOException {
        if (!meshes.isEmpty()) {
            g.writeArrayFieldStart("meshes");
            for (GltfMesh m : meshes) {
                writeMesh(g, m);
            }
            g.writeEndArray();
        }
        if (!skins.isEmpty()) {
            g.writeArrayFieldStart("skins");
            for (GltfSkin s : skins) {
                g.writeStartObject();
                if (s.name != null) {
                    g.writeStringField("name", s.name);
                }
                g.writeNumberField("inverseBindMatrices", s.inverseBindMatrices);
                g.writeArrayFieldStart("joints");
                for (int j : s.joints) {
                    g.writeNumber(j);
                }
                g.writeEndArray();
                g.writeEndObject();
            }
            g.writeEndArray();
        }
    }

    private void writeMesh(JsonGenerator g, GltfMesh m) throws IOException {
        g.writeStartObject();
        if (m.name != null) {
            g.writeStringField("name", m.name);
        }
        g.writeArrayFieldStart("primitives");
        for (Primitive p : m.primitives) {
            g.writeStartObject();
            writeMap(g, "attributes", m.attributes);
            g.writeNumberField("indices", p.indices);
            if (p.material >= 0) {
                g.writeNumberField("material", p.material);
            }
            g.writeNumberField("mode", 4);
            if (!m.targets.isEmpty()) {
                g.writeArrayFieldStart("targets");
                for (Map<String, Integer> t : m.targets) {
                    writeMap(g, null, t);
                }
                g.writeEndArray();
            }
            if (m.skinned) {
                writeExtension(g);
            }
            g.writeEndObject();
        }
        g.writeEndArray();
        if (m.weights != null) {
            BinaryChunk.writeFloats(g, "weights", m.weights);
        }
        g.writeEndObject();
    }

    /** The primitive's {@value #EXTENSION} object (docs/integrations.md). */
    private void writeExtension(JsonGenerator g) throws IOException {
        g.writeObjectFieldStart("extensions");
        g.writeObjectFieldStart(EXTENSION);
        g.writeArrayFieldStart("methods");
        for (String k : methodKeys) {
            g.writeString(k);
        }
        g.writeEndArray();
        g.writeObjectFieldStart("attributes");
        if (cor) {
            g.writeStringField("cor", COR_ATTRIBUTE);
        }
        g.writeEndObject();
        g.writeNumberField("version", 1);
        g.writeEndObject();
        g.writeEndObject();
    }

    private static void writeMap(JsonGenerator g, String name, Map<String, Integer> map) throws IOException {
        if (name != null) {
            g.writeObjectFieldStart(name);
        } else {
            g.writeStartObject();
        }
        for (Map.Entry<String, Integer> e : map.entrySet()) {
            g.writeNumberField(e.getKey(), e.getValue());
        }
        g.writeEndObject();
    }
}
