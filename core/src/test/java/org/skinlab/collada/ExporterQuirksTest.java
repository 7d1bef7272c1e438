package org.skinlab.collada;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.skinlab.collada.QuadFixture.with;
import static org.skinlab.collada.Snippets.oneWarning;

import java.io.ByteArrayInputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;

import org.joml.Matrix4f;
import org.junit.jupiter.api.Test;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.model.AnimationChannel;
import org.skinlab.model.ImportWarning;
import org.skinlab.model.KeyframeTrack;
import org.skinlab.model.Mesh;
import org.skinlab.model.Model;
import org.skinlab.model.Skin;
import org.skinlab.model.TransformElement;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinnedModel;
import org.skinlab.skinning.SkinningMethod;

/**
 * What real exporters write that the specification does not quite allow, and the importer reads
 * with a warning instead of refusing (docs/importer.md, "Lenient or refused"): each case is a small
 * hand-made fixture in {@code fixtures/quirks/} (or {@code skinned-quad.dae} with one change),
 * checked value by value, with exactly the warning it deserves.
 */
class ExporterQuirksTest {
    private static final float EXACT = 0f;

    // ------------------------------------------------------------------ unnamed accessor params

    @Test
    void accessorsWithoutNamedParamsAreReadAsData() {
        Model m = Fixtures.resource("quirks/fbx-unnamed-params.dae");
        Skin skin = m.skins().get(0);
        assertEquals(List.of("Root", "Tip"), skin.jointNames());
        Matrix4f tipInverseBind = skin.inverseBindMatrix(1, new Matrix4f());
        assertEquals(-1f, tipInverseBind.m30(), EXACT, "translation of Tip's inverse bind matrix (row-major value 3)");
        // Position 1: Root 0.5, Tip 0.5 (weights 1 and 0.5 are values 0 and 1 of the weight array).
        assertEquals(2, skin.influenceCount(1));
        assertEquals(0.5f, skin.influenceWeight(skin.influenceStart(1)), EXACT);
        assertEquals(1f, skin.influenceWeight(skin.influenceStart(0)), EXACT);

        AnimationChannel channel = m.clips().get(0).channels().get(0);
        KeyframeTrack track = channel.track();
        assertArrayEquals(new float[] {0f, 1f}, track.times(), EXACT);
        assertEquals(16, track.width());
        assertEquals(-1f, track.value(1, 1), EXACT, "row 0, column 1 of the second key: -sin 90");

        ImportWarning w = oneWarning(m, "no <param> of this accessor has a name");
        assertTrue(w.message().contains("read as data"), w::toString);
        assertEquals(1, m.warnings().size(), () -> m.warnings().toString());
    }

    @Test
    void jointNamesWithSpacesAreSplitByTheScenesNodeNames() {
        Model m = Fixtures.resource("quirks/fbx-spaced-joint-names.dae");
        Skin skin = m.skins().get(0);
        assertEquals(List.of("Bip01 Spine", "Bip01 Spine1", "Bip01 Pelvis"), skin.jointNames());
        org.skinlab.model.MeshInstance instance = m.instances().get(0);
        for (int j = 0; j < 3; j++) {
            assertEquals(skin.jointNames().get(j), m.node(instance.jointNode(j)).id());
        }
        oneWarning(m, "count=\"3\" but 6 words: the names have spaces in them");
        oneWarning(m, "no <param> of this accessor has a name");
        assertEquals(2, m.warnings().size(), () -> m.warnings().toString());
    }

    @Test
    void wordsThatSplitIntoNoSceneNamesStayACountMismatch() {
        // "Bip01 Spine Bip01 Spine1 Bip01 Pelvis" with count 4: no split into 4 node names exists.
        String text = Fixtures.text("quirks/fbx-spaced-joint-names.dae").replace(
                "<Name_array id=\"bar-skin-joints-array\" count=\"3\">", "<Name_array id=\"bar-skin-joints-array\" count=\"4\">");
        ColladaException e = Fixtures.error("unsplittable.dae", text);
        assertTrue(e.getMessage().contains("matches no node"), e::getMessage);
    }

