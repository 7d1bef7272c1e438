package org.skinlab.collada;

import java.io.BufferedInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

import org.skinlab.model.AnimationClip;
import org.skinlab.model.AssetInfo;
import org.skinlab.model.Material;
import org.skinlab.model.Mesh;
import org.skinlab.model.Model;
import org.skinlab.model.Morph;
import org.skinlab.model.Skin;
import org.skinlab.model.UpAxis;

/**
 * Reads a COLLADA 1.4/1.5 document into an immutable {@link Model}.
 *
 * <p>The file is parsed once into a lightweight tree by {@link SafeXmlReader} (no DTDs, no
 * entities, nothing outside the file is ever read), then each library is read by its own loader,
 * in dependency order: geometries ({@link GeometryLoader}), controllers ({@link SkinLoader}),
 * the visual scene ({@link SceneLoader}), animations and clips ({@link AnimationLoader}).
 *
 * <p>Every problem that makes the file unusable is a {@link ColladaException} naming the file
 * and the element; everything tolerated is listed in {@link Model#warnings()}. See
 * {@code docs/importer.md} for the mapping and the leniency decisions. Thread-safe: each call
 * works on its own state.
 */
public final class ColladaImporter {
    private ColladaImporter() {
    }

    /**
     * Imports a file; its name (not its path) appears in messages. Relative URLs in it (image
     * files, references to itself by file name) are resolved against its folder.
     *
     * @param file the {@code .dae} file to read
     * @return the imported model, with the file's name as its {@link Model#source()}
     * @throws IOException when the file cannot be opened or read
     * @throws ColladaException when its content cannot be imported (see {@link ColladaException})
     */
    public static Model read(Path file) throws IOException, ColladaException {
        String name = file.getFileName() == null ? file.toString() : file.getFileName().toString();
        try (InputStream in = new BufferedInputStream(Files.newInputStream(file), 1 << 16)) {
            return read(in, name, file.toAbsolutePath());
        }
    }

    /**
     * Imports from a stream (UTF-8, or UTF-16 with a byte order mark, or any encoding the XML
     * declaration names). The caller closes the stream. The name is also taken as the document's
     * location (a path, possibly relative) for its relative URLs; see
     * {@link #read(InputStream, String, Path)}.
     *
     * @param in   the document's bytes, not closed
     * @param name the name used in messages and {@link Model#source()}
     * @return the imported model
     * @throws IOException when reading the stream fails
     * @throws ColladaException when the document cannot be imported (see {@link ColladaException})
     */
    public static Model read(InputStream in, String name) throws IOException, ColladaException {
        return read(in, name, DocumentLocation.fromName(name));
    }

    /**
     * Imports from a stream whose document lives at {@code location}: relative URLs in it (image
     * files, references to the document itself by file name) are resolved against that path's
     * folder. The importer never opens any file there.
     *
     * @param in       the document's bytes, not closed
     * @param name     the name used in messages and {@link Model#source()}
     * @param location the document's path (absolute or relative), or null when unknown
     * @return the imported model
     * @throws IOException      when reading the stream fails
     * @throws ColladaException when the document cannot be imported (see {@link ColladaException})
     */
    public static Model read(InputStream in, String name, Path location) throws IOException, ColladaException {
        XmlElement root = SafeXmlReader.read(in, name);
        try {
            return build(root, name, location);
        } catch (RuntimeException e) {
            // A safety net: every problem should already be a ColladaException with a precise
            // message; if one slipped through, the user still gets one line naming the file.
            throw new ColladaException(name, "document", "cannot be imported: " + e, e);
        }
    }

