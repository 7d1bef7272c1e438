package org.skinlab.collada;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.skinlab.model.ImportWarning;
import org.skinlab.model.Mesh;
import org.skinlab.model.MeshPart;
import org.skinlab.model.Model;
import org.skinlab.testing.TestPaths;

/**
 * {@link GeometryLoader} on small hand-made meshes: every primitive kind, triangulation order and
 * winding, inputs at any offset and set, attributes inside {@code <vertices>}, the value-based
 * vertex merge, accessors with skipped params, offsets and padding, and what is skipped with a
 * warning. Expected numbers are worked out by hand from the fixture next to each test.
 */
class GeometryImportTest {
    // ---- fixture helpers

    /** A document with one geometry "g" whose {@code <mesh>} holds {@code body}. */
    private static String doc(String body) {
        return """
                <?xml version="1.0" encoding="utf-8"?>
                <COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
                  <asset><up_axis>Y_UP</up_axis></asset>
                  <library_geometries>
                    <geometry id="g" name="G">
                      <mesh>
                %s
                      </mesh>
                    </geometry>
                  </library_geometries>
                </COLLADA>
                """.formatted(body);
    }

    /** A float {@code <source>} whose accessor names {@code params} (e.g. "X Y Z"); count from the values. */
    private static String source(String id, String params, String values) {
        String[] names = params.split(" ");
        int n = values.trim().split("\\s+").length;
        StringBuilder p = new StringBuilder();
        for (String name : names) {
            p.append("<param name=\"").append(name).append("\" type=\"float\"/>");
        }
        return """
                <source id="%1$s">
                  <float_array id="%1$s-array" count="%2$d">%3$s</float_array>
                  <technique_common>
                    <accessor source="#%1$s-array" count="%4$d" stride="%5$d">%6$s</accessor>
                  </technique_common>
                </source>
                """.formatted(id, n, values, n / names.length, names.length, p);
    }

    /** A position source "pos" with the given values and {@code <vertices id="v">} over it. */
    private static String positions(String values) {
        return source("pos", "X Y Z", values) + "<vertices id=\"v\"><input semantic=\"POSITION\" source=\"#pos\"/></vertices>\n";
    }

    private static Mesh onlyMesh(Model m) {
        assertEquals(1, m.meshes().size());
        return m.meshes().get(0);
    }

    /** The position index of every triangle corner, triangle by triangle. */
    private static int[] trianglePositions(Mesh mesh) {
        int[] t = mesh.triangles();
        int[] p = new int[t.length];
        for (int i = 0; i < t.length; i++) {
            p[i] = mesh.vertexPosition(t[i]);
        }
        return p;
    }

    /** Twice the signed area of triangle t projected on the xy plane (positive: counter-clockwise). */
    private static float signedAreaXY(Mesh mesh, int t) {
        int a = mesh.vertexPosition(mesh.triangleVertex(t, 0));
        int b = mesh.vertexPosition(mesh.triangleVertex(t, 1));
        int c = mesh.vertexPosition(mesh.triangleVertex(t, 2));
        float abx = mesh.position(b, 0) - mesh.position(a, 0);
        float aby = mesh.position(b, 1) - mesh.position(a, 1);
        float acx = mesh.position(c, 0) - mesh.position(a, 0);
        float acy = mesh.position(c, 1) - mesh.position(a, 1);
        return abx * acy - aby * acx;
    }

    private static float[] vertexValue(float[] values, int width, int vertex) {
        return Arrays.copyOfRange(values, width * vertex, width * vertex + width);
    }

    private static List<String> warningTexts(Model m) {
        return m.warnings().stream().map(ImportWarning::toString).toList();
    }

    /** Positions 0..n-1 on a line: where triangulation order, not shape, is under test. */
    private static String linePositions(int n) {
        StringBuilder sb = new StringBuilder();
        for (int i = 0; i < n; i++) {
            sb.append(i).append(" 0 0  ");
        }
        return positions(sb.toString());
    }

    // ---- primitive kinds and triangulation

    @Test
    void trianglesShareVerticesOfTheSamePosition() {
        Mesh mesh = onlyMesh(Fixtures.read("triangles.dae", doc(positions("0 0 0  1 0 0  1 1 0  0 1 0") + """
                <triangles count="2" material="mat">
                  <input semantic="VERTEX" source="#v" offset="0"/>
                  <p>0 1 2  0 2 3</p>
                </triangles>
                """)));
        assertEquals(4, mesh.positionCount());
        assertEquals(4, mesh.vertexCount()); // positions 0 and 2 are used twice but are one vertex each
        assertEquals(2, mesh.triangleCount());
        assertArrayEquals(new int[] {0, 1, 2, 0, 2, 3}, trianglePositions(mesh));
        assertEquals(List.of(new MeshPart("triangles", "mat", 0, 2)), mesh.parts());
        assertFalse(mesh.hasNormals());
        assertFalse(mesh.hasColors());
        assertEquals(0, mesh.texCoordSetCount());
        assertEquals("g", mesh.id());
        assertEquals("G", mesh.name());
    }

    @Test
    void polylistFansEachPolygonFromItsFirstCorner() {
        // Triangle i of an n-gon is (corner 0, corner i+1, corner i+2):
        //   pentagon 4 2 0 1 3 -> (4 2 0) (4 0 1) (4 1 3); triangle 5 6 7; quad 7 6 5 0 -> (7 6 5) (7 5 0)
        Model m = Fixtures.read("polylist.dae", doc(linePositions(8) + """
                <polylist count="3">
                  <input semantic="VERTEX" source="#v" offset="0"/>
                  <vcount>5 3 4</vcount>
                  <p>4 2 0 1 3  5 6 7  7 6 5 0</p>
                </polylist>
                """));
        Mesh mesh = onlyMesh(m);
        assertArrayEquals(new int[] {4, 2, 0, 4, 0, 1, 4, 1, 3, 5, 6, 7, 7, 6, 5, 7, 5, 0}, trianglePositions(mesh));
        assertEquals(List.of(new MeshPart("polylist", null, 0, 6)), mesh.parts());
        assertEquals(List.of(), m.warnings());
    }