    @Test
    void anUnnamedParamBesideNamedOnesStillSkipsItsSlot() {
        // The specification's rule where it makes sense: X, (unnamed), Z picks values 0 and 2.
        Model m = Fixtures.read("skip.dae", with("<float_array id=\"quad-nrm-array\" count=\"3\">0 0 1</float_array>",
                "<float_array id=\"quad-nrm-array\" count=\"4\">0 0 1 7</float_array>")
                .replace("<accessor source=\"#quad-nrm-array\" count=\"1\" stride=\"3\">\n"
                        + "              <param name=\"X\" type=\"float\"/>\n"
                        + "              <param name=\"Y\" type=\"float\"/>",
                        "<accessor source=\"#quad-nrm-array\" count=\"1\" stride=\"4\">\n"
                        + "              <param name=\"X\" type=\"float\"/>\n"
                        + "              <param type=\"float\"/><param name=\"Y\" type=\"float\"/>"));
        float[] normals = m.meshes().get(0).normals();
        assertArrayEquals(new float[] {0f, 1f, 7f}, new float[] {normals[0], normals[1], normals[2]}, EXACT);
        Snippets.assertNoWarnings(m);
    }

    // ------------------------------------------------------------------------- decimal commas

    @Test
    void decimalCommasAreReadAsDecimalPoints() {
        Model m = Fixtures.resource("quirks/decimal-comma.dae");
        assertEquals(0.01, m.asset().unitMeter(), 0.0);
        Mesh tri = m.meshes().get(0);
        assertArrayEquals(new float[] {0, 0, 0, 1.5f, 0, 0, 0, 2.25f, -0.125f}, tri.positions(), EXACT);
        List<TransformElement> transforms = m.nodes().get(0).transforms();
        assertArrayEquals(new float[] {0.5f, 0, 0}, transforms.get(0).values(), EXACT);
        assertArrayEquals(new float[] {0, 0, 1, 22.5f}, transforms.get(1).values(), EXACT);
        KeyframeTrack track = m.clips().get(0).channels().get(0).track();
        assertArrayEquals(new float[] {0f, 0.5f, 1.25f}, track.times(), EXACT);
        assertEquals(45.5f, track.value(1, 0), EXACT);
        oneWarning(m, "decimal comma");
        assertEquals(1, m.warnings().size(), () -> m.warnings().toString());
    }

    @Test
    void aCommaThatSeparatesNumbersIsStillRefused() {
        // "0,0,0" is a comma-separated list, not a decimal: refused, not misread as 0.0.
        ColladaException e = Fixtures.error("list.dae", with("0 0 0  1 0 0", "0,0,0  1 0 0"));
        assertTrue(e.getMessage().contains("value 0 \"0,0,0\" is not a number"), e::getMessage);
    }

    // ------------------------------------------------------------------ counts and accessor slips

    @Test
    void anArrayCountThatDisagreesWithItsValuesIsWarnedAndTheValuesAreRead() {
        for (String count : new String[] {"11", "13"}) {
            Model m = Fixtures.read("float-count.dae", with("count=\"12\">0 0 0", "count=\"" + count + "\">0 0 0"));
            assertEquals(4, m.meshes().get(0).positionCount());
            oneWarning(m, "count=\"" + count + "\" but 12 values; the values present are read");
            assertEquals(1, m.warnings().size(), () -> m.warnings().toString());
        }
    }

    @Test
    void anAccessorCountBeyondItsArrayReadsTheWholeElementsPresent() {
        // 5 positions declared, 4 written: the 4 are read; nothing indexes a fifth.
        Model m = Fixtures.read("accessor-count.dae", with("<accessor source=\"#quad-pos-array\" count=\"4\"",
                "<accessor source=\"#quad-pos-array\" count=\"5\""));
        assertEquals(4, m.meshes().get(0).positionCount());
        oneWarning(m, "count=\"5\" stride=\"3\" offset=\"0\" needs 15 values but the array has 12; the 4 whole"
                + " elements present are read");
    }

