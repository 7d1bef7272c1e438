package org.skinlab.desktop.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import org.junit.jupiter.api.Test;
import org.skinlab.desktop.Cli;
import org.skinlab.desktop.ExitCodes;
import org.skinlab.desktop.bench.SyntheticSkinData;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.Skinners;
import org.skinlab.skinning.SkinningMethod;

/** {@code skinlab bench skinning}: its JSON contract and its text, with tiny timings. */
class SkinningBenchCommandTest {
    private static final ObjectMapper JSON = new ObjectMapper();

    /** The checksum of one scalar run, computed here without the command (the independent value). */
    private static double checksum(SkinningMethod m, int vertices) {
        SyntheticSkinData data = new SyntheticSkinData(vertices);
        float[] p = new float[3 * vertices];
        float[] n = new float[3 * vertices];
        Skinners.scalar(m, data.geometry(), NormalTransform.BLENDED_MATRIX).skinAll(data.palette(), p, n);
        return SyntheticSkinData.checksum(p, n);
    }

    @Test
    void jsonHasTheRequiredKeysAndValues() throws Exception {
        for (String method : new String[] {"lbs", "dqs"}) {
            Cli r = Cli.run("bench", "skinning", "--vertices", "1000", "--threads", "2", "--method", method,
                    "--warmup-seconds", "0", "--seconds", "0", "--json");
            assertEquals(ExitCodes.OK, r.status, r::toString);
            assertTrue(r.out.indexOf('\n') == r.out.length() - 1, "one line: " + r);
            JsonNode root = JSON.readTree(r.out);
            assertEquals(List.of("method", "vertices", "threads", "influences", "normals", "minNsPerVertex",
                    "medianNsPerVertex", "checksum", "implementation", "java", "javaVendor"), Cli.keys(root));
            assertEquals(method, root.get("method").asText());
            assertEquals(1000, root.get("vertices").intValue());
            assertEquals(2, root.get("threads").intValue());
            assertEquals(4, root.get("influences").intValue());
            assertEquals("blended", root.get("normals").asText());
            double min = root.get("minNsPerVertex").doubleValue();
            double median = root.get("medianNsPerVertex").doubleValue();
            assertTrue(min > 0 && min <= median, r::toString);
            assertEquals(checksum(SkinningMethod.fromKey(method), 1000), root.get("checksum").doubleValue(), 1e-3);
            assertEquals("vector-256", root.get("implementation").asText(), "the kernel; threads are their own key");
        }
    }

    @Test
    void positionsOnlyAtAnyInfluenceCountSumThePositions() throws Exception {
        // The checksum of positions only is the sum of the positions, which are those of the kernel
        // with normals bit for bit: computed here from a scalar run with normals.
        for (String method : new String[] {"lbs", "dqs"}) {
            for (int k : new int[] {1, 4, 8}) {
                for (String impl : new String[] {"scalar", "vector"}) {
                    Cli r = Cli.run("bench", "skinning", "--vertices", "800", "--method", method, "--normals", "none",
                            "--influences", Integer.toString(k), "--implementation", impl, "--warmup-seconds", "0",
                            "--seconds", "0", "--json");
                    assertEquals(ExitCodes.OK, r.status, r::toString);
                    JsonNode root = JSON.readTree(r.out);
                    assertEquals("none", root.get("normals").asText());
                    assertEquals(k, root.get("influences").intValue());
                    SyntheticSkinData data = new SyntheticSkinData(800, SyntheticSkinData.SEED, k);
                    float[] p = new float[3 * 800];
                    Skinners.scalar(SkinningMethod.fromKey(method), data.geometry(), NormalTransform.BLENDED_MATRIX)
                            .skinAll(data.palette(), p, new float[3 * 800]);
                    assertEquals(SyntheticSkinData.checksum(p, null), root.get("checksum").doubleValue(),
                            impl.equals("scalar") ? 1e-9 : 1e-3, r::toString);
                }
            }
        }
        Cli text = Cli.run("bench", "skinning", "--vertices", "300", "--method", "dqs", "--normals", "none",
                "--influences", "2", "--warmup-seconds", "0", "--seconds", "0");
        assertTrue(text.out.startsWith("skinning dqs, 300 vertices, 2 influences, 1 thread, vector-256,"
                + " positions only,"), text::toString);
    }

    @Test
    void scalarImplementationAndThesisBaselineAreReported() throws Exception {
        Cli r = Cli.run("bench", "skinning", "--vertices", "500", "--method", "dqs", "--implementation", "scalar",
                "--baseline", "thesis", "--warmup-seconds", "0", "--seconds", "0", "--json");
        assertEquals(ExitCodes.OK, r.status, r::toString);
        JsonNode root = JSON.readTree(r.out);
        assertEquals("scalar", root.get("implementation").asText());
        assertEquals(1, root.get("threads").intValue());
        double expected = checksum(SkinningMethod.DQS, 500);
        assertEquals(expected, root.get("checksum").doubleValue(), 1e-3);
        assertEquals(expected, root.get("baselineChecksum").doubleValue(), 1e-2);
        assertTrue(root.get("baselineMinNsPerVertex").doubleValue() <= root.get("baselineMedianNsPerVertex").doubleValue());
        double ratio = root.get("baselineRatio").doubleValue();
        assertEquals(root.get("baselineMedianNsPerVertex").doubleValue() / root.get("medianNsPerVertex").doubleValue(),
                ratio, ratio * 0.01 + 0.01);
    }

    @Test
    void textReportNamesTheSetupAndTheTimes() {
        Cli r = Cli.run("bench", "skinning", "--vertices", "300", "--method", "lbs", "--warmup-seconds", "0",
                "--seconds", "0");
        assertEquals(ExitCodes.OK, r.status, r::toString);
        String[] lines = r.out.split("\n");
        assertEquals("skinning lbs, 300 vertices, 4 influences, 1 thread, vector-256, normals by the blended matrix,"
                + " Java "
                + System.getProperty("java.version") + " (" + System.getProperty("java.vendor") + ")", lines[0]);
        assertTrue(lines[1].matches("min [0-9.]+ ns/vertex, median [0-9.]+ ns/vertex \\([0-9]+ runs\\), checksum "
                + "-?[0-9.]+"), lines[1]);
    }

    @Test
    void badOptionsAreUsageErrors() {
        for (String[] args : new String[][] {{"--method", "xyz"}, {"--vertices", "0"}, {"--threads", "0"},
            {"--implementation", "gpu"}, {"--normals", "flat"}, {"--baseline", "ozz"}, {"--influences", "0"},
            {"--influences", "65"}, {"--normals", "none", "--method", "cor"},
            {"--normals", "none", "--baseline", "thesis"}}) {
            String[] all = new String[args.length + 2];
            all[0] = "bench";
            all[1] = "skinning";
            System.arraycopy(args, 0, all, 2, args.length);
            Cli r = Cli.run(all);
            assertEquals(ExitCodes.USAGE, r.status, r::toString);
            assertEquals(1, r.errLines().length, r::toString);
            assertTrue(r.errLines()[0].startsWith("skinlab: bench skinning: "), r::toString);
        }
    }
}
