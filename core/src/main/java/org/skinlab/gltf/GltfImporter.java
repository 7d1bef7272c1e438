package org.skinlab.gltf;

import java.io.BufferedInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.skinlab.model.AnimationClip;
import org.skinlab.model.AssetInfo;
import org.skinlab.model.Mesh;
import org.skinlab.model.Model;
import org.skinlab.model.Morph;
import org.skinlab.model.UpAxis;

/**
 * Reads a glTF 2.0 document ({@code .gltf} JSON, or binary {@code .glb}, told apart by the GLB
 * magic, not the name) into an immutable {@link Model}.
 *
 * <p>Pipeline: the bytes ({@link GlbContainer}), the JSON tree ({@link JsonTree}), the buffers and
 * views ({@link Buffers}, with {@link UriResolver} guarding every URI), accessors
 * ({@link Accessors}), materials ({@link MaterialReader}), meshes ({@link MeshReader}), the scene
 * ({@link SceneReader}), skins, morphs and mesh instances ({@link InstanceBuilder}) and animations
 * ({@link AnimationReader}). glTF's frame is Y-up, in metres.
 *
 * <p>Every problem that makes the file unusable is a {@link GltfException} naming the file and
 * the JSON path; what is tolerated is a warning in {@link Model#warnings()}. See
 * docs/importer.md ("glTF 2.0"). Thread-safe: each call works on its own state.
 */
public final class GltfImporter {
    private GltfImporter() {
    }

    /**
     * Imports a file; its name (not its path) appears in messages. Buffers and images it names by
     * relative URI are read from its folder (never outside it).
     *
     * @param file the {@code .gltf} or {@code .glb} file to read
     * @return the imported model, with the file's name as its {@link Model#source()}
     * @throws IOException when the file cannot be opened or read
     * @throws GltfException when its content, or a buffer or image it needs, cannot be imported
     */
    public static Model read(Path file) throws IOException, GltfException {
        String name = file.getFileName() == null ? file.toString() : file.getFileName().toString();
        try (InputStream in = new BufferedInputStream(Files.newInputStream(file), 1 << 16)) {
            return read(in, name, file.toAbsolutePath());
        }
    }

    /**
     * Imports from a stream (the caller closes it).
     *
     * @param in       the document's bytes ({@code .gltf} JSON or {@code .glb}), not closed
     * @param name     the name used in messages and {@link Model#source()}
     * @param location the document's path, against whose folder relative URIs are resolved, or
     *                 null: then a URI naming a file is refused
     * @return the imported model
     * @throws IOException   when reading the stream fails
     * @throws GltfException when the document, or a buffer or image it needs, cannot be imported
     */
    public static Model read(InputStream in, String name, Path location) throws IOException, GltfException {
        GltfContext ctx = new GltfContext(name);
        GlbContainer container = GlbContainer.read(ctx, in);
        ctx.addDocumentBytes(container.bytes.length);
        try {
            return build(ctx, container, location);
        } catch (RuntimeException | StackOverflowError e) {
            // A safety net: every problem should already be a GltfException with a precise
            // message; if one slipped through, the user still gets one line naming the file.
            throw new GltfException(name, "", "cannot be imported: " + e, e);
        }
    }

    /** The material symbol (and material id) of material {@code m}: its JSON pointer. */
    static String materialSymbol(int m) {
        return "/materials/" + m;
    }

    private static Model build(GltfContext ctx, GlbContainer container, Path location) throws GltfException {
        JsonNode root = JsonTree.parse(ctx, container.bytes, container.jsonOffset, container.jsonLength);
        AssetInfo asset = asset(root.get("asset"));
        GltfDocumentChecks.check(root, ctx);
        boolean quantized = Extensions.check(ctx, root);
        UriResolver uris = new UriResolver(ctx, location);
        Buffers buffers = new Buffers(ctx, root, container, uris);
        Accessors accessors = new Accessors(ctx, root, buffers);
        GltfDataChecks.check(ctx, root, buffers, accessors);
        MaterialReader materials = new MaterialReader(ctx, uris, buffers, root);

        JsonNode meshList = root.get("meshes").arrayOrMissing();
        MeshReader meshReader = new MeshReader(ctx, accessors, quantized, materials.materials().size());
        MeshData[] meshes = new MeshData[meshList.size()];
        List<Mesh> modelMeshes = new ArrayList<>();
        for (int m = 0; m < meshes.length; m++) {
            meshes[m] = meshReader.read(meshList.get(m), m);
            if (meshes[m] != null) {
                modelMeshes.add(meshes[m].mesh);
            }
        }
        SceneReader scene = new SceneReader(ctx, root);
        scene.read(root, InstanceBuilder.jointFlags(root));
        InstanceBuilder instances = new InstanceBuilder(ctx, root, accessors, scene, meshes, materials);
        instances.build();
        for (Morph morph : instances.morphs()) {
            modelMeshes.add(morph.result());
        }
        List<AnimationClip> clips = new AnimationReader(ctx, accessors, scene, instances.instances(), root).read(root);
        return new Model(ctx.file(), asset, modelMeshes, instances.skins(), instances.morphs(),
                materials.materials(), materials.images(), scene.result, instances.instances(), clips,
                ctx.warnings());
    }

    private static AssetInfo asset(JsonNode asset) throws GltfException {
        if (asset.isMissing()) {
            throw asset.error("missing: a glTF document must have an asset with its version");
        }
        JsonNode versionNode = asset.get("version");
        String version = versionNode.string();
        if (!version.matches("2\\.[0-9]+")) {
            throw versionNode.error("version \"" + version + "\" is not glTF 2.x");
        }
        JsonNode minVersion = asset.get("minVersion");
        if (!minVersion.isMissing()) {
            String min = minVersion.string();
            if (!min.matches("[0-9]+\\.[0-9]+") || !min.equals("2.0")) {
                throw minVersion.error("minVersion \"" + min + "\": this importer reads glTF 2.0");
            }
        }
        return new AssetInfo(UpAxis.Y_UP, 1.0, "meter", asset.get("generator").string(null), true);
    }
}