    private static Model build(XmlElement root, String name, Path location) throws ColladaException {
        ImportContext ctx = new ImportContext(name, location, root);
        if (!root.name().equals("COLLADA")) {
            throw ctx.error(root, "the root element is <" + root.name() + ">, not <COLLADA>");
        }
        String version = root.attr("version");
        if (version != null && !version.startsWith("1.4") && !version.startsWith("1.5")) {
            ctx.warn(root, "version=\"" + version + "\" is not 1.4.x or 1.5.x; reading it as 1.4.1");
        }
        AssetInfo asset = readAsset(ctx, root);

        Map<XmlElement, Mesh> meshesByGeometry = loadGeometries(ctx, root);
        List<Mesh> meshes = new ArrayList<>(meshesByGeometry.values());

        MorphLoader morphLoader = new MorphLoader(ctx, meshesByGeometry);
        Map<XmlElement, Morph> morphsByController = morphLoader.loadAll(root);
        for (Morph m : morphsByController.values()) {
            meshes.add(m.result());
        }

        Map<XmlElement, Skin> skinsByController = loadSkins(ctx, root, meshesByGeometry, morphsByController);
        List<Skin> skins = new ArrayList<>(skinsByController.values());

        MaterialLoader materialLoader = new MaterialLoader(ctx);
        Map<XmlElement, Material> materials = materialLoader.loadAll(root);

        SceneLoader.Result scene = new SceneLoader(ctx, meshesByGeometry, morphsByController, skinsByController,
                materials, asset.authoringTool()).load(root);
        List<AnimationClip> clips = new AnimationLoader(ctx, scene, morphsByController, morphLoader,
                asset.authoringTool()).load(root);
        return new Model(name, asset, meshes, skins, new ArrayList<>(morphsByController.values()),
                new ArrayList<>(materials.values()), materialLoader.images(), scene.nodes, scene.instances, clips,
                ctx.warnings());
    }

    /** Every {@code <geometry>} with a mesh, in document order. */
    private static Map<XmlElement, Mesh> loadGeometries(ImportContext ctx, XmlElement root) throws ColladaException {
        Map<XmlElement, Mesh> meshesByGeometry = new LinkedHashMap<>();
        GeometryLoader geometryLoader = new GeometryLoader(ctx);
        for (XmlElement library : root.children("library_geometries")) {
            for (XmlElement geometry : library.children("geometry")) {
                if (geometry.id() == null) {
                    ctx.warn(geometry, "geometry without id; nothing can refer to it");
                }
                Mesh mesh = geometryLoader.load(geometry);
                if (mesh != null) {
                    meshesByGeometry.put(geometry, mesh);
                }
            }
        }
        return meshesByGeometry;
    }

    /** Every {@code <controller><skin>}, in document order. */
    private static Map<XmlElement, Skin> loadSkins(ImportContext ctx, XmlElement root,
            Map<XmlElement, Mesh> meshesByGeometry, Map<XmlElement, Morph> morphsByController) throws ColladaException {
        Map<XmlElement, Skin> skinsByController = new LinkedHashMap<>();
        SkinLoader skinLoader = new SkinLoader(ctx, meshesByGeometry, morphsByController);
        for (XmlElement library : root.children("library_controllers")) {
            for (XmlElement controller : library.children("controller")) {
                XmlElement skin = controller.child("skin");
                if (skin != null) {
                    skinsByController.put(controller, skinLoader.load(controller, skin));
                }
            }
        }
        return skinsByController;
    }

    private static AssetInfo readAsset(ImportContext ctx, XmlElement root) throws ColladaException {
        XmlElement asset = root.child("asset");
        if (asset == null) {
            ctx.warn(root, "no <asset>; assuming Y_UP and 1 unit = 1 meter");
            return new AssetInfo(UpAxis.Y_UP, 1.0, "meter", null, false);
        }
        UpAxis up = UpAxis.Y_UP;
        XmlElement upAxis = asset.child("up_axis");
        if (upAxis != null && !upAxis.text().isEmpty()) {
            String text = upAxis.text().trim().toUpperCase(Locale.ROOT);
            try {
                up = UpAxis.valueOf(text);
            } catch (IllegalArgumentException e) {
                ctx.warn(upAxis, "unknown up axis \"" + upAxis.text().trim() + "\"; assuming Y_UP");
            }
        }
        double meter = 1.0;
        String unitName = "meter";
        XmlElement unit = asset.child("unit");
        if (unit != null) {
            meter = ctx.number(unit, "meter", 1.0);
            if (meter <= 0) {
                ctx.warn(unit, "meter=\"" + unit.attr("meter") + "\" is not positive; assuming 1");
                meter = 1.0;
            }
            if (unit.attr("name") != null) {
                unitName = unit.attr("name");
            }
        }
        String tool = null;
        for (XmlElement contributor : asset.children("contributor")) {
            XmlElement t = contributor.child("authoring_tool");
            if (t != null && !t.text().isEmpty()) {
                tool = t.text().trim();
                break;
            }
        }
        return new AssetInfo(up, meter, unitName, tool, true);
    }
}