    @Test
    void fanOfAConvexCounterClockwisePolygonKeepsItsWinding() {
        // A regular hexagon, corners counter-clockwise; the polygon starts at corner 2:
        // fan (2 3 4) (2 4 5) (2 5 0) (2 0 1), each counter-clockwise like the polygon.
        StringBuilder hex = new StringBuilder();
        for (int k = 0; k < 6; k++) {
            hex.append((float) Math.cos(k * Math.PI / 3)).append(' ').append((float) Math.sin(k * Math.PI / 3)).append(" 0  ");
        }
        Mesh mesh = onlyMesh(Fixtures.read("hexagon.dae", doc(positions(hex.toString()) + """
                <polylist count="1">
                  <input semantic="VERTEX" source="#v" offset="0"/>
                  <vcount>6</vcount>
                  <p>2 3 4 5 0 1</p>
                </polylist>
                """)));
        assertArrayEquals(new int[] {2, 3, 4, 2, 4, 5, 2, 5, 0, 2, 0, 1}, trianglePositions(mesh));
        for (int t = 0; t < 4; t++) {
            assertTrue(signedAreaXY(mesh, t) > 0, "triangle " + t + " is counter-clockwise");
        }
    }

    @Test
    void polygonsKeepsEveryPNotJustTheLast() {
        // quad 0 1 2 3 -> 2 triangles; triangle 4 5 6 -> 1; pentagon 7 8 9 10 11 -> 3: 6 in all.
        Model m = Fixtures.read("polygons.dae", doc(linePositions(12) + """
                <polygons count="3" material="wood">
                  <input semantic="VERTEX" source="#v" offset="0"/>
                  <p>0 1 2 3</p>
                  <p>4 5 6</p>
                  <p>7 8 9 10 11</p>
                </polygons>
                """));
        Mesh mesh = onlyMesh(m);
        assertEquals(6, mesh.triangleCount());
        assertArrayEquals(new int[] {0, 1, 2, 0, 2, 3, 4, 5, 6, 7, 8, 9, 7, 9, 10, 7, 10, 11}, trianglePositions(mesh));
        assertEquals(List.of(new MeshPart("polygons", "wood", 0, 6)), mesh.parts());
        assertEquals(List.of(), m.warnings());
    }

    @Test
    void polygonsWithHolesFillTheOuterRingAndWarnAboutTheHoles() {
        Model m = Fixtures.resource("geometry/polygons-with-holes.dae");
        Mesh mesh = onlyMesh(m);
        // See the fixture's comment: (0 1 2) (0 2 3) from the first <ph>, then (10 11 12), (13 14 15).
        assertArrayEquals(new int[] {0, 1, 2, 0, 2, 3, 10, 11, 12, 13, 14, 15}, trianglePositions(mesh));
        assertEquals(List.of(new MeshPart("polygons", "stone", 0, 4)), mesh.parts());
        assertEquals(19, mesh.positionCount());
        for (int hole : new int[] {4, 5, 6, 7, 8, 9, 16, 17, 18}) {
            assertEquals(0, mesh.verticesOfPosition(hole).length, "hole corner " + hole + " is in no triangle");
        }
        assertEquals(1, m.warnings().size(), () -> warningTexts(m).toString());
        String w = m.warnings().get(0).toString();
        assertTrue(w.contains("<polygons") && w.contains("3 polygon holes (<h>) ignored"), w);
        assertTrue(w.contains("<geometry id=\"holes\">"), w);
        for (int t = 0; t < mesh.triangleCount(); t++) {
            assertTrue(signedAreaXY(mesh, t) > 0);
        }
    }

    @Test
    void trifansFanEachPFromItsFirstCorner() {
        // fan 0 1 2 3 4 -> (0 1 2) (0 2 3) (0 3 4); fan 5 6 7 -> (5 6 7)
        Mesh mesh = onlyMesh(Fixtures.read("trifans.dae", doc(linePositions(8) + """
                <trifans count="2" material="fan">
                  <input semantic="VERTEX" source="#v" offset="0"/>
                  <p>0 1 2 3 4</p>
                  <p>5 6 7</p>
                </trifans>
                """)));
        assertArrayEquals(new int[] {0, 1, 2, 0, 2, 3, 0, 3, 4, 5, 6, 7}, trianglePositions(mesh));
        assertEquals(List.of(new MeshPart("trifans", "fan", 0, 4)), mesh.parts());
    }

