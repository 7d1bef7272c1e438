package org.skinlab.desktop.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.skinlab.desktop.Cli;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.Skinners;
import org.skinlab.skinning.SkinningMethod;

/**
 * Reading the C++ programs' result lines (the shared reference's printf format,
 * ../shared/perf/skin_ref.cpp), and our positions-only program (bench/cpp/skin_positions.cpp)
 * compiled and run: its data and loops against the reference's published checksums and the
 * reference itself, and its positions-only checksums against our Java kernels on
 * {@link SyntheticSkinData}. Tolerances: the with-normals calibration and scalar LBS do the same
 * float operations in the same order as their counterparts, so their checksums agree to the
 * printed digits (1e-6); scalar DQS takes its square root in double, the vector kernels fuse
 * multiply-adds: 1e-6 relative of a sum of 30,000 floats (the reference's and our figures in
 * docs/benchmarks.md differ by 4e-9 relative).
 */
class CppSkinningReferenceTest {
    private static final int V = 10_000;

    @TempDir
    Path dir;

    @Test
    void readsTheResultLinesAndIgnoresTheRest() {
        String out = "some banner\n"
                + "V=10000    c-lbs     min  13.201  median  13.694 ns/vertex  (n=1234)  checksum 971.419057\n"
                + "V=100000   c-dqs     min  33.100  median  35.002 ns/vertex  (n=87)  checksum -1046.777414\n"
                + "V=10000    c-dqs-pos min  24.759  median  24.765 ns/vertex  (n=142)  checksum 997.108263\n";
        List<CppSkinningReference.Result> r = CppSkinningReference.parse(out);
        assertEquals(3, r.size());
        assertEquals(new CppSkinningReference.Result(10000, "c-lbs", 13.201, 13.694, 1234, 971.419057), r.get(0));
        assertEquals(new CppSkinningReference.Result(100000, "c-dqs", 33.1, 35.002, 87, -1046.777414), r.get(1));
        assertEquals(new CppSkinningReference.Result(10000, "c-dqs-pos", 24.759, 24.765, 142, 997.108263), r.get(2));
        assertEquals(SkinningMethod.LBS, r.get(0).method());
        assertEquals(NormalTransform.BLENDED_MATRIX, r.get(0).normals());
        assertEquals(SkinningMethod.DQS, r.get(2).method());
        assertEquals(NormalTransform.NONE, r.get(2).normals());
    }

    private static String compilerOrSkip() {
        String compiler = CppSkinningReference.compiler();
        assumeTrue(compiler != null, "no C++ compiler (g++ or c++) on the PATH: the C++ programs are not run");
        return compiler;
    }

    private static Map<String, Double> checksums(List<CppSkinningReference.Result> results) {
        return results.stream().collect(Collectors.toMap(CppSkinningReference.Result::variant,
                CppSkinningReference.Result::checksum));
    }

    /** Our kernel's checksum on the same data: positions only, or normals by the blended matrix. */
    private static double java(SkinningMethod m, NormalTransform rule, boolean scalar, int influences) {
        SyntheticSkinData data = new SyntheticSkinData(V, SyntheticSkinData.SEED, influences);
        float[] p = new float[3 * V];
        float[] n = rule == NormalTransform.NONE ? null : new float[3 * V];
        (scalar ? Skinners.scalar(m, data.geometry(), rule) : Skinners.create(m, data.geometry(), rule))
                .skinAll(data.palette(), p, n);
        return SyntheticSkinData.checksum(p, n);
    }

