package org.skinlab.desktop.cli;

import java.nio.file.Path;
import java.util.Locale;

import org.skinlab.skinning.CentresOfRotation;

/** Entry point of the {@code skinlab} application. */
public final class SkinlabMain {
    private SkinlabMain() {
    }

    public static void main(String[] args) {
        CentresOfRotation.setCacheDirectory(cacheDirectory());
        System.exit(SkinlabCommand.run(args));
    }

    /**
     * Where precomputed data (CoR's centres) is kept between runs: {@code SKINLAB_CACHE} if set
     * (empty: no cache), else the platform's user cache folder.
     */
    static Path cacheDirectory() {
        String own = System.getenv("SKINLAB_CACHE");
        if (own != null) {
            return own.isBlank() ? null : Path.of(own);
        }
        String os = System.getProperty("os.name", "").toLowerCase(Locale.ROOT);
        String home = System.getProperty("user.home");
        if (os.contains("win")) {
            String local = System.getenv("LOCALAPPDATA");
            return local == null ? null : Path.of(local, "skinlab", "cache");
        }
        if (os.contains("mac")) {
            return home == null ? null : Path.of(home, "Library", "Caches", "skinlab");
        }
        String xdg = System.getenv("XDG_CACHE_HOME");
        if (xdg != null && !xdg.isBlank()) {
            return Path.of(xdg, "skinlab");
        }
        return home == null ? null : Path.of(home, ".cache", "skinlab");
    }
}
