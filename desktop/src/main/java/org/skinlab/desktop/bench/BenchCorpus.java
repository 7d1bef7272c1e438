package org.skinlab.desktop.bench;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.skinlab.desktop.ModelFileSearch;

/**
 * Where {@code bench frame --all-corpus} finds its files: our characters
 * ({@code assets/characters/*.dae} of the repository) and the shared third-party corpus
 * ({@code ../shared/corpus}: beside the repository root, or beside the current directory).
 * The repository root is the first folder, from the current directory up, that holds
 * {@code settings.gradle} and {@code assets/characters}; so the command works from the root and
 * from any folder inside the repository.
 */
public final class BenchCorpus {
    public static final String CHARACTERS = "assets/characters";
    public static final String SHARED_CORPUS = "../shared/corpus";

    private BenchCorpus() {
    }

    /** The repository root at or above {@code from}, or null outside a checkout. */
    public static Path repositoryRoot(Path from) {
        for (Path d = from.toAbsolutePath().normalize(); d != null; d = d.getParent()) {
            if (Files.isRegularFile(d.resolve("settings.gradle")) && Files.isDirectory(d.resolve(CHARACTERS))) {
                return d;
            }
        }
        return null;
    }

    /**
     * The shared corpus beside the repository root (when there is one) or else beside
     * {@code from}; null when neither exists.
     */
    public static Path sharedCorpus(Path root, Path from) {
        List<Path> places = new ArrayList<>();
        if (root != null) {
            places.add(root.resolve(SHARED_CORPUS).normalize());
        }
        places.add(from.toAbsolutePath().resolve(SHARED_CORPUS).normalize());
        for (Path p : places) {
            if (Files.isDirectory(p)) {
                return p;
            }
        }
        return null;
    }

    /** Our characters: the {@code .dae} files of the repository's assets/characters. */
    public static List<ModelFileSearch.Entry> characters(Path root) {
        return ModelFileSearch.expand(List.of(root.resolve(CHARACTERS)), ModelFileSearch.COLLADA);
    }

    /** Every {@code .dae} below the corpus folder, in {@link ModelFileSearch}'s order. */
    public static List<ModelFileSearch.Entry> corpusFiles(Path corpus) {
        return ModelFileSearch.expand(List.of(corpus), ModelFileSearch.COLLADA);
    }
}
