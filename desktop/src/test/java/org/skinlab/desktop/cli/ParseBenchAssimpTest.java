package org.skinlab.desktop.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.skinlab.desktop.ExitCodes;
import org.skinlab.desktop.bench.AssimpBaseline;

/**
 * {@code skinlab bench parse --compare-assimp}: the extra JSON fields, their absence without the
 * option (the format stays backwards compatible), and a file assimp refuses.
 */
class ParseBenchAssimpTest {
    /** The fields of a file before --compare-assimp existed; other tools read exactly these. */
    private static final Set<String> PLAIN_FILE_FIELDS =
            Set.of("file", "bytes", "triangles", "runs", "minMillis", "medianMillis", "mbPerSecond");

    /**
     * One triangle in a geometry library and no {@code <scene>}: our importer reads the mesh,
     * assimp 5.4.1 refuses the file ("Collada: File came out empty").
     */
    private static final String GEOMETRY_WITHOUT_SCENE = """
            <?xml version="1.0" encoding="utf-8"?>
            <COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
              <library_geometries>
                <geometry id="tri">
                  <mesh>
                    <source id="p">
                      <float_array id="pa" count="9">0 0 0 1 0 0 0 1 0</float_array>
                      <technique_common>
                        <accessor source="#pa" count="3" stride="3">
                          <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
                        </accessor>
                      </technique_common>
                    </source>
                    <vertices id="v"><input semantic="POSITION" source="#p"/></vertices>
                    <triangles count="1"><input semantic="VERTEX" source="#v" offset="0"/><p>0 1 2</p></triangles>
                  </mesh>
                </geometry>
              </library_geometries>
            </COLLADA>
            """;

    private static Path asset(String name) {
        return Path.of(System.getProperty("skinlab.root", "../"), "assets", name);
    }

    private static String assimpUnavailable() {
        try {
            AssimpBaseline.loadAndVersion();
            return null;
        } catch (IllegalStateException e) {
            return e.getMessage();
        }
    }

    /** Runs the command with three runs and no warm-up; asserts exit status 0; returns the JSON. */
    private static JsonNode bench(String... extra) throws Exception {
        List<String> args = new ArrayList<>(List.of("bench", "parse", "--json", "--runs", "3", "--warmup-seconds", "0"));
        args.addAll(List.of(extra));
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        int status = SkinlabCommand.run(new PrintWriter(out), new PrintWriter(err), args.toArray(new String[0]));
        assertEquals(ExitCodes.OK, status, err::toString);
        return new ObjectMapper().readTree(out.toString());
    }

    private static Set<String> fieldNames(JsonNode node) {
        Set<String> names = new TreeSet<>();
        node.fieldNames().forEachRemaining(names::add);
        return names;
    }

    @Test
    void compareAssimpAddsAssimpTimesRatioAndTriangleCount() throws Exception {
        String why = assimpUnavailable();
        assumeTrue(why == null, () -> "skipped: " + why);
        JsonNode json = bench("--compare-assimp", asset("cylinders/cylinder-twist-low.dae").toString());

        assertTrue(json.get("assimpVersion").asText().matches("5\\.\\d+\\.\\d+"), json::toString);
        assertEquals("aiProcess_Triangulate | aiProcess_JoinIdenticalVertices", json.get("assimpFlags").asText());
        assertEquals(1, json.get("files").size());
        JsonNode f = json.get("files").get(0);
        Set<String> expected = new TreeSet<>(PLAIN_FILE_FIELDS);
        expected.addAll(Set.of("assimpTriangles", "assimpMinMillis", "assimpMedianMillis", "assimpRatio"));
        assertEquals(expected, fieldNames(f));
        // The thesis' low-resolution cylinder: 1148 triangles (assets/README.md); assimp,
        // triangulating, sees the same.
        assertEquals(1148, f.get("triangles").asLong());
        assertEquals(1148, f.get("assimpTriangles").asLong());
        double ours = f.get("medianMillis").asDouble();
        double assimp = f.get("assimpMedianMillis").asDouble();
        assertTrue(assimp > 0 && f.get("assimpMinMillis").asDouble() <= assimp, f::toString);
        // The ratio is assimp/ours of the unrounded medians; each median is rounded to 0.001 ms,
        // so compare with 2 % relative tolerance plus the rounding of the ratio itself.
        assertEquals(assimp / ours, f.get("assimpRatio").asDouble(), 0.02 * assimp / ours + 0.001, f::toString);
    }

    @Test
    void withoutCompareAssimpTheJsonKeepsItsFormerFields() throws Exception {
        JsonNode json = bench(asset("cylinders/cylinder-twist-low.dae").toString());

        assertEquals(Set.of("benchmark", "java", "cores", "files"), fieldNames(json));
        assertEquals(PLAIN_FILE_FIELDS, fieldNames(json.get("files").get(0)));
        assertEquals(3, json.get("files").get(0).get("runs").asInt());
    }

    @Test
    void aFileAssimpRefusesIsReportedFailedAndStillMeasuredForUs(@TempDir Path dir) throws Exception {
        String why = assimpUnavailable();
        assumeTrue(why == null, () -> "skipped: " + why);
        Path file = dir.resolve("no-scene.dae");
        Files.writeString(file, GEOMETRY_WITHOUT_SCENE, StandardCharsets.UTF_8);
        JsonNode f = bench("--compare-assimp", file.toString()).get("files").get(0);

        assertEquals(1, f.get("triangles").asLong());
        assertEquals(3, f.get("runs").asInt());
        assertTrue(f.get("medianMillis").asDouble() > 0, f::toString);
        assertTrue(f.get("assimpTriangles").isNull(), f::toString);
        assertTrue(f.get("assimpMedianMillis").isNull(), f::toString);
        assertTrue(f.get("assimpMinMillis").isNull(), f::toString);
        assertTrue(f.get("assimpRatio").isNull(), f::toString);
        assertFalse(f.get("assimpError").asText().isBlank(), f::toString);
    }
}
