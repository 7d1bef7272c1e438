package org.skinlab.skinning;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.skinlab.collada.ColladaImporter;
import org.skinlab.testing.TestPaths;

/** The centres' disk cache: the second load reads what the first computed; bad entries are passed by. */
class CentresCacheTest {
    private static SkinnedGeometry geometry(String asset) throws Exception {
        return SkinnedModel.of(ColladaImporter.read(TestPaths.asset(asset))).geometries().get(0);
    }

    private static List<Path> entries(Path dir) throws Exception {
        try (Stream<Path> files = Files.list(dir)) {
            return files.toList();
        }
    }

    @Test
    void theSecondLoadReadsTheFirstsCentres(@TempDir Path dir) throws Exception {
        SkinnedGeometry g = geometry("cylinders/cylinder-bend.dae");
        float[] computed = CentresOfRotation.compute(g, CentresOfRotation.Parameters.DEFAULT, CentresOfRotation.Progress.NONE);
        String key = CentresCache.key(g, CentresOfRotation.Parameters.DEFAULT);
        assertEquals(null, CentresCache.load(dir, key, computed.length));
        CentresCache.store(dir, key, computed);
        assertEquals(List.of(dir.resolve(key + ".cor")), entries(dir), "one file, no temporary left");
        assertArrayEquals(computed, CentresCache.load(dir, key, computed.length));
        // Another sigma or epsilon, or another geometry, is another entry; the twist cylinder is the bend
        // cylinder's mesh and weights with another animation: the same entry serves both.
        assertNotEquals(key, CentresCache.key(g, new CentresOfRotation.Parameters(0.2, 0.1)));
        assertNotEquals(key, CentresCache.key(g, new CentresOfRotation.Parameters(0.1, 0.05)));
        assertNotEquals(key, CentresCache.key(geometry("cylinders/cylinder-twist-low.dae"), CentresOfRotation.Parameters.DEFAULT));
        assertEquals(key, CentresCache.key(geometry("cylinders/cylinder-twist-high.dae"), CentresOfRotation.Parameters.DEFAULT));
    }

    @Test
    void computeOrLoadUsesTheCacheDirectory(@TempDir Path dir) throws Exception {
        SkinnedGeometry g = geometry("cylinders/cylinder-twist-low.dae");
        Path before = CentresOfRotation.cacheDirectory();
        CentresOfRotation.setCacheDirectory(dir.resolve("cache"));
        try {
            AtomicInteger calls = new AtomicInteger();
            float[] first = CentresOfRotation.computeOrLoad(g, CentresOfRotation.Parameters.DEFAULT, (done, total) -> calls.incrementAndGet());
            int computingCalls = calls.get();
            assertTrue(computingCalls >= 1);
            assertEquals(1, entries(dir.resolve("cache")).size());
            calls.set(0);
            float[] second = CentresOfRotation.computeOrLoad(g, CentresOfRotation.Parameters.DEFAULT, (done, total) -> calls.incrementAndGet());
            assertArrayEquals(first, second);
            assertEquals(1, calls.get(), "a load reports itself done at once");
        } finally {
            CentresOfRotation.setCacheDirectory(before);
        }
    }

    @Test
    void aDamagedEntryIsPassedBy(@TempDir Path dir) throws Exception {
        SkinnedGeometry g = geometry("cylinders/cylinder-twist-low.dae");
        String key = CentresCache.key(g, CentresOfRotation.Parameters.DEFAULT);
        int floats = 3 * g.pointCount();
        Files.write(dir.resolve(key + ".cor"), new byte[12 + 4 * floats]); // right size, wrong header
        assertEquals(null, CentresCache.load(dir, key, floats));
        Files.write(dir.resolve(key + ".cor"), new byte[7]);
        assertEquals(null, CentresCache.load(dir, key, floats));
        // A folder that cannot be a folder: storing fails quietly.
        Path notAFolder = dir.resolve("file");
        Files.writeString(notAFolder, "x");
        CentresCache.store(notAFolder, key, new float[floats]);
        assertEquals(null, CentresCache.load(notAFolder, key, floats));
    }
}