    @Test
    void tristripsReverseEveryOtherTriangleToKeepTheWinding() {
        // Zigzag in the z=0 plane: 0(0,1) 1(0,0) 2(1,1) 3(1,0) 4(2,1) 5(2,0).
        // Strip triangle k is (k, k+1, k+2) with every odd one reversed, counting afresh in
        // each <p>: strip 0 1 2 3 4 -> (0 1 2) (2 1 3) (2 3 4); strip 5 4 3 2 -> (5 4 3) (4 2 3).
        // All counter-clockwise, like the first triangle of each strip (signed area 1/2 each).
        Mesh mesh = onlyMesh(Fixtures.read("tristrips.dae", doc(positions("0 1 0  0 0 0  1 1 0  1 0 0  2 1 0  2 0 0") + """
                <tristrips count="2">
                  <input semantic="VERTEX" source="#v" offset="0"/>
                  <p>0 1 2 3 4</p>
                  <p>5 4 3 2</p>
                </tristrips>
                """)));
        assertEquals(5, mesh.triangleCount());
        int[] expected = {0, 1, 2, 2, 1, 3, 2, 3, 4, 5, 4, 3, 4, 2, 3};
        int[] actual = trianglePositions(mesh);
        for (int t = 0; t < 5; t++) {
            // Same triangle and same winding: equal up to a rotation of its corners.
            assertArrayEquals(rotated(Arrays.copyOfRange(expected, 3 * t, 3 * t + 3)),
                    rotated(Arrays.copyOfRange(actual, 3 * t, 3 * t + 3)), "triangle " + t);
        }
        for (int t = 0; t < 5; t++) {
            assertEquals(1f, signedAreaXY(mesh, t), 0f, "strip triangle " + t + " counter-clockwise");
        }
    }

    /** The corners rotated so that the smallest comes first (keeps the winding). */
    private static int[] rotated(int[] tri) {
        int min = tri[0] <= tri[1] && tri[0] <= tri[2] ? 0 : tri[1] <= tri[2] ? 1 : 2;
        return new int[] {tri[min], tri[(min + 1) % 3], tri[(min + 2) % 3]};
    }

    @Test
    void severalPrimitivesBecomePartsWithTheirRangesAndMaterials() {
        Model m = Fixtures.resource("geometry/several-primitives.dae");
        Mesh mesh = onlyMesh(m);
        // Worked out in the fixture's comment.
        assertEquals(List.of(
                new MeshPart("triangles", "red", 0, 2),
                new MeshPart("polylist", "blue", 2, 3),
                new MeshPart("polygons", null, 5, 1),
                new MeshPart("tristrips", "green", 6, 3)), mesh.parts());
        assertEquals(9, mesh.triangleCount());
        int[] tp = trianglePositions(mesh);
        assertArrayEquals(new int[] {0, 1, 6, 0, 6, 5}, Arrays.copyOfRange(tp, 0, 6));
        assertArrayEquals(new int[] {1, 2, 7, 1, 7, 6, 2, 3, 8}, Arrays.copyOfRange(tp, 6, 15));
        assertArrayEquals(new int[] {3, 4, 9}, Arrays.copyOfRange(tp, 15, 18));
        assertArrayEquals(rotated(new int[] {5, 0, 6}), rotated(Arrays.copyOfRange(tp, 18, 21)));
        assertArrayEquals(rotated(new int[] {0, 1, 6}), rotated(Arrays.copyOfRange(tp, 21, 24)));
        assertArrayEquals(rotated(new int[] {6, 1, 7}), rotated(Arrays.copyOfRange(tp, 24, 27)));
        for (int t = 0; t < 9; t++) {
            assertTrue(signedAreaXY(mesh, t) > 0, "triangle " + t + " counter-clockwise");
        }
        // The primitives share one <vertices> and carry no other attribute: one vertex per
        // position, the same vertex wherever the position is used.
        assertEquals(10, mesh.vertexCount());
        for (int p = 0; p < 10; p++) {
            assertEquals(1, mesh.verticesOfPosition(p).length, "position " + p);
        }
        assertEquals(1, m.warnings().size(), () -> warningTexts(m).toString());
        assertTrue(m.warnings().get(0).toString().contains("<lines"), m.warnings().get(0)::toString);
    }

    @Test
    void linesAndLinestripsAreSkippedWithAWarningAndAddNoTriangles() {
        Model m = Fixtures.read("lines.dae", doc(linePositions(6) + """
                <lines count="2">
                  <input semantic="VERTEX" source="#v" offset="0"/>
                  <p>0 3  3 4</p>
                </lines>
                <triangles count="1">
                  <input semantic="VERTEX" source="#v" offset="0"/>
                  <p>0 1 2</p>
                </triangles>
                <linestrips count="1">
                  <input semantic="VERTEX" source="#v" offset="0"/>
                  <p>3 4 5</p>
                </linestrips>
                """));
        Mesh mesh = onlyMesh(m);
        assertEquals(1, mesh.triangleCount());
        assertEquals(List.of(new MeshPart("triangles", null, 0, 1)), mesh.parts());
        assertEquals(3, mesh.vertexCount()); // line corners make no vertices
        assertEquals(6, mesh.positionCount());
        List<String> w = warningTexts(m);
        assertEquals(2, w.size(), w::toString);
        assertTrue(w.get(0).startsWith("<lines> in <geometry id=\"g\">") && w.get(0).contains("skipped"), w.get(0));
        assertTrue(w.get(1).startsWith("<linestrips> in <geometry id=\"g\">") && w.get(1).contains("skipped"), w.get(1));
    }

