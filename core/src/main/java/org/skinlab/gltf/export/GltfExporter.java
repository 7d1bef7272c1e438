package org.skinlab.gltf.export;

import java.io.BufferedOutputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;

import org.skinlab.animation.Skeleton;
import org.skinlab.model.AnimationClip;
import org.skinlab.model.MeshInstance;
import org.skinlab.model.Model;
import org.skinlab.skinning.CentresOfRotation;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinningMethod;

import com.fasterxml.jackson.core.JsonEncoding;
import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonGenerator;

/**
 * Writes a {@link Model} as a binary glTF 2.0 file (GLB) with the bind-time data skinlab's skinning
 * methods need beyond glTF's own: per skinned primitive the {@value MeshExport#EXTENSION} object
 * naming the methods, and for CoR the vertex attribute {@value MeshExport#COR_ATTRIBUTE} (each
 * vertex's centre of rotation, computed here by {@link CentresOfRotation} with the paper's
 * parameters, in the space of POSITION). The layout, the extension's schema and what is converted
 * how (bind shape, up axis, resampled clips) are in docs/integrations.md. A COLLADA
 * document that is not Y-up in metres gets a root node that makes it so; the model's own
 * coordinates are written unchanged beneath it.
 *
 * <p>Offline work: computing the centres takes up to a second per large character. Thread-safe:
 * each call works on its own state.
 */
public final class GltfExporter {
    /** The methods whose data the export can carry (LBS and DQS need none beyond glTF's skin). */
    public static final Set<SkinningMethod> METHODS = Set.copyOf(EnumSet.of(SkinningMethod.LBS, SkinningMethod.DQS,
            SkinningMethod.COR));

    private static final int GLB_MAGIC = 0x46546C67;
    private static final int CHUNK_JSON = 0x4E4F534A;
    private static final int CHUNK_BIN = 0x004E4942;

    private GltfExporter() {
    }