    @Test
    void primitiveCountsThatDisagreeWithTheirIndicesAreWarnedAndTheIndicesRead() {
        Model triangles = Fixtures.read("triangles-count.dae", with("<triangles count=\"1\">", "<triangles count=\"2\">"));
        assertEquals(2, triangles.meshes().get(0).triangleCount());
        oneWarning(triangles, "count=\"2\" but <p> holds 1 triangles; they are read");

        Model polylist = Fixtures.read("polylist-count.dae", with("<polylist count=\"1\">", "<polylist count=\"2\">"));
        assertEquals(2, polylist.meshes().get(0).triangleCount());
        oneWarning(polylist, "count=\"2\" but <vcount> and <p> hold 1 polygons; they are read");
    }

    @Test
    void trianglesWhoseIndicesFitNoWholeTriangleAreStillRefused() {
        ColladaException e = Fixtures.error("p-short.dae", with("<p>0 0 1 0 2 0</p>", "<p>0 0 1 0 2</p>"));
        assertTrue(e.getMessage().contains("count=\"1\" triangles with 2 index offsets need 6 indices, <p> has 5"),
                e::getMessage);
    }

    @Test
    void anAccessorNamingNothingReadsItsSourcesOwnArray() {
        Model m = Fixtures.read("accessor.dae", with("<accessor source=\"#quad-nrm-array\"", "<accessor source=\"#nope\""));
        assertArrayEquals(new float[] {0, 0, 1}, java.util.Arrays.copyOf(m.meshes().get(0).normals(), 3), EXACT);
        oneWarning(m, "source=\"#nope\" refers to nothing in the file; its <source>'s own <float_array"
                + " id=\"quad-nrm-array\"> is read");
    }

    @Test
    void aVertexInputNamingAnythingButTheMeshsVerticesReadsThem() {
        for (String ref : new String[] {"#nope", "#quad-pos"}) {
            Model m = Fixtures.read("vertex-ref.dae", with("<triangles count=\"1\">\n"
                    + "          <input semantic=\"VERTEX\" source=\"#quad-vtx\"",
                    "<triangles count=\"1\">\n          <input semantic=\"VERTEX\" source=\"" + ref + "\""));
            assertEquals(2, m.meshes().get(0).triangleCount());
            oneWarning(m, "source=\"" + ref + "\" is not this mesh's <vertices> \"#quad-vtx\", the only one a VERTEX"
                    + " input can name; read as that");
        }
    }

    // --------------------------------------------------------- broken optional data: UVs, colours

    @Test
    void brokenOptionalInputsAreDroppedOrZeroedAndTheGeometryKept() {
        Model m = Fixtures.resource("quirks/uv-trouble.dae");
        Mesh quad = m.meshes().get(0);
        assertEquals(4, quad.positionCount());
        assertEquals(2, quad.triangleCount());
        assertFalse(quad.hasNormals(), "the <vertices> NORMAL source is shorter than the positions: dropped");
        float[] uv = quad.texCoords(0);
        float[] colors = quad.colors();
        for (float f : uv) {
            assertTrue(Float.isFinite(f));
        }
        // Triangle 0 (first primitive): corners 0 1 2 with UVs (0,0) (1,0) (1,NaN -> 0).
        assertUv(quad, uv, 0, 0, 0f, 0f);
        assertUv(quad, uv, 0, 1, 1f, 0f);
        assertUv(quad, uv, 0, 2, 1f, 0f);
        // Triangle 1 (second primitive): its TEXCOORD input was dropped, so all zero.
        for (int c = 0; c < 3; c++) {
            assertUv(quad, uv, 1, c, 0f, 0f);
        }
        int v = quad.triangleVertex(0, 0);
        assertArrayEquals(new float[] {1f, 0f, 0f, 1f}, java.util.Arrays.copyOfRange(colors, 4 * v, 4 * v + 4), EXACT,
                "the colour's -INF is read as 0");

        oneWarning(m, "1 NaN or infinite values (first: value 5 \"NaN\") in TEXCOORD source \"quad-uv\"; read as 0");
        oneWarning(m, "1 NaN or infinite values (first: value 1 \"-INF\") in COLOR source \"quad-col\"; read as 0");
        oneWarning(m, "index 4 is out of range: source \"quad-uv\" has 4 elements; that input is dropped for this"
                + " primitive");
        oneWarning(m, "index 3 is out of range: source \"quad-nrm\" has 2 elements; that input is dropped");
        oneWarning(m, "has no TEXCOORD set 0 while other primitives do; its texture coordinates there are zero");
        assertEquals(5, m.warnings().size(), () -> m.warnings().toString());
    }