    @Test
    void polygonsWithFewerThanThreeCornersAreWarnedAndYieldNoTriangles() {
        // polylist: vcount 3 2 1 0 4 -> 1 + 0 + 0 + 0 + 2 = 3 triangles, 3 degenerate polygons.
        // polygons: corners 2 and 3 -> 1 triangle, 1 degenerate. tristrips: 2 corners -> 1 degenerate.
        Model m = Fixtures.read("degenerate.dae", doc(linePositions(10) + """
                <polylist count="5">
                  <input semantic="VERTEX" source="#v" offset="0"/>
                  <vcount>3 2 1 0 4</vcount>
                  <p>0 1 2  3 4  5  6 7 8 9</p>
                </polylist>
                <polygons count="2">
                  <input semantic="VERTEX" source="#v" offset="0"/>
                  <p>0 1</p>
                  <p>2 3 4</p>
                </polygons>
                <tristrips count="1">
                  <input semantic="VERTEX" source="#v" offset="0"/>
                  <p>5 6</p>
                </tristrips>
                """));
        Mesh mesh = onlyMesh(m);
        assertArrayEquals(new int[] {0, 1, 2, 6, 7, 8, 6, 8, 9, 2, 3, 4}, trianglePositions(mesh));
        assertEquals(List.of(new MeshPart("polylist", null, 0, 3), new MeshPart("polygons", null, 3, 1),
                new MeshPart("tristrips", null, 4, 0)), mesh.parts());
        List<String> w = warningTexts(m);
        assertEquals(3, w.size(), w::toString);
        assertTrue(w.get(0).startsWith("<polylist") && w.get(0).contains("3 polygons with fewer than 3 corners"), w.get(0));
        assertTrue(w.get(1).startsWith("<polygons") && w.get(1).contains("1 polygon with fewer than 3 corners yields no triangles"), w.get(1));
        assertTrue(w.get(2).startsWith("<tristrips") && w.get(2).contains("1 polygon with fewer than 3 corners yields no triangles"), w.get(2));
    }

    // ---- inputs: offsets, sets, semantics

    @Test
    void inputsAtAnyOffsetAndTexcoordSetsInAnyOrder() {
        // One quad whose corners hold five indices in the order the inputs declare:
        //   offset 0 TEXCOORD set 0, 1 VERTEX, 2 NORMAL, 3 TEXCOORD set 1, 4 COLOR (RGB)
        // (declared out of order on purpose: set 1 first, VERTEX third).
        // corner: uv0 pos nrm uv1 col
        //         3   0   0   1   1
        //         2   1   0   0   0
        //         1   2   0   3   1
        //         0   3   0   2   0
        Model m = Fixtures.read("offsets.dae", doc(positions("0 0 0  1 0 0  1 1 0  0 1 0")
                + source("nrm", "X Y Z", "0 0 1")
                + source("uv0", "S T", "0 0  1 0  1 1  0 1")
                + source("uv1", "S T", "0.25 0.75  0.5 0.5  0.75 0.25  0.125 0.875")
                + source("rgb", "R G B", "1 0 0  0 0.5 1")
                + """
                <polylist count="1">
                  <input semantic="TEXCOORD" source="#uv1" offset="3" set="1"/>
                  <input semantic="NORMAL" source="#nrm" offset="2"/>
                  <input semantic="VERTEX" source="#v" offset="1"/>
                  <input semantic="TEXCOORD" source="#uv0" offset="0" set="0"/>
                  <input semantic="COLOR" source="#rgb" offset="4"/>
                  <vcount>4</vcount>
                  <p>3 0 0 1 1  2 1 0 0 0  1 2 0 3 1  0 3 0 2 0</p>
                </polylist>
                """));
        Mesh mesh = onlyMesh(m);
        assertEquals(4, mesh.vertexCount());
        assertArrayEquals(new int[] {0, 1, 2, 0, 2, 3}, trianglePositions(mesh));
        assertEquals(2, mesh.texCoordSetCount());
        float[][] uv0ByPosition = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
        float[][] uv1ByPosition = {{0.5f, 0.5f}, {0.25f, 0.75f}, {0.125f, 0.875f}, {0.75f, 0.25f}};
        float[][] colorByPosition = {{0, 0.5f, 1, 1}, {1, 0, 0, 1}, {0, 0.5f, 1, 1}, {1, 0, 0, 1}};
        float[] uv0 = mesh.texCoords(0);
        float[] uv1 = mesh.texCoords(1);
        float[] colors = mesh.colors();
        float[] normals = mesh.normals();
        for (int v = 0; v < 4; v++) {
            int p = mesh.vertexPosition(v);
            assertArrayEquals(uv0ByPosition[p], vertexValue(uv0, 2, v), "set 0 at position " + p);
            assertArrayEquals(uv1ByPosition[p], vertexValue(uv1, 2, v), "set 1 at position " + p);
            assertArrayEquals(colorByPosition[p], vertexValue(colors, 4, v), "colour (alpha 1) at position " + p);
            assertArrayEquals(new float[] {0, 0, 1}, vertexValue(normals, 3, v));
        }
        assertEquals(List.of(), m.warnings());
    }

    @Test
    void inputsSharingAnOffsetUseTheSameIndexAndUnusedOffsetsCountInTheStride() {
        // VERTEX and NORMAL share offset 0, TEXCOORD is at offset 2 and nothing uses offset 1:
        // each corner has 3 indices (position/normal, ignored, uv).
        Mesh mesh = onlyMesh(Fixtures.read("shared-offset.dae", doc(positions("0 0 0  1 0 0  0 1 0")
                + source("nrm", "X Y Z", "1 0 0  0 1 0  0 0 1")
                + source("uv", "S T", "0.5 0.25  0.75 1")
                + """
                <triangles count="1">
                  <input semantic="VERTEX" source="#v" offset="0"/>
                  <input semantic="NORMAL" source="#nrm" offset="0"/>
                  <input semantic="TEXCOORD" source="#uv" offset="2"/>
                  <p>0 99 1  1 99 0  2 99 1</p>
                </triangles>
                """)));
        assertArrayEquals(new int[] {0, 1, 2}, trianglePositions(mesh));
        float[][] normalByPosition = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        float[][] uvByPosition = {{0.75f, 1}, {0.5f, 0.25f}, {0.75f, 1}};
        for (int v = 0; v < 3; v++) {
            int p = mesh.vertexPosition(v);
            assertArrayEquals(normalByPosition[p], vertexValue(mesh.normals(), 3, v));
            assertArrayEquals(uvByPosition[p], vertexValue(mesh.texCoords(0), 2, v));
        }
    }

