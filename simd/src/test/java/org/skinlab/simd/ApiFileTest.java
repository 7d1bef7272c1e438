package org.skinlab.simd;

import java.io.IOException;

import org.junit.jupiter.api.Test;
import org.skinlab.testing.PublicApi;
import org.skinlab.testing.TestPaths;

/** simd's public API is the committed {@code simd/api.txt}, line for line (as core's: its ApiFileTest). */
class ApiFileTest {
    @Test
    void thePublicApiIsTheCommittedFile() throws IOException {
        PublicApi.check(PublicApi.of(VectorSkinnerProvider.class), TestPaths.root().resolve("simd/api.txt"));
    }
}