    @Test
    void thePositionsOnlyProgramSkinsTheReferencesDataAsTheReferenceAndOurKernelsDo() throws Exception {
        String compiler = compilerOrSkip();
        CppSkinningReference ours = CppSkinningReference.compile(compiler,
                Cli.root().resolve(CppSkinningReference.POSITIONS_SOURCE), dir);
        List<CppSkinningReference.Result> results = ours.run(CppSkinningReference.POSITIONS_VARIANTS, 1, 0,
                List.of(V));
        assertEquals(CppSkinningReference.POSITIONS_VARIANTS,
                results.stream().map(CppSkinningReference.Result::variant).toList());
        for (CppSkinningReference.Result r : results) {
            assertTrue(r.samples() >= 5 && r.minNs() > 0 && r.minNs() <= r.medianNs(), r::toString);
        }
        Map<String, Double> c = checksums(results);
        // The reference's README: LBS 971.419057 and DQS 1046.777414 at V=10k.
        assertEquals(971.419057, c.get("c-lbs-nrm"), 1e-6);
        assertEquals(1046.777414, c.get("c-dqs-nrm"), 1e-6);
        Path reference = Cli.shared().resolve("perf/skin_ref.cpp");
        if (Files.isRegularFile(reference)) {
            Map<String, Double> ref = checksums(CppSkinningReference.compile(compiler, reference, dir)
                    .run(CppSkinningReference.REFERENCE_VARIANTS, 1, 0, List.of(V)));
            assertEquals(ref.get("c-lbs"), c.get("c-lbs-nrm"), 1e-6);
            assertEquals(ref.get("c-dqs"), c.get("c-dqs-nrm"), 1e-6);
        }
        for (boolean scalar : new boolean[] {true, false}) {
            assertEquals(c.get("c-lbs-pos"), java(SkinningMethod.LBS, NormalTransform.NONE, scalar, 4),
                    scalar ? 1e-6 : 1e-6 * Math.abs(c.get("c-lbs-pos")));
            assertEquals(c.get("c-dqs-pos"), java(SkinningMethod.DQS, NormalTransform.NONE, scalar, 4),
                    1e-6 * Math.abs(c.get("c-dqs-pos")));
            assertEquals(c.get("c-lbs-nrm"), java(SkinningMethod.LBS, NormalTransform.BLENDED_MATRIX, scalar, 4),
                    scalar ? 1e-6 : 1e-6 * Math.abs(c.get("c-lbs-nrm")));
        }
    }

    @Test
    void otherInfluenceCountsAreDrawnAsSyntheticSkinDataDrawsThem() throws Exception {
        String compiler = compilerOrSkip();
        CppSkinningReference ours = CppSkinningReference.compile(compiler,
                Cli.root().resolve(CppSkinningReference.POSITIONS_SOURCE), dir);
        for (int k : new int[] {1, 2, 8}) {
            Map<String, Double> c = checksums(ours.run(List.of("c-lbs-pos", "c-dqs-pos"), 1, 0, List.of(V), k));
            // Scalar LBS: the same operations, so the same sum; any other draw would differ in the
            // first digits.
            assertEquals(c.get("c-lbs-pos"), java(SkinningMethod.LBS, NormalTransform.NONE, true, k), 1e-6,
                    k + " influences");
            assertEquals(c.get("c-dqs-pos"), java(SkinningMethod.DQS, NormalTransform.NONE, true, k),
                    1e-6 * Math.abs(c.get("c-dqs-pos")), k + " influences");
        }
    }

    @Test
    void runBothGivesTheReferenceAndOurProgramPerSize() throws Exception {
        String compiler = compilerOrSkip();
        Path reference = Cli.shared().resolve("perf/skin_ref.cpp");
        assumeTrue(Files.isRegularFile(reference), "no shared reference at " + reference);
        List<CppSkinningReference.Result> r = CppSkinningReference.runBoth(compiler, reference,
                Cli.root().resolve(CppSkinningReference.POSITIONS_SOURCE), dir, 1, 0, List.of(1000, 2000));
        assertEquals(List.of("c-lbs", "c-dqs", "c-lbs-pos", "c-dqs-pos", "c-lbs-nrm", "c-dqs-nrm", "c-lbs", "c-dqs",
                "c-lbs-pos", "c-dqs-pos", "c-lbs-nrm", "c-dqs-nrm"),
                r.stream().map(CppSkinningReference.Result::variant).toList());
        assertEquals(List.of(1000, 1000, 1000, 1000, 1000, 1000, 2000, 2000, 2000, 2000, 2000, 2000),
                r.stream().map(CppSkinningReference.Result::vertices).toList());
    }
}