    @Test
    void colorsWithThreeComponentsGetAlphaOneAndFourComponentsKeepTheirAlpha() {
        String triangle = """
                <triangles count="1">
                  <input semantic="VERTEX" source="#v" offset="0"/>
                  <input semantic="COLOR" source="#col" offset="1"/>
                  <p>0 0  1 0  2 1</p>
                </triangles>
                """;
        Mesh rgb = onlyMesh(Fixtures.read("rgb.dae", doc(positions("0 0 0  1 0 0  0 1 0")
                + source("col", "R G B", "0.2 0.4 0.6  1 1 1") + triangle)));
        assertTrue(rgb.hasColors());
        assertColorsByPosition(rgb, new float[][] {{0.2f, 0.4f, 0.6f, 1}, {0.2f, 0.4f, 0.6f, 1}, {1, 1, 1, 1}});

        Mesh rgba = onlyMesh(Fixtures.read("rgba.dae", doc(positions("0 0 0  1 0 0  0 1 0")
                + source("col", "R G B A", "0.2 0.4 0.6 0.25  1 1 1 0") + triangle)));
        assertColorsByPosition(rgba, new float[][] {{0.2f, 0.4f, 0.6f, 0.25f}, {0.2f, 0.4f, 0.6f, 0.25f}, {1, 1, 1, 0}});
    }

    private static void assertColorsByPosition(Mesh mesh, float[][] byPosition) {
        assertEquals(byPosition.length, mesh.vertexCount());
        for (int v = 0; v < mesh.vertexCount(); v++) {
            int p = mesh.vertexPosition(v);
            assertArrayEquals(byPosition[p], vertexValue(mesh.colors(), 4, v), "colour at position " + p);
        }
    }

    @Test
    void attributeInputsInsideVerticesAreIndexedLikeThePosition() {
        // <vertices> carries NORMAL and TEXCOORD: one normal and one uv per position, found
        // through the VERTEX index (offset 1 here, so nothing else can stand in for it). The
        // primitive adds a second uv set per corner at offset 0.
        Model m = Fixtures.read("vertex-attributes.dae", doc(source("pos", "X Y Z", "0 0 0  1 0 0  1 1 0  0 1 0")
                + source("nrm", "X Y Z", "0 0 1  0 1 0  1 0 0  0 0 -1")
                + source("uv", "S T", "0.1 0.2  0.3 0.4  0.5 0.6  0.7 0.8")
                + source("uv2", "S T", "9 8  7 6")
                + """
                <vertices id="v">
                  <input semantic="POSITION" source="#pos"/>
                  <input semantic="NORMAL" source="#nrm"/>
                  <input semantic="TEXCOORD" source="#uv" set="0"/>
                </vertices>
                <triangles count="2">
                  <input semantic="TEXCOORD" source="#uv2" offset="0" set="1"/>
                  <input semantic="VERTEX" source="#v" offset="1"/>
                  <p>0 0  0 1  0 2  0 0  0 2  1 3</p>
                </triangles>
                """));
        Mesh mesh = onlyMesh(m);
        assertEquals(4, mesh.vertexCount());
        assertEquals(2, mesh.texCoordSetCount());
        float[][] normalByPosition = {{0, 0, 1}, {0, 1, 0}, {1, 0, 0}, {0, 0, -1}};
        float[][] uvByPosition = {{0.1f, 0.2f}, {0.3f, 0.4f}, {0.5f, 0.6f}, {0.7f, 0.8f}};
        float[][] uv2ByPosition = {{9, 8}, {9, 8}, {9, 8}, {7, 6}};
        for (int v = 0; v < 4; v++) {
            int p = mesh.vertexPosition(v);
            assertArrayEquals(normalByPosition[p], vertexValue(mesh.normals(), 3, v), "normal at position " + p);
            assertArrayEquals(uvByPosition[p], vertexValue(mesh.texCoords(0), 2, v), "uv at position " + p);
            assertArrayEquals(uv2ByPosition[p], vertexValue(mesh.texCoords(1), 2, v), "uv set 1 at position " + p);
        }
        assertEquals(List.of(), m.warnings());
    }

    @Test
    void texcoordInputWithoutSetTakesTheLowestSetNoOtherInputUses() {
        // "set 1" then an input without a set: the unnamed one becomes set 0, so both survive
        // (numbering unnamed inputs by their position would make both set 1 and lose one).
        Model m = Fixtures.read("unnamed-set.dae", doc(positions("0 0 0  1 0 0  0 1 0")
                + source("uvA", "S T", "1 1  2 2  3 3") + source("uvB", "S T", "7 7  8 8  9 9")
                + """
                <triangles count="1">
                  <input semantic="VERTEX" source="#v" offset="0"/>
                  <input semantic="TEXCOORD" source="#uvA" offset="0" set="1"/>
                  <input semantic="TEXCOORD" source="#uvB" offset="0"/>
                  <p>0 1 2</p>
                </triangles>
                """));
        Mesh mesh = onlyMesh(m);
        assertEquals(2, mesh.texCoordSetCount());
        for (int v = 0; v < 3; v++) {
            int p = mesh.vertexPosition(v);
            assertArrayEquals(new float[] {7 + p, 7 + p}, vertexValue(mesh.texCoords(0), 2, v), "set 0 (unnamed)");
            assertArrayEquals(new float[] {1 + p, 1 + p}, vertexValue(mesh.texCoords(1), 2, v), "set 1");
        }
        assertEquals(List.of(), m.warnings());
    }

