package org.skinlab.desktop.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;

import org.junit.jupiter.api.Test;

/** Reading the shared C++ reference's result lines (its printf format, ../shared/perf/skin_ref.cpp). */
class CppSkinningReferenceTest {
    @Test
    void readsTheResultLinesAndIgnoresTheRest() {
        String out = "some banner\n"
                + "V=10000    c-lbs     min  13.201  median  13.694 ns/vertex  (n=1234)  checksum 971.419057\n"
                + "V=100000   c-dqs     min  33.100  median  35.002 ns/vertex  (n=87)  checksum -1046.777414\n";
        List<CppSkinningReference.Result> r = CppSkinningReference.parse(out);
        assertEquals(2, r.size());
        assertEquals(new CppSkinningReference.Result(10000, "c-lbs", 13.201, 13.694, 1234, 971.419057), r.get(0));
        assertEquals(new CppSkinningReference.Result(100000, "c-dqs", 33.1, 35.002, 87, -1046.777414), r.get(1));
    }
}