    private static void assertUv(Mesh mesh, float[] uv, int triangle, int corner, float s, float t) {
        int v = mesh.triangleVertex(triangle, corner);
        assertEquals(s, uv[2 * v], EXACT, "s of triangle " + triangle + " corner " + corner);
        assertEquals(t, uv[2 * v + 1], EXACT, "t of triangle " + triangle + " corner " + corner);
    }

    @Test
    void aNormalIndexOutOfRangeDropsTheNormalsOfThatPrimitive() {
        Model m = Fixtures.read("p-normal.dae", with("<p>0 0 1 0 2 0</p>", "<p>0 0 1 1 2 0</p>"));
        Mesh quad = m.meshes().get(0);
        assertEquals(2, quad.triangleCount());
        int v = quad.triangleVertex(0, 0);
        assertArrayEquals(new float[] {0, 0, 0}, java.util.Arrays.copyOfRange(quad.normals(), 3 * v, 3 * v + 3), EXACT);
        oneWarning(m, "index 1 is out of range: source \"quad-nrm\" has 1 elements; that input is dropped for this"
                + " primitive");
        oneWarning(m, "has no NORMAL input while other primitives do; its normals are zero");
    }

    @Test
    void nonFinitePositionsAreStillRefused() {
        ColladaException e = Fixtures.error("nan.dae", with("0 0 0  1 0 0  1 1 0", "0 0 0  1 NaN 0  1 1 0"));
        assertTrue(e.getMessage().contains("<float_array id=\"quad-pos-array\">"), e::getMessage);
        assertTrue(e.getMessage().contains("value 4 \"NaN\" is not a finite number (POSITION data must be finite)"),
                e::getMessage);
    }

    @Test
    void anEmptyMeshWithStrideZeroIsEmptyNotRefused() {
        // pycollada's test file: count="0" stride="0" (nothing to lay out) and an empty <p>.
        Model m = Fixtures.read("empty.dae", Snippets.collada("""
                <library_geometries><geometry id="g"><mesh>
                  <source id="g-vtx"><float_array id="g-vtx-array" count="0"></float_array>
                    <technique_common><accessor source="#g-vtx-array" count="0" stride="0">
                      <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
                    </accessor></technique_common></source>
                  <vertices id="g-vertices"><input semantic="POSITION" source="#g-vtx"/></vertices>
                  <triangles count="0"><input semantic="VERTEX" source="#g-vertices" offset="0"/>
                    <input semantic="NORMAL" source="#g-vtx" offset="1"/><p>  </p></triangles>
                </mesh></geometry></library_geometries>
                <library_visual_scenes><visual_scene id="s"><node><instance_geometry url="#g"/></node>
                </visual_scene></library_visual_scenes><scene><instance_visual_scene url="#s"/></scene>"""));
        assertEquals(0, m.meshes().get(0).positionCount());
        assertEquals(0, m.meshes().get(0).triangleCount());
        assertEquals(1, m.instances().size());
        Snippets.assertNoWarnings(m);
        // With elements to read, stride 0 means nothing: refused.
        ColladaException e = Fixtures.error("stride.dae", with("count=\"4\" stride=\"3\"", "count=\"4\" stride=\"0\""));
        assertTrue(e.getMessage().contains("stride=\"0\""), e::getMessage);
    }

    // ------------------------------------------------------------------------------ 2-D positions

    @Test
    void twoDimensionalPositionsGetZeroZ() {
        Model m = Fixtures.resource("quirks/2d-positions.dae");
        assertArrayEquals(new float[] {0, 0, 0, 2, 0, 0, 2, 2, 0, 0, 2, 0}, m.meshes().get(0).positions(), EXACT);
        assertEquals(2, m.meshes().get(0).triangleCount());
        oneWarning(m, "has 2 components per element; read as X Y with Z = 0");
        assertEquals(1, m.warnings().size(), () -> m.warnings().toString());
    }

    // ------------------------------------------------------------------------ self-naming URLs