    @Test
    void aSecondTexcoordInputForTheSameSetIsIgnoredWithAWarning() {
        Model m = Fixtures.read("same-set.dae", doc(positions("0 0 0  1 0 0  0 1 0")
                + source("uvA", "S T", "1 1  2 2  3 3") + source("uvB", "S T", "7 7  8 8  9 9")
                + """
                <triangles count="1">
                  <input semantic="VERTEX" source="#v" offset="0"/>
                  <input semantic="TEXCOORD" source="#uvA" offset="0" set="0"/>
                  <input semantic="TEXCOORD" source="#uvB" offset="0" set="0"/>
                  <p>0 1 2</p>
                </triangles>
                """));
        Mesh mesh = onlyMesh(m);
        assertEquals(1, mesh.texCoordSetCount());
        assertArrayEquals(new float[] {1, 1}, vertexValue(mesh.texCoords(0), 2, 0), "the first input wins");
        assertEquals(1, m.warnings().size(), () -> m.warnings().toString());
        assertTrue(m.warnings().get(0).toString().contains("a second TEXCOORD input for set 0"));
    }

    @Test
    void aPrimitiveWithoutATexcoordSetOthersHaveGetsZeroUvsAndAWarning() {
        Model m = Fixtures.read("missing-set.dae", doc(positions("0 0 0  1 0 0  0 1 0  1 1 0")
                + source("uv", "S T", "0.5 0.5")
                + """
                <triangles count="1" material="textured">
                  <input semantic="VERTEX" source="#v" offset="0"/>
                  <input semantic="TEXCOORD" source="#uv" offset="1" set="0"/>
                  <p>0 0  1 0  2 0</p>
                </triangles>
                <triangles count="1" material="plain">
                  <input semantic="VERTEX" source="#v" offset="0"/>
                  <p>1 3 2</p>
                </triangles>
                """));
        Mesh mesh = onlyMesh(m);
        // Position 3 is only used by the untextured triangle: its vertex has uv (0, 0).
        int v3 = mesh.verticesOfPosition(3)[0];
        assertArrayEquals(new float[] {0, 0}, vertexValue(mesh.texCoords(0), 2, v3));
        assertEquals(1, m.warnings().size(), () -> m.warnings().toString());
        assertTrue(m.warnings().get(0).toString().contains("has no TEXCOORD set 0 while other primitives do"));
    }

    // ---- the vertex merge

    @Test
    void cornersWithEqualValuesMergeEvenWhenTheFileUsesDifferentIndices() {
        // uv 0 and uv 1 are the same value, as are normals 0 and 1 (Blender writes one index per
        // polygon corner). Position 0 is used with (uv0, n0) and with (uv1, n1): one vertex.
        // Positions 1, 2, 3: one vertex each. 4 vertices, not 6 corners' worth.
        Mesh mesh = onlyMesh(Fixtures.read("merge.dae", doc(positions("0 0 0  1 0 0  1 1 0  0 1 0")
                + source("uv", "S T", "0.5 0.5  0.5 0.5  0 0")
                + source("nrm", "X Y Z", "0 0 1  0 0 1")
                + """
                <triangles count="2">
                  <input semantic="VERTEX" source="#v" offset="0"/>
                  <input semantic="TEXCOORD" source="#uv" offset="1" set="0"/>
                  <input semantic="NORMAL" source="#nrm" offset="2"/>
                  <p>0 0 0  1 2 0  2 2 0    0 1 1  2 2 1  3 2 0</p>
                </triangles>
                """)));
        assertEquals(4, mesh.vertexCount());
        assertEquals(mesh.triangleVertex(0, 0), mesh.triangleVertex(1, 0), "position 0 is one vertex");
        assertEquals(mesh.triangleVertex(0, 2), mesh.triangleVertex(1, 1), "position 2 is one vertex");
        assertEquals(1, mesh.verticesOfPosition(0).length);
    }

    @Test
    void negativeAndPositiveZeroMerge() {
        // Normals 0 and 1 and uvs 0 and 1 differ only in the sign of zero.
        Mesh mesh = onlyMesh(Fixtures.read("zeros.dae", doc(positions("0 0 0  1 0 0  0 1 0")
                + source("nrm", "X Y Z", "0 0 1  -0 -0.0 1")
                + source("uv", "S T", "0 0.5  -0.0 0.5")
                + """
                <triangles count="2">
                  <input semantic="VERTEX" source="#v" offset="0"/>
                  <input semantic="NORMAL" source="#nrm" offset="1"/>
                  <input semantic="TEXCOORD" source="#uv" offset="2"/>
                  <p>0 0 0  1 0 0  2 0 0    0 1 1  1 1 1  2 1 1</p>
                </triangles>
                """)));
        assertEquals(3, mesh.vertexCount());
        for (int c = 0; c < 3; c++) {
            assertEquals(mesh.triangleVertex(0, c), mesh.triangleVertex(1, c), "second triangle reuses corner " + c);
        }
        for (int v = 0; v < 3; v++) {
            assertEquals(0f, mesh.normals()[3 * v], 0f);
            assertEquals(0f, mesh.texCoords(0)[2 * v], 0f);
        }
    }

    @Test
    void differentNormalsAtOnePositionStaySeparateVertices() {
        // Two faces of a cube edge share positions 0 and 1 but have normals +z and +y: positions
        // 0 and 1 get two vertices each (a hard edge), positions 2 and 3 one each.
        Mesh mesh = onlyMesh(Fixtures.read("hard-edge.dae", doc(positions("0 0 0  1 0 0  1 -1 0  1 0 1")
                + source("nrm", "X Y Z", "0 0 1  0 1 0")
                + """
                <triangles count="2">
                  <input semantic="VERTEX" source="#v" offset="0"/>
                  <input semantic="NORMAL" source="#nrm" offset="1"/>
                  <p>0 0  2 0  1 0    0 1  1 1  3 1</p>
                </triangles>
                """)));
        assertEquals(6, mesh.vertexCount());
        assertVerticesOfPositionHaveNormals(mesh, 0, new float[][] {{0, 0, 1}, {0, 1, 0}});
        assertVerticesOfPositionHaveNormals(mesh, 1, new float[][] {{0, 0, 1}, {0, 1, 0}});
        assertVerticesOfPositionHaveNormals(mesh, 2, new float[][] {{0, 0, 1}});
        assertVerticesOfPositionHaveNormals(mesh, 3, new float[][] {{0, 1, 0}});
    }