    /**
     * Writes the model as a GLB file.
     *
     * @param model   the model to write
     * @param methods the methods the skinned primitives declare, a non-empty subset of {@link #METHODS}
     * @param file    the file to write (replaced when it exists)
     * @return what was written
     * @throws IOException              when the file cannot be written
     * @throws IllegalArgumentException when {@code methods} is empty or holds a method outside {@link #METHODS}
     */
    public static ExportResult write(Model model, Set<SkinningMethod> methods, Path file) throws IOException {
        // Written beside the target and moved into place: a failed export leaves no half file.
        Path folder = file.toAbsolutePath().getParent();
        Path partial = Files.createTempFile(folder, ".skinlab-export-", ".glb.part");
        try {
            ExportResult result;
            try (OutputStream out = new BufferedOutputStream(Files.newOutputStream(partial))) {
                result = write(model, methods, out);
            }
            try {
                Files.move(partial, file, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
            } catch (AtomicMoveNotSupportedException e) {
                Files.move(partial, file, StandardCopyOption.REPLACE_EXISTING);
            }
            return result;
        } finally {
            Files.deleteIfExists(partial);
        }
    }

    /**
     * Writes the model as GLB bytes to a stream (not closed).
     *
     * @param model   the model to write
     * @param methods the methods the skinned primitives declare, a non-empty subset of {@link #METHODS}
     * @param out     receives the GLB
     * @return what was written
     * @throws IOException              when writing to the stream fails
     * @throws IllegalArgumentException when {@code methods} is empty or holds a method outside {@link #METHODS}
     */
    public static ExportResult write(Model model, Set<SkinningMethod> methods, OutputStream out) throws IOException {
        if (methods.isEmpty() || !METHODS.containsAll(methods)) {
            throw new IllegalArgumentException("the export carries data for lbs, dqs and cor only, not " + methods);
        }
        List<String> keys = new ArrayList<>();
        for (SkinningMethod m : EnumSet.copyOf(methods)) {
            keys.add(m.key());
        }
        List<String> warnings = new ArrayList<>();
        Set<String> extensions = new TreeSet<>();
        BinaryChunk bin = new BinaryChunk();
        MaterialExport materials = new MaterialExport(bin, warnings, extensions);
        MeshExport meshes = new MeshExport(bin, materials, keys, warnings);

        List<SkinnedGeometry> geometries = new ArrayList<>();
        boolean documentFrame = false;
        for (MeshInstance instance : model.instances()) {
            SkinnedGeometry g = instance.isSkinned() ? SkinnedGeometry.of(instance, model.nodes()) : null;
            geometries.add(g);
            for (int j = 0; g != null && j < g.jointCount(); j++) {
                documentFrame |= g.jointNode(j) < 0;
            }
        }
        Skeleton skeleton = Skeleton.of(model);
        NodeLayout nodes = new NodeLayout(model, skeleton, ClipExport.animatedNodes(model), documentFrame);
        int[] instanceNodes = new int[model.instances().size()];
        for (int i = 0; i < instanceNodes.length; i++) {
            MeshInstance instance = model.instances().get(i);
            SkinnedGeometry g = geometries.get(i);
            float[] centres = g != null && methods.contains(SkinningMethod.COR)
                    ? CentresOfRotation.computeOrLoad(g, CentresOfRotation.Parameters.DEFAULT,
                            CentresOfRotation.Progress.NONE)
                    : null;
            int mesh = meshes.mesh(model, instance, g, centres);
            String name = instance.mesh().name() != null ? instance.mesh().name() : model.node(instance.node()).label();
            int node = g != null ? nodes.skinnedMeshNode(instance.node(), name) : nodes.staticMeshNode(instance.node(), name);
            instanceNodes[i] = node;
            nodes.get(node).mesh = mesh;
            nodes.get(node).weights = meshes.weights(mesh);
            if (g != null) {
                int[] joints = new int[g.jointCount()];
                for (int j = 0; j < joints.length; j++) {
                    joints[j] = g.jointNode(j) < 0 ? nodes.documentFrame() : nodes.node(g.jointNode(j));
                }
                nodes.get(node).skin = meshes.skin(instance.skin().name(), g,
                        nodes.withTransformedAncestors(nodes.jointNodes(joints)));
            }
        }
        ClipExport clips = new ClipExport(model, skeleton, nodes, instanceNodes, bin, warnings);
        for (AnimationClip clip : model.clips()) {
            clips.clip(clip);
        }
        if (!geometries.stream().allMatch(g -> g == null)) {
            extensions.add(MeshExport.EXTENSION);
        }
        byte[] json = json(model, nodes, meshes, materials, clips, bin, extensions);
        int jsonLength = (json.length + 3) & ~3;
        long total = 12L + 8 + jsonLength + 8 + bin.paddedLength();
        ByteBuffer header = ByteBuffer.allocate(20).order(ByteOrder.LITTLE_ENDIAN);
        header.putInt(GLB_MAGIC).putInt(2).putInt((int) total).putInt(jsonLength).putInt(CHUNK_JSON);
        out.write(header.array());
        out.write(json);
        for (int i = json.length; i < jsonLength; i++) {
            out.write(' ');
        }
        ByteBuffer binHeader = ByteBuffer.allocate(8).order(ByteOrder.LITTLE_ENDIAN);
        binHeader.putInt(bin.paddedLength()).putInt(CHUNK_BIN);
        out.write(binHeader.array());
        bin.writeTo(out);
        out.flush();
        return new ExportResult(meshes.meshCount(), meshes.vertexCount(), clips.clipCount(), keys, total, warnings);
    }

    private static byte[] json(Model model, NodeLayout nodes, MeshExport meshes, MaterialExport materials,
            ClipExport clips, BinaryChunk bin, Set<String> extensions) throws IOException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (JsonGenerator g = new JsonFactory().createGenerator(bytes, JsonEncoding.UTF8)) {
            g.writeStartObject();
            g.writeObjectFieldStart("asset");
            g.writeStringField("version", "2.0");
            g.writeStringField("generator", "skinlab glTF exporter (from " + model.source() + ")");
            g.writeEndObject();
            nodes.writeJson(g);
            meshes.writeJson(g);
            // Materials before extensionsUsed: writing them finds KHR_texture_transform.
            materials.writeJson(g);
            clips.writeJson(g);
            bin.writeJson(g);
            if (!extensions.isEmpty()) {
                g.writeArrayFieldStart("extensionsUsed");
                for (String e : extensions) {
                    g.writeString(e);
                }
                g.writeEndArray();
            }
            g.writeEndObject();
        }
        return bytes.toByteArray();
    }
}
