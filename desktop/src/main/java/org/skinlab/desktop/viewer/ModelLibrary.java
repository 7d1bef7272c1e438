package org.skinlab.desktop.viewer;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.URISyntaxException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.stream.Stream;

import org.skinlab.importer.ModelImporter;

/**
 * The models "previous/next mesh" cycle through: every bundled model file under the assets
 * folder ({@code .dae}, {@code .gltf}, {@code .glb}: our assets' {@code .glb} twins come right
 * after their {@code .dae}; the default character first, the rest by path), then the files the
 * user opened.
 */
public final class ModelLibrary {
    /** The model the viewer opens when given none, relative to the assets folder. */
    public static final String DEFAULT_ASSET = org.skinlab.internal.scene.DefaultAsset.PATH;

    private final Path assets;
    private final List<Path> models = new ArrayList<>();

    /** The library of an assets folder (null: none found, only opened files). */
    public ModelLibrary(Path assets) {
        this.assets = assets == null ? null : assets.toAbsolutePath().normalize();
        if (this.assets != null) {
            List<Path> found = new ArrayList<>();
            try (Stream<Path> files = Files.walk(this.assets)) {
                files.filter(p -> ModelImporter.isModelFile(p.getFileName().toString()))
                        .filter(Files::isRegularFile).forEach(p -> found.add(p.toAbsolutePath().normalize()));
            } catch (IOException e) {
                throw new UncheckedIOException("cannot list the assets in " + this.assets, e);
            }
            Collections.sort(found);
            // The default character first, and its twin with it, so that every .glb stays right after its .dae.
            Path def = this.assets.resolve(DEFAULT_ASSET);
            Path twin = def.resolveSibling(def.getFileName().toString().replaceFirst("\\.dae$", ".glb"));
            if (!twin.equals(def) && found.remove(twin)) {
                found.add(0, twin);
            }
            if (found.remove(def)) {
                found.add(0, def);
            }
            models.addAll(found);
        }
    }

    /**
     * The bundled assets: the folder named by the system property {@code skinlab.assets}, else
     * {@code ./assets}, else the first {@code assets} folder above the running code that holds
     * the default character (an installed or a built copy inside the repository).
     */
    public static ModelLibrary find() {
        return new ModelLibrary(findAssets());
    }

    static Path findAssets() {
        String property = System.getProperty("skinlab.assets");
        if (property != null && !property.isBlank()) {
            return Path.of(property);
        }
        Path here = Path.of("assets");
        if (Files.isRegularFile(here.resolve(DEFAULT_ASSET))) {
            return here;
        }
        try {
            Path code = Path.of(ModelLibrary.class.getProtectionDomain().getCodeSource().getLocation().toURI());
            for (Path p = code.toAbsolutePath(); p != null; p = p.getParent()) {
                if (Files.isRegularFile(p.resolve("assets").resolve(DEFAULT_ASSET))) {
                    return p.resolve("assets");
                }
            }
        } catch (URISyntaxException | SecurityException | NullPointerException e) {
            return null;
        }
        return null;
    }

    /** The default character, or null when no assets folder was found. */
    public Path defaultModel() {
        return assets == null ? null : assets.resolve(DEFAULT_ASSET);
    }

    public List<Path> models() {
        return Collections.unmodifiableList(models);
    }

    /** Adds a file the user opened (once) and returns its index. */
    public int add(Path file) {
        Path p = file.toAbsolutePath().normalize();
        int i = models.indexOf(p);
        if (i >= 0) {
            return i;
        }
        models.add(p);
        return models.size() - 1;
    }

    public int indexOf(Path file) {
        return models.indexOf(file.toAbsolutePath().normalize());
    }

    /** The model {@code steps} after {@code file} in the list, wrapping; the first when unknown. */
    public Path neighbour(Path file, int steps) {
        if (models.isEmpty()) {
            return null;
        }
        int i = file == null ? -1 : indexOf(file);
        int base = i < 0 ? (steps > 0 ? -1 : 0) : i;
        return models.get(Math.floorMod(base + steps, models.size()));
    }

    /** The path relative to the assets folder for bundled models, else the file name. */
    public String displayName(Path file) {
        Path p = file.toAbsolutePath().normalize();
        if (assets != null && p.startsWith(assets)) {
            return assets.relativize(p).toString().replace('\\', '/');
        }
        Path name = p.getFileName();
        return name == null ? p.toString() : name.toString();
    }
}