    /** The vertices of position p, ascending, carry exactly these normals (in any order). */
    private static void assertVerticesOfPositionHaveNormals(Mesh mesh, int p, float[][] normals) {
        int[] vs = mesh.verticesOfPosition(p);
        assertEquals(normals.length, vs.length, "vertices of position " + p);
        List<String> expected = new ArrayList<>();
        List<String> actual = new ArrayList<>();
        for (int i = 0; i < vs.length; i++) {
            assertEquals(p, mesh.vertexPosition(vs[i]));
            if (i > 0) {
                assertTrue(vs[i] > vs[i - 1], "ascending");
            }
            expected.add(Arrays.toString(normals[i]));
            actual.add(Arrays.toString(vertexValue(mesh.normals(), 3, vs[i])));
        }
        expected.sort(null);
        actual.sort(null);
        assertEquals(expected, actual, "normals at position " + p);
    }

    @Test
    void primitivesSharingVerticesShareTheVerticesOfTheirCommonPositions() {
        // Two <triangles> over one <vertices>: (0 1 2) smooth with normal n0 = (0 0 1) and
        // (0 2 3) in a second primitive with the same normal value through index 1 -> the
        // shared positions 0 and 2 stay one vertex each across the primitives; a third primitive
        // with normal (1 0 0) on position 0 adds a second vertex to position 0.
        Mesh mesh = onlyMesh(Fixtures.read("shared-vertices.dae", doc(positions("0 0 0  1 0 0  1 1 0  0 1 0  -1 0 0")
                + source("nrm", "X Y Z", "0 0 1  0 0 1  1 0 0")
                + """
                <triangles count="1" material="a">
                  <input semantic="VERTEX" source="#v" offset="0"/>
                  <input semantic="NORMAL" source="#nrm" offset="1"/>
                  <p>0 0  1 0  2 0</p>
                </triangles>
                <triangles count="1" material="b">
                  <input semantic="VERTEX" source="#v" offset="0"/>
                  <input semantic="NORMAL" source="#nrm" offset="1"/>
                  <p>0 1  2 1  3 1</p>
                </triangles>
                <triangles count="1" material="c">
                  <input semantic="VERTEX" source="#v" offset="0"/>
                  <input semantic="NORMAL" source="#nrm" offset="1"/>
                  <p>0 2  3 2  4 2</p>
                </triangles>
                """)));
        assertEquals(List.of(new MeshPart("triangles", "a", 0, 1), new MeshPart("triangles", "b", 1, 1),
                new MeshPart("triangles", "c", 2, 1)), mesh.parts());
        assertEquals(mesh.triangleVertex(0, 0), mesh.triangleVertex(1, 0));
        assertEquals(mesh.triangleVertex(0, 2), mesh.triangleVertex(1, 1));
        // Position 0: +z (primitives a and b) and +x (c); position 3: +z (b) and +x (c).
        assertEquals(7, mesh.vertexCount());
        assertVerticesOfPositionHaveNormals(mesh, 0, new float[][] {{0, 0, 1}, {1, 0, 0}});
        assertVerticesOfPositionHaveNormals(mesh, 1, new float[][] {{0, 0, 1}});
        assertVerticesOfPositionHaveNormals(mesh, 2, new float[][] {{0, 0, 1}});
        assertVerticesOfPositionHaveNormals(mesh, 3, new float[][] {{0, 0, 1}, {1, 0, 0}});
        assertVerticesOfPositionHaveNormals(mesh, 4, new float[][] {{1, 0, 0}});
    }

    // ---- accessors and the position count

    @Test
    void anUnnamedParamSkipsItsSlot() {
        // Positions: stride 4, params X, (unnamed), Y, Z -> the second value of each group is skipped.
        // uv: stride 3, params (unnamed), S, T.
        String body = """
                <source id="pos">
                  <float_array id="pos-array" count="12">1 99 2 3  4 99 5 6  7 99 8 9</float_array>
                  <technique_common>
                    <accessor source="#pos-array" count="3" stride="4">
                      <param name="X" type="float"/>
                      <param type="float"/>
                      <param name="Y" type="float"/>
                      <param name="Z" type="float"/>
                    </accessor>
                  </technique_common>
                </source>
                <source id="uv">
                  <float_array id="uv-array" count="6">-1 0.25 0.5  -1 0.75 1</float_array>
                  <technique_common>
                    <accessor source="#uv-array" count="2" stride="3">
                      <param type="float"/>
                      <param name="S" type="float"/>
                      <param name="T" type="float"/>
                    </accessor>
                  </technique_common>
                </source>
                <vertices id="v"><input semantic="POSITION" source="#pos"/></vertices>
                <triangles count="1">
                  <input semantic="VERTEX" source="#v" offset="0"/>
                  <input semantic="TEXCOORD" source="#uv" offset="1" set="0"/>
                  <p>0 0  1 1  2 1</p>
                </triangles>
                """;
        Mesh mesh = onlyMesh(Fixtures.read("unnamed-param.dae", doc(body)));
        assertArrayEquals(new float[] {1, 2, 3, 4, 5, 6, 7, 8, 9}, mesh.positions());
        assertArrayEquals(new float[] {0.25f, 0.5f, 0.75f, 1, 0.75f, 1}, mesh.texCoords(0));
    }

