package org.skinlab;

import java.io.IOException;

import org.junit.jupiter.api.Test;
import org.skinlab.model.Model;
import org.skinlab.testing.PublicApi;
import org.skinlab.testing.TestPaths;

/**
 * core's public API is the committed {@code core/api.txt}, line for line: a public type, method,
 * constructor or field added, removed or changed fails here until the file says so, so that every
 * change of what users of the published jar can call is a decision (docs/running.md, "The public
 * API file").
 */
class ApiFileTest {
    @Test
    void thePublicApiIsTheCommittedFile() throws IOException {
        PublicApi.check(PublicApi.of(Model.class), TestPaths.root().resolve("core/api.txt"));
    }
}