    @Test
    void urlsThatNameTheDocumentByItsFileNameResolveInsideIt() {
        // Fixtures.resource passes "quirks/self-url.dae" as the name, which is also the location.
        Model m = Fixtures.resource("quirks/self-url.dae");
        assertEquals(2, m.instances().size());
        assertEquals(3, m.meshes().get(0).positionCount());
        oneWarning(m, "names this document by its file name");
        assertEquals(1, m.warnings().size(), () -> m.warnings().toString());
    }

    @Test
    void aUrlNamingAnotherDocumentIsRefusedAndSoIsOneWhoseFolderIsUnknown() throws Exception {
        String text = new String(Fixtures.class.getResourceAsStream("/fixtures/quirks/self-url.dae").readAllBytes(),
                StandardCharsets.UTF_8);
        String other = text.replace("<instance_geometry url=\"./self-url.dae#tri\"/>",
                "<instance_geometry url=\"other.dae#tri\"/>");
        ColladaException e = Fixtures.error("quirks/self-url.dae", other);
        assertTrue(e.getMessage().contains("url=\"other.dae#tri\" points into another document"), e::getMessage);

        // Read under another location, "../quirks/self-url.dae" names another file.
        ColladaException moved = org.junit.jupiter.api.Assertions.assertThrows(ColladaException.class,
                () -> ColladaImporter.read(new ByteArrayInputStream(text.getBytes(StandardCharsets.UTF_8)), "x.dae",
                        Path.of("elsewhere", "self-url.dae")));
        assertTrue(moved.getMessage().contains("url=\"../quirks/self-url.dae#scene\" points into another document"),
                moved::getMessage);
    }

    // ------------------------------------------------------------------------- negative weights

    @Test
    void negativeWeightsAreReadAsZeroAndAPositionLeftWithoutWeightKeepsTheBindShape() {
        Model m = Fixtures.resource("quirks/negative-weights.dae");
        Skin skin = m.skins().get(0);
        // Weights 1 | 0.5 0.5 | -0.25 1.25 | -1, the negative ones read as 0.
        float[] weights = new float[skin.influenceTotal()];
        for (int i = 0; i < weights.length; i++) {
            weights[i] = skin.influenceWeight(i);
        }
        assertArrayEquals(new float[] {1f, 0.5f, 0.5f, 0f, 1.25f, 0f}, weights, EXACT);
        assertEquals(2, skin.influenceCount(2), "the influence stays, with weight 0");

        ImportWarning w = oneWarning(m, "negative weights");
        assertTrue(w.element().startsWith("<vertex_weights> in <controller id=\"quad-skin\">"), w::toString);
        assertEquals("2 negative weights (most negative -1.0) on 2 of 4 positions read as 0; the other weights of"
                + " those positions are divided by their sum, and 1 position is left without weight, keeping the"
                + " bind shape", w.message());
        assertEquals(1, m.warnings().size(), () -> m.warnings().toString());

        // At the end of the clip Tip has turned 90 degrees about Z at (1 0 0): position 2, carried
        // by Tip alone, goes to the origin; position 3 stays where the bind shape puts it.
        SkinnedModel model = SkinnedModel.of(m);
        model.pose(1f, RotationInterpolation.SLERP);
        SkinnedGeometry g = model.geometries().get(0);
        for (SkinningMethod method : SkinningMethod.values()) {
            float[] points = new float[3 * g.pointCount()];
            model.skin(0, method, points, new float[3 * g.pointCount()]);
            float[] positions = g.positionsInSourceOrder(points, new float[12]);
            if (method == SkinningMethod.COR || method == SkinningMethod.SPLINE) {
                // CoR turns a blended point about its centre of rotation, not about the joint, and
                // the spline carries it on the curve that cuts the joint's corner: only the points
                // with one influence (or none) are fixed by the pose alone.
                positions = java.util.Arrays.copyOfRange(positions, 6, 12);
                assertArrayEquals(new float[] {0, 0, 0, 0, 1, 0}, positions, 1e-6f, method.toString());
                continue;
            }
            assertArrayEquals(new float[] {0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 1, 0}, positions, 1e-6f, method.toString());
        }
    }
}