    @Test
    void accessorOffsetAndAStrideWiderThanTheParamsAreHonoured() {
        // Positions start at value 2 and come in groups of 4 (X Y Z and one padding value).
        // Normals: stride 4 with X Y Z, offset 1.
        String body = """
                <source id="pos">
                  <float_array id="pos-array" count="14">-5 -5  1 2 3 -9  4 5 6 -9  7 8 9 -9</float_array>
                  <technique_common>
                    <accessor source="#pos-array" count="3" offset="2" stride="4">
                      <param name="X" type="float"/>
                      <param name="Y" type="float"/>
                      <param name="Z" type="float"/>
                    </accessor>
                  </technique_common>
                </source>
                <source id="nrm">
                  <float_array id="nrm-array" count="9">-5  0 0 1 -9  1 0 0 -9</float_array>
                  <technique_common>
                    <accessor source="#nrm-array" count="2" offset="1" stride="4">
                      <param name="X" type="float"/>
                      <param name="Y" type="float"/>
                      <param name="Z" type="float"/>
                    </accessor>
                  </technique_common>
                </source>
                <vertices id="v"><input semantic="POSITION" source="#pos"/></vertices>
                <triangles count="1">
                  <input semantic="VERTEX" source="#v" offset="0"/>
                  <input semantic="NORMAL" source="#nrm" offset="1"/>
                  <p>0 1  1 0  2 1</p>
                </triangles>
                """;
        Mesh mesh = onlyMesh(Fixtures.read("accessor-offset.dae", doc(body)));
        assertEquals(3, mesh.positionCount());
        assertArrayEquals(new float[] {1, 2, 3, 4, 5, 6, 7, 8, 9}, mesh.positions());
        float[][] normalByPosition = {{1, 0, 0}, {0, 0, 1}, {1, 0, 0}};
        for (int v = 0; v < 3; v++) {
            assertArrayEquals(normalByPosition[mesh.vertexPosition(v)], vertexValue(mesh.normals(), 3, v));
        }
    }

    @Test
    void positionsAreCountedFromTheVerticesPositionSource() {
        // Another source comes first; the position array holds 15 values, but the accessor reads
        // 4 positions; only 3 of them are used by triangles. positionCount is 4: the accessor's
        // count, neither the array's 5 groups nor the 3 positions in use nor the 2 normals.
        String body = source("nrm", "X Y Z", "0 0 1  0 1 0") + """
                <source id="pos">
                  <float_array id="pos-array" count="15">0 0 0  1 0 0  0 1 0  5 5 5  8 8 8</float_array>
                  <technique_common>
                    <accessor source="#pos-array" count="4" stride="3">
                      <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
                    </accessor>
                  </technique_common>
                </source>
                <vertices id="v"><input semantic="POSITION" source="#pos"/></vertices>
                <triangles count="1">
                  <input semantic="VERTEX" source="#v" offset="0"/>
                  <input semantic="NORMAL" source="#nrm" offset="1"/>
                  <p>0 0  1 0  2 1</p>
                </triangles>
                """;
        Mesh mesh = onlyMesh(Fixtures.read("position-count.dae", doc(body)));
        assertEquals(4, mesh.positionCount());
        assertArrayEquals(new float[] {0, 0, 0, 1, 0, 0, 0, 1, 0, 5, 5, 5}, mesh.positions());
        assertEquals(3, mesh.vertexCount());
        assertEquals(0, mesh.verticesOfPosition(3).length, "position 3 is in no triangle");
    }

    @Test
    void cornerIndexBeyondThePositionCountIsRefused() {
        // The array holds 5 positions but the accessor declares 4: index 4 is out of range.
        String body = """
                <source id="pos">
                  <float_array id="pos-array" count="15">0 0 0  1 0 0  0 1 0  5 5 5  8 8 8</float_array>
                  <technique_common>
                    <accessor source="#pos-array" count="4" stride="3">
                      <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
                    </accessor>
                  </technique_common>
                </source>
                <vertices id="v"><input semantic="POSITION" source="#pos"/></vertices>
                <triangles count="1">
                  <input semantic="VERTEX" source="#v" offset="0"/>
                  <p>0 1 4</p>
                </triangles>
                """;
        String m = Fixtures.error("position-range.dae", doc(body)).getMessage();
        assertTrue(m.contains("position-range.dae") && m.contains("index 4") && m.contains("4 positions"), m);
    }

    // ---- the corpus

    @Test
    void corpusPolygonsFileYieldsOneTriangleFanPerP() throws Exception {
        // S12_library_animation_clips.dae (assimp's test model) describes its cube with one
        // <polygons count="26"> of 26 <p> elements, all quads. Expected numbers were derived
        // independently with Python's xml.etree: for every <p>, corners = len(p.text.split()) //
        // (max input offset + 1) (all four inputs are at offset 0), triangles += corners - 2;
        // that gives 26 polygons, 52 triangles, and the POSITION accessor count is 72.
        Model m = ColladaImporter.read(TestPaths.corpusFileOrSkip("S12_library_animation_clips.dae"));
        Mesh mesh = m.mesh("id-mesh-10").orElseThrow();
        assertEquals(52, mesh.triangleCount());
        assertEquals(72, mesh.positionCount());
        assertEquals(List.of(new MeshPart("polygons", "id-trimat-11", 0, 52)), mesh.parts());
        assertTrue(mesh.hasNormals() && mesh.hasColors());
        assertEquals(1, mesh.texCoordSetCount());
    }
}
