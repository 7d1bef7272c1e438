package org.skinlab.desktop.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Where {@code bench frame --all-corpus} looks for the repository and the shared corpus. */
class BenchCorpusTest {
    @TempDir
    Path dir;

    /** dir/work/repo (a checkout) with dir/work/shared/corpus beside it. */
    private Path checkout(boolean withShared) throws Exception {
        Path repo = Files.createDirectories(dir.resolve("work/repo"));
        Files.writeString(repo.resolve("settings.gradle"), "");
        Files.createDirectories(repo.resolve("assets/characters"));
        Files.createDirectories(repo.resolve("desktop/src"));
        if (withShared) {
            Files.createDirectories(dir.resolve("work/shared/corpus"));
        }
        return repo;
    }

    @Test
    void theRootIsFoundFromAnyFolderInsideTheCheckout() throws Exception {
        Path repo = checkout(true);
        assertEquals(repo, BenchCorpus.repositoryRoot(repo));
        assertEquals(repo, BenchCorpus.repositoryRoot(repo.resolve("desktop/src")));
        assertNull(BenchCorpus.repositoryRoot(dir), "no checkout above");
        // settings.gradle alone is not our repository.
        Files.writeString(dir.resolve("settings.gradle"), "");
        assertNull(BenchCorpus.repositoryRoot(dir));
    }

    @Test
    void theCorpusBesideTheRootWinsFromAnyFolderInside() throws Exception {
        Path repo = checkout(true);
        Path shared = dir.resolve("work/shared/corpus");
        Path inside = repo.resolve("desktop/src");
        assertEquals(shared, BenchCorpus.sharedCorpus(BenchCorpus.repositoryRoot(inside), inside));
    }

    @Test
    void withoutACheckoutTheCorpusBesideTheCurrentFolderCounts() throws Exception {
        Path elsewhere = Files.createDirectories(dir.resolve("other/here"));
        Files.createDirectories(dir.resolve("other/shared/corpus"));
        assertEquals(dir.resolve("other/shared/corpus"), BenchCorpus.sharedCorpus(null, elsewhere));
        Path repo = checkout(false);
        assertNull(BenchCorpus.sharedCorpus(repo, repo), "absent: the caller reports a usage error");
    }
}
