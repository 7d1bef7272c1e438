package org.skinlab.collada;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.nio.charset.Charset;
import java.nio.charset.StandardCharsets;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.skinlab.model.AssetInfo;
import org.skinlab.model.Mesh;
import org.skinlab.model.Model;
import org.skinlab.model.UpAxis;

/**
 * {@code <asset>} is recorded as written (up axis, unit; nothing converted), its absence is
 * tolerated with a warning, and documents in UTF-8 (with or without BOM), UTF-16 (LE and BE,
 * with BOM) and a declared ISO-8859-1 keep their non-ASCII names.
 */
class AssetAndEncodingTest {
    /** Names that must survive decoding: umlauts and ß (Latin-1), CJK (BMP) and an emoji (a surrogate pair). */
    private static final String GERMAN = "Würfel ÄÖÜ äöü ß";
    private static final String WIDE = GERMAN + " 立方体 \uD83E\uDDCA";

    /** A triangle geometry named {@code name} with id "g", after {@code asset} (which may be empty). */
    private static String doc(String encoding, String asset, String name) {
        return """
                <?xml version="1.0" encoding="%s"?>
                <COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
                %s
                  <library_geometries>
                    <geometry id="g" name="%s">
                      <mesh>
                        <source id="pos">
                          <float_array id="pos-array" count="9">0 0 0  100 0 0  0 250.5 -3</float_array>
                          <technique_common>
                            <accessor source="#pos-array" count="3" stride="3">
                              <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
                            </accessor>
                          </technique_common>
                        </source>
                        <vertices id="v"><input semantic="POSITION" source="#pos"/></vertices>
                        <triangles count="1">
                          <input semantic="VERTEX" source="#v" offset="0"/>
                          <p>0 1 2</p>
                        </triangles>
                      </mesh>
                    </geometry>
                  </library_geometries>
                </COLLADA>
                """.formatted(encoding, asset, name);
    }

    private static Model readBytes(String name, byte[] bytes) throws Exception {
        return ColladaImporter.read(new ByteArrayInputStream(bytes), name);
    }

