package org.skinlab.android.logic;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import org.skinlab.importer.ModelImporter;
import org.skinlab.internal.scene.DefaultAsset;

/**
 * The models bundled in the APK ({@code .dae}, {@code .gltf}, {@code .glb}), the default character
 * first, then the rest by name; cycles on "next".
 */
public final class ModelCatalog {
    private final List<String> names;
    private int current;

    public ModelCatalog(String[] fileNames) {
        List<String> list = new ArrayList<>();
        for (String n : fileNames) {
            if (ModelImporter.isModelFile(n)) {
                list.add(n);
            }
        }
        list.sort(null);
        if (list.remove(DefaultAsset.fileName())) {
            list.add(0, DefaultAsset.fileName());
        }
        if (list.isEmpty()) {
            throw new IllegalArgumentException("no model file (.dae, .gltf, .glb) among " + Arrays.toString(fileNames));
        }
        this.names = List.copyOf(list);
    }

    public List<String> names() {
        return names;
    }

    public String current() {
        return names.get(current);
    }

    /** Makes {@code name} the current model if the catalog has it; returns whether it does (never for null). */
    public boolean select(String name) {
        int i = name == null ? -1 : names.indexOf(name);
        if (i >= 0) {
            current = i;
        }
        return i >= 0;
    }

    /** Moves to the next model (wrapping) and returns its name. */
    public String next() {
        current = (current + 1) % names.size();
        return current();
    }
}