    private static byte[] concat(byte[] a, byte[] b) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        out.writeBytes(a);
        out.writeBytes(b);
        return out.toByteArray();
    }

    /** The whole document decoded: name, and the numbers at its end still parse. */
    private static void assertDecoded(Model m, String name) {
        assertEquals(1, m.meshes().size());
        Mesh mesh = m.meshes().get(0);
        assertEquals(name, mesh.name());
        assertArrayEquals(new float[] {0, 0, 0, 100, 0, 0, 0, 250.5f, -3}, mesh.positions());
        assertEquals(1, mesh.triangleCount());
        assertEquals(List.of(), m.warnings());
    }

    private static final String PLAIN_ASSET = "<asset><up_axis>Y_UP</up_axis></asset>";

    // ---- asset

    @ParameterizedTest
    @EnumSource(UpAxis.class)
    void upAxisIsRecordedAsWritten(UpAxis axis) {
        Model m = Fixtures.read("up.dae", doc("utf-8", "<asset><up_axis>" + axis.name() + "</up_axis></asset>", "G"));
        assertEquals(axis, m.asset().upAxis());
        assertTrue(m.asset().present());
        // Recorded, not applied: positions stay in the document's frame whatever the axis.
        assertArrayEquals(new float[] {0, 0, 0, 100, 0, 0, 0, 250.5f, -3}, m.meshes().get(0).positions());
        assertEquals(List.of(), m.warnings());
    }

    @Test
    void upAxisMayBeSurroundedByWhitespace() {
        Model m = Fixtures.read("up-ws.dae", doc("utf-8", "<asset><up_axis>\n\t  Z_UP \r\n</up_axis></asset>", "G"));
        assertEquals(UpAxis.Z_UP, m.asset().upAxis());
        assertEquals(List.of(), m.warnings());
    }

    @Test
    void unitIsRecordedAndPositionsAreNotConverted() {
        Model m = Fixtures.read("cm.dae", doc("utf-8", """
                <asset>
                  <contributor><authoring_tool>Hand, 2024</authoring_tool></contributor>
                  <unit meter="0.01" name="centimeter"/>
                  <up_axis>Z_UP</up_axis>
                </asset>""", "G"));
        AssetInfo a = m.asset();
        assertEquals(new AssetInfo(UpAxis.Z_UP, 0.01, "centimeter", "Hand, 2024", true), a);
        // 100 document units are 1 m, but the model keeps the document's numbers.
        assertArrayEquals(new float[] {0, 0, 0, 100, 0, 0, 0, 250.5f, -3}, m.meshes().get(0).positions());
    }

    @Test
    void assetWithoutUnitOrUpAxisUsesTheColladaDefaults() {
        Model m = Fixtures.read("bare-asset.dae", doc("utf-8", "<asset><created>2024-01-01T00:00:00</created></asset>", "G"));
        assertEquals(new AssetInfo(UpAxis.Y_UP, 1.0, "meter", null, true), m.asset());
        assertEquals(List.of(), m.warnings());
    }

    @Test
    void missingAssetIsToleratedWithAWarningAndDefaults() {
        Model m = Fixtures.read("no-asset.dae", doc("utf-8", "", "G"));
        assertEquals(new AssetInfo(UpAxis.Y_UP, 1.0, "meter", null, false), m.asset());
        assertFalse(m.asset().present());
        assertEquals(1, m.warnings().size(), m.warnings()::toString);
        String w = m.warnings().get(0).toString();
        assertTrue(w.startsWith("<COLLADA>") && w.contains("no <asset>"), w);
        assertEquals(1, m.meshes().get(0).triangleCount(), "the rest of the file is read as usual");
    }

    @Test
    void unknownUpAxisFallsBackToYUpWithAWarning() {
        Model m = Fixtures.read("w-up.dae", doc("utf-8", "<asset><up_axis>W_UP</up_axis></asset>", "G"));
        assertEquals(UpAxis.Y_UP, m.asset().upAxis());
        assertEquals(1, m.warnings().size(), m.warnings()::toString);
        assertTrue(m.warnings().get(0).toString().contains("unknown up axis \"W_UP\""), m.warnings()::toString);
    }

    // ---- encodings

    @Test
    void utf8WithoutBomKeepsNonAsciiNames() throws Exception {
        assertDecoded(readBytes("utf8.dae", doc("UTF-8", PLAIN_ASSET, WIDE).getBytes(StandardCharsets.UTF_8)), WIDE);
    }

    @Test
    void utf8WithBomKeepsNonAsciiNames() throws Exception {
        byte[] bom = {(byte) 0xEF, (byte) 0xBB, (byte) 0xBF};
        byte[] bytes = concat(bom, doc("UTF-8", PLAIN_ASSET, WIDE).getBytes(StandardCharsets.UTF_8));
        assertDecoded(readBytes("utf8-bom.dae", bytes), WIDE);
    }

    @Test
    void utf16LittleEndianWithBomKeepsNonAsciiNames() throws Exception {
        byte[] bom = {(byte) 0xFF, (byte) 0xFE};
        byte[] bytes = concat(bom, doc("UTF-16", PLAIN_ASSET, WIDE).getBytes(StandardCharsets.UTF_16LE));
        assertEquals(0x3C, bytes[2]); // '<' in little-endian order: 3C 00
        assertEquals(0x00, bytes[3]);
        assertDecoded(readBytes("utf16le.dae", bytes), WIDE);
    }

    @Test
    void utf16BigEndianWithBomKeepsNonAsciiNames() throws Exception {
        byte[] bom = {(byte) 0xFE, (byte) 0xFF};
        byte[] bytes = concat(bom, doc("UTF-16", PLAIN_ASSET, WIDE).getBytes(StandardCharsets.UTF_16BE));
        assertEquals(0x00, bytes[2]); // '<' in big-endian order: 00 3C
        assertEquals(0x3C, bytes[3]);
        assertDecoded(readBytes("utf16be.dae", bytes), WIDE);
    }

    @Test
    void declaredLatin1KeepsUmlauts() throws Exception {
        Charset latin1 = StandardCharsets.ISO_8859_1;
        byte[] bytes = doc("ISO-8859-1", PLAIN_ASSET, GERMAN).getBytes(latin1);
        assertEquals(GERMAN.length(), new String(GERMAN.getBytes(latin1), latin1).length()); // one byte per umlaut
        assertDecoded(readBytes("latin1.dae", bytes), GERMAN);
    }

    @Test
    void characterReferencesAndPredefinedEntitiesInNamesAreDecoded() throws Exception {
        // A pure-ASCII file spelling "Würfel & Kegel <2>" with references.
        byte[] bytes = doc("US-ASCII", PLAIN_ASSET, "W&#xFC;rfel &amp; Kegel &lt;2&gt; &#x1F9CA;").getBytes(StandardCharsets.US_ASCII);
        assertDecoded(readBytes("refs.dae", bytes), "Würfel & Kegel <2> \uD83E\uDDCA");
    }

    @Test
    void nonAsciiIdsResolve() {
        // A geometry whose id has umlauts, instantiated from the scene by that id.
        String xml = doc("utf-8", PLAIN_ASSET, GERMAN).replace("id=\"g\"", "id=\"würfel-ü\"").replace("</library_geometries>", """
                </library_geometries>
                  <library_visual_scenes>
                    <visual_scene id="szene">
                      <node id="knoten-ö" name="Knöten"><instance_geometry url="#würfel-ü"/></node>
                    </visual_scene>
                  </library_visual_scenes>
                  <scene><instance_visual_scene url="#szene"/></scene>""");
        Model m = Fixtures.read("ids.dae", xml);
        assertEquals("würfel-ü", m.meshes().get(0).id());
        assertTrue(m.mesh("würfel-ü").isPresent());
        assertEquals(1, m.instances().size());
        assertSame(m.meshes().get(0), m.instances().get(0).mesh());
        assertEquals("Knöten", m.nodeById("knoten-ö").orElseThrow().name());
    }
}
