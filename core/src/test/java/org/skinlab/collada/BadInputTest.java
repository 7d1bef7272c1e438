package org.skinlab.collada;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.skinlab.collada.QuadFixture.with;

import java.lang.management.ManagementFactory;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.Random;

import org.junit.jupiter.api.Test;
import org.skinlab.model.AnimationClip;
import org.skinlab.model.Mesh;
import org.skinlab.model.Model;
import org.skinlab.model.Skin;

/**
 * Broken files are refused with one {@link ColladaException} whose message names the file, the
 * element (with its id, or the nearest ancestor's) and the problem; never another exception, an
 * {@code Error}, a hang or a huge allocation. Each case is {@code skinned-quad.dae} with one
 * change (see {@link QuadFixture#with}); {@link #theUnbrokenFixtureImportsCleanly()} proves that
 * the change alone is what each case refuses.
 */
class BadInputTest {
    /** Every refusal must be quick; the slowest real case (the instancing bomb) is far below. */
    private static final Duration FAST = Duration.ofSeconds(5);

    /**
     * Imports and asserts the refusal: the exception names {@code file}, its element part contains
     * {@code element} and its problem part contains {@code problem}; the message is one line.
     */
    private static ColladaException refused(String file, byte[] bytes, String element, String problem) {
        ColladaException e = assertTimeoutPreemptively(FAST, () -> Fixtures.error(file, bytes));
        String m = e.getMessage();
        assertEquals(file, e.file(), m);
        assertTrue(m.startsWith(file + ": "), m);
        assertTrue(e.element().contains(element), () -> "element \"" + element + "\" not named in: " + m);
        assertTrue(e.problem().contains(problem), () -> "problem \"" + problem + "\" not stated in: " + m);
        assertFalse(m.contains("\n"), () -> "not one line: " + m);
        return e;
    }

    private static ColladaException refused(String file, String xml, String element, String problem) {
        return refused(file, xml.getBytes(StandardCharsets.UTF_8), element, problem);
    }

    // ------------------------------------------------------------------------------ the control

    @Test
    void theUnbrokenFixtureImportsCleanly() {
        // Counted by hand from skinned-quad.dae: 4 positions; one triangle in <triangles> and one
        // in <polylist>; joints Root and Tip; positions 1 and 2 have two influences.
        Model m = Fixtures.resource(QuadFixture.NAME);
        assertEquals(1, m.meshes().size());
        Mesh quad = m.meshes().get(0);
        assertEquals(4, quad.positionCount());
        assertEquals(2, quad.triangleCount());
        Skin skin = m.skins().get(0);
        assertEquals(2, skin.jointCount());
        assertEquals(2, skin.maxInfluences());
        assertEquals(6, skin.influenceTotal());
        // Armature, Root, Tip, the marker copy under Tip, quad-node, static-quad.
        assertEquals(6, m.nodes().size());
        assertEquals(2, m.instances().size());
        assertEquals(1, m.clips().size());
        AnimationClip wave = m.clips().get(0);
        assertEquals("wave", wave.name());
        assertEquals(1.0f, wave.duration(), 0f);
        assertEquals(1, wave.channels().size());
        assertEquals(0, m.warnings().size(), () -> m.warnings().toString());
    }

    // ---------------------------------------------------------------------------- malformed XML

    @Test
    void anythingAfterTheRootElementIsIgnored() {
        // Parsing stops when </COLLADA> closes the document (the JDK parser would otherwise pay
        // for an exception at the end of every input): trailing comments, junk or even a second
        // root change nothing.
        String xml = QuadFixture.text().trim() + "\n<!-- c --> junk <COLLADA><unclosed>";
        Model m = Fixtures.read("trailing.dae", xml);
        assertEquals(2, m.meshes().get(0).triangleCount());
        assertEquals(0, m.warnings().size(), () -> m.warnings().toString());
    }

    @Test
    void unclosedTagNamesTheElementLeftOpen() {
        // </asset> removed: the parser stops at </COLLADA> while <asset> is still open.
        ColladaException e = refused("unclosed.dae", with("</asset>", ""), "inside <asset> at line",
                "must be terminated by the matching end-tag");
        assertTrue(e.element().startsWith("XML at line "), e.getMessage());
    }

    @Test
    void textBeforeTheRootElementIsMalformed() {
        refused("prolog.dae", "junk " + QuadFixture.text().substring(QuadFixture.text().indexOf("<COLLADA")),
                "XML at line 1, column 1", "Content is not allowed in prolog");
    }

    @Test
    void emptyFileIsMalformed() {
        refused("empty.dae", new byte[0], "XML at line 1", "Premature end of file");
    }

    @Test
    void randomBinaryIsMalformed() {
        byte[] bytes = new byte[4096];
        new Random(20190501L).nextBytes(bytes);
        // Random bytes are not UTF-8; which byte the parser trips over first is its business.
        refused("noise.dae", bytes, "XML at line 1", "malformed XML");
    }

    @Test
    void unsupportedEncodingIsAFileProblemNotAnIoError() {
        // UnsupportedEncodingException is an IOException; the importer must not let it pass as one.
        refused("utf7.dae", "<?xml version=\"1.0\" encoding=\"UTF-7\"?><COLLADA/>", "XML declaration",
                "encoding \"UTF-7\" is not supported");
    }

    @Test
    void aParserMessageQuotingALineBreakStaysOneLine() {
        // Found by ColladaImporterFuzzTest: the parser quotes the bad version, line break and all.
        ColladaException e = refused("version.dae", "<?xml version=\"1.\n0\"?><COLLADA/>", "XML at line 2",
                "XML version \"1.\\n0\" is not supported");
        assertEquals(-1, e.problem().indexOf('\n'), e.problem());
    }

    @Test
    void wrongRootElementIsRefused() {
        refused("html.dae", "<html><body>not a model</body></html>", "<html> at line 1",
                "the root element is <html>, not <COLLADA>");
    }

    // ------------------------------------------------------------- missing and dangling references

    @Test
    void inputSourceThatNamesNothingIsRefused() {
        refused("input.dae", with("<input semantic=\"POSITION\" source=\"#quad-pos\"/>",
                "<input semantic=\"POSITION\" source=\"#nope\"/>"), "<input> in <vertices id=\"quad-vtx\">",
                "source=\"#nope\" refers to nothing in the file");
    }

    @Test
    void instanceGeometryUrlThatNamesNothingIsRefused() {
        refused("geometry-url.dae", with("<instance_geometry url=\"#quad\"/>", "<instance_geometry url=\"#nope\"/>"),
                "<instance_geometry> in <node id=\"static-quad\">", "url=\"#nope\" refers to nothing in the file");
    }

    @Test
    void instanceGeometryUrlToAControllerIsRefused() {
        refused("geometry-type.dae", with("<instance_geometry url=\"#quad\"/>",
                "<instance_geometry url=\"#quad-skin\"/>"), "<instance_geometry> in <node id=\"static-quad\">",
                "url=\"#quad-skin\" refers to a <controller>, expected <geometry>");
    }

    @Test
    void instanceAnimationUrlThatNamesNothingIsRefused() {
        refused("clip-url.dae", with("<instance_animation url=\"#tip-anim\"/>", "<instance_animation url=\"#nope\"/>"),
                "<instance_animation> in <animation_clip id=\"wave\">", "url=\"#nope\" refers to nothing in the file");
    }

    @Test
    void accessorSourceThatNamesNothingIsRefusedWhenItsSourceHoldsNoArray() {
        // The normals' own array moved out of their <source>: nothing to fall back to.
        String xml = with("<float_array id=\"quad-nrm-array\" count=\"3\">0 0 1</float_array>", "")
                .replace("<accessor source=\"#quad-nrm-array\"", "<accessor source=\"#nope\"");
        refused("accessor.dae", xml, "<accessor> in <source id=\"quad-nrm\">",
                "source=\"#nope\" refers to nothing in the file");
    }

    @Test
    void accessorMayReadAnotherSourcesArray() {
        // COLLADA lets an accessor read any array: here the normals' accessor reads the
        // positions' array, so the normals are the first position values.
        Model m = Fixtures.read("accessor-other.dae",
                with("<accessor source=\"#quad-nrm-array\"", "<accessor source=\"#quad-pos-array\""));
        Mesh quad = m.meshes().get(0);
        float[] positions = quad.positions();
        float[] normals = quad.normals();
        for (int c = 0; c < 3; c++) {
            assertEquals(positions[c], normals[c], 0f);
        }
        assertEquals(0, m.warnings().size(), () -> m.warnings().toString());
    }

    @Test
    void accessorReadingSomethingThatIsNoArrayIsRefused() {
        refused("accessor-node.dae", with("<accessor source=\"#quad-nrm-array\"", "<accessor source=\"#quad-node\""),
                "<accessor> in <source id=\"quad-nrm\">", "refers to a <node>");
    }

    @Test
    void skinSourceThatNamesNothingIsRefused() {
        refused("skin-source.dae", with("<skin source=\"#quad\">", "<skin source=\"#nope\">"),
                "<skin> in <controller id=\"quad-skin\">", "source=\"#nope\" refers to nothing in the file");
    }

    @Test
    void channelSourceThatNamesNothingIsRefused() {
        refused("channel.dae", with("<channel source=\"#tip-anim-sampler\"", "<channel source=\"#nope\""),
                "<channel> in <animation id=\"tip-anim\">", "source=\"#nope\" refers to nothing in the file");
    }

    @Test
    void missingPositionInputIsRefused() {
        refused("no-position.dae", with("<input semantic=\"POSITION\" source=\"#quad-pos\"/>", ""),
                "<vertices id=\"quad-vtx\">", "has no POSITION input");
    }

    // ------------------------------------------------------------ counts that disagree with data

    @Test
    void accessorStrideBeyondItsArrayLeavesPositionsAnIndexReachesAndIsRefusedThere() {
        // 4 positions * stride 4 need 15 values of a 12-value array: the 3 whole positions present
        // are read (warned), and the corner that names position 3 is refused.
        refused("accessor-stride.dae", with("count=\"4\" stride=\"3\"", "count=\"4\" stride=\"4\""),
                "<p> in <geometry id=\"quad\">", "index 3 (value 4) is out of range: <vertices> has 3 positions");
    }

    @Test
    void vcountSumOtherThanTheIndicesIsRefused() {
        // A quad needs 4 corners * 2 offsets = 8 indices; <p> holds 6.
        refused("vcount-sum.dae", with("<vcount>3</vcount>", "<vcount>4</vcount>"), "<p> in <geometry id=\"quad\">",
                "<vcount> adds up to 4 corners, which with 2 index offsets need 8 indices, <p> has 6");
    }

    @Test
    void vertexWeightsCountOtherThanThePositionsIsRefused() {
        refused("weights-count.dae", with("<vertex_weights count=\"4\">", "<vertex_weights count=\"5\">"),
                "<vertex_weights> in <controller id=\"quad-skin\">", "count=\"5\" but geometry \"quad\" has 4 positions");
    }

    @Test
    void vertexWeightsVcountEntriesOtherThanCountIsRefused() {
        refused("weights-vcount.dae", with("<vcount>1 2 2 1</vcount>", "<vcount>1 2 2 1 0</vcount>"),
                "<vcount> in <controller id=\"quad-skin\">", "has 5 entries but count=\"4\"");
    }

    @Test
    void vertexWeightsVcountSumOtherThanTheIndicesIsRefused() {
        // 7 influences * 2 offsets = 14 indices; <v> holds 12.
        refused("weights-sum.dae", with("<vcount>1 2 2 1</vcount>", "<vcount>1 2 2 2</vcount>"),
                "<v> in <controller id=\"quad-skin\">", "<vcount> adds up to 7 influences, which with 2 index offsets"
                        + " need 14 indices, <v> has 12");
    }

    @Test
    void moreJointsThanInverseBindMatricesIsRefused() {
        String xml = with("<Name_array id=\"quad-joints-array\" count=\"2\">Root Tip</Name_array>",
                "<Name_array id=\"quad-joints-array\" count=\"3\">Root Tip Extra</Name_array>")
                .replace("<accessor source=\"#quad-joints-array\" count=\"2\"", "<accessor source=\"#quad-joints-array\" count=\"3\"");
        refused("ibm-count.dae", xml, "<input> in <controller id=\"quad-skin\">", "3 joints but 2 inverse bind matrices");
    }

    @Test
    void samplerOutputWithFewerKeysThanInputIsRefused() {
        String xml = with("count=\"2\">0 90</float_array>", "count=\"1\">0</float_array>")
                .replace("<accessor source=\"#tip-anim-angle-array\" count=\"2\"", "<accessor source=\"#tip-anim-angle-array\" count=\"1\"");
        refused("keys.dae", xml, "<input> in <sampler id=\"tip-anim-sampler\">",
                "OUTPUT source \"tip-anim-angle\" has 1 entries for 2 keys");
    }

    @Test
    void positionIndexOutOfRangeIsRefused() {
        // Third corner: position 4 of 0..3; it is value 4 of <p> (position, normal pairs).
        refused("p-position.dae", with("<p>0 0 1 0 2 0</p>", "<p>0 0 1 0 4 0</p>"), "<p> in <geometry id=\"quad\">",
                "index 4 (value 4) is out of range: <vertices> has 4 positions");
    }

    @Test
    void negativePositionIndexIsRefused() {
        refused("p-negative.dae", with("<p>0 0 1 0 2 0</p>", "<p>0 0 -1 0 2 0</p>"), "<p> in <geometry id=\"quad\">",
                "index -1 (value 2) is out of range");
    }

    @Test
    void jointIndexOutOfRangeIsRefused() {
        // Last influence (value 10 of <v>) names joint 2 of Root, Tip.
        refused("v-joint.dae", with("<v>0 0  0 1 1 2  0 1 1 2  1 0</v>", "<v>0 0  0 1 1 2  0 1 1 2  2 0</v>"),
                "<v> in <controller id=\"quad-skin\">", "joint index 2 (value 10) is out of range: the skin has 2 joints");
    }

    @Test
    void weightIndexOutOfRangeIsRefused() {
        // Last influence's weight (value 11 of <v>) is index 3 of a three-weight source.
        refused("v-weight.dae", with("<v>0 0  0 1 1 2  0 1 1 2  1 0</v>", "<v>0 0  0 1 1 2  0 1 1 2  1 3</v>"),
                "<v> in <controller id=\"quad-skin\">",
                "weight index 3 (value 11) is out of range: source \"quad-weights\" has 3 weights");
    }

    @Test
    void jointIndexPastTheVertexWeightsOwnJointSourceIsRefused() {
        // <vertex_weights> names its joints through a one-name source ("Tip"): joint index 1 is
        // valid for <joints> (Root, Tip) but not for that source. The first influence is value 0.
        String tipOnly = "<source id=\"tip-only\"><Name_array id=\"tip-only-array\" count=\"1\">Tip</Name_array>"
                + "<technique_common><accessor source=\"#tip-only-array\" count=\"1\" stride=\"1\">"
                + "<param name=\"JOINT\" type=\"name\"/></accessor></technique_common></source>\n        <joints>";
        String xml = with("<joints>", tipOnly).replace("<input semantic=\"JOINT\" source=\"#quad-joints\" offset=\"0\"/>",
                "<input semantic=\"JOINT\" source=\"#tip-only\" offset=\"0\"/>")
                .replace("<v>0 0  0 1 1 2  0 1 1 2  1 0</v>", "<v>1 0  0 1 0 2  0 1 0 2  0 0</v>");
        refused("remap.dae", xml, "<v> in <controller id=\"quad-skin\">",
                "joint index 1 (value 0) is out of range: JOINT source \"tip-only\" has 1 names");
    }

    @Test
    void vertexWeightsJointSourceIsMappedByName() {
        // The control for the case above: the same one-name source with index 0 everywhere means
        // every influence is joint "Tip", which is joint 1 of the skin.
        String tipOnly = "<source id=\"tip-only\"><Name_array id=\"tip-only-array\" count=\"1\">Tip</Name_array>"
                + "<technique_common><accessor source=\"#tip-only-array\" count=\"1\" stride=\"1\">"
                + "<param name=\"JOINT\" type=\"name\"/></accessor></technique_common></source>\n        <joints>";
        String xml = with("<joints>", tipOnly).replace("<input semantic=\"JOINT\" source=\"#quad-joints\" offset=\"0\"/>",
                "<input semantic=\"JOINT\" source=\"#tip-only\" offset=\"0\"/>")
                .replace("<v>0 0  0 1 1 2  0 1 1 2  1 0</v>", "<v>0 0  0 1 0 2  0 1 0 2  0 0</v>");
        Skin skin = Fixtures.read("remap-ok.dae", xml).skins().get(0);
        for (int i = 0; i < skin.influenceTotal(); i++) {
            assertEquals(1, skin.influenceJoint(i));
        }
    }

    @Test
    void clipTimeBeyondFloatRangeIsRefused() {
        // 1e39 is a finite double but an infinite float: the clip's duration would be NaN.
        refused("clip-start.dae", with("start=\"0\" end=\"1\"", "start=\"1e39\""),
                "<animation_clip id=\"wave\">", "start=\"1e39\" is out of float range");
        refused("clip-end.dae", with("start=\"0\" end=\"1\"", "start=\"0\" end=\"1e39\""),
                "<animation_clip id=\"wave\">", "end=\"1e39\" is out of float range");
    }

    // ------------------------------------------------------------------------- non-finite numbers

    private static void nonFinite(String token, String problem) {
        // The token replaces the y of position 1, value 4 of the array.
        refused("number.dae", with("0 0 0  1 0 0  1 1 0", "0 0 0  1 " + token + " 0  1 1 0"),
                "<float_array id=\"quad-pos-array\">", "value 4 \"" + token + "\" is " + problem);
    }

    @Test
    void nanIsRefused() {
        nonFinite("NaN", "not a finite number");
    }

    @Test
    void infinityIsRefused() {
        nonFinite("INF", "not a finite number");
        nonFinite("-INF", "not a finite number");
        nonFinite("Infinity", "not a finite number");
    }

    @Test
    void msvcNanSpellingIsRefused() {
        nonFinite("1.#QNAN", "not a finite number");
        nonFinite("-1.#IND", "not a finite number");
    }

    @Test
    void floatBeyondFloatRangeIsRefused() {
        nonFinite("1e39", "out of float range");
        nonFinite("-3.5e38", "out of float range");
    }

    @Test
    void nonFiniteUnitIsRefused() {
        refused("unit.dae", with("meter=\"1\"", "meter=\"NaN\""), "<unit>", "meter=\"NaN\" is not a finite number");
    }

    // -------------------------------------------------------------------------------- absurd sizes

    /** Bytes allocated by the current thread, or -1 where the JVM cannot tell. */
    private static long allocatedBytes() {
        java.lang.management.ThreadMXBean bean = ManagementFactory.getThreadMXBean();
        if (bean instanceof com.sun.management.ThreadMXBean) {
            return ((com.sun.management.ThreadMXBean) bean).getThreadAllocatedBytes(Thread.currentThread().getId());
        }
        return -1;
    }

    @Test
    void hugeDeclaredArrayCountIsNeverAllocated() {
        // 2,000,000,000 floats would be 8 GB; the text holds 12 values. The count only sizes a
        // first buffer (capped), so the whole import (XML included) allocates less than 16 MB and
        // reads the 12 values present, with a warning.
        String xml = with("count=\"12\">0 0 0", "count=\"2000000000\">0 0 0");
        assertTimeoutPreemptively(Duration.ofSeconds(2), () -> {
            long before = allocatedBytes();
            Model m = Fixtures.read("huge-count.dae", xml);
            long after = allocatedBytes();
            assertEquals(4, m.meshes().get(0).positionCount());
            assertTrue(m.warnings().stream().anyMatch(w -> w.message().startsWith(
                    "count=\"2000000000\" but 12 values")), () -> m.warnings().toString());
            if (before >= 0) {
                assertTrue(after - before < 16_000_000, "allocated " + (after - before) + " bytes");
            }
        });
    }

    @Test
    void declaredCountBeyondIntRangeIsRefused() {
        refused("count-range.dae", with("count=\"12\">0 0 0", "count=\"99999999999\">0 0 0"),
                "<float_array id=\"quad-pos-array\">", "count=\"99999999999\" is out of range");
    }

    @Test
    void hugeVcountEntryIsRefusedWithoutOverflow() {
        // 2^31-1 corners * 2 offsets = 4,294,967,294 indices: computed in long, compared with 6.
        refused("huge-vcount.dae", with("<vcount>3</vcount>", "<vcount>2147483647</vcount>"),
                "<p> in <geometry id=\"quad\">", "<vcount> adds up to 2147483647 corners, which with 2 index offsets"
                        + " need 4294967294 indices, <p> has 6");
    }

    @Test
    void hugeInfluenceCountsAreRefusedWithoutOverflow() {
        // 1 + 2 + 2 + (2^31-1) = 2,147,483,652 influences: more than an int, summed in long.
        refused("huge-influences.dae", with("<vcount>1 2 2 1</vcount>", "<vcount>1 2 2 2147483647</vcount>"),
                "<v> in <controller id=\"quad-skin\">", "<vcount> adds up to 2147483652 influences");
    }

    @Test
    void vcountEntryBeyondIntRangeIsRefused() {
        refused("vcount-range.dae", with("<vcount>3</vcount>", "<vcount>2147483648</vcount>"),
                "<vcount> in <geometry id=\"quad\">", "value 0 \"2147483648\" is integer out of range");
    }

    @Test
    void hugeInputOffsetIsRefused() {
        // offset 2^31-1 would make the index stride 2^31, which overflows an int.
        refused("huge-offset.dae", with("<input semantic=\"WEIGHT\" source=\"#quad-weights\" offset=\"1\"/>",
                "<input semantic=\"WEIGHT\" source=\"#quad-weights\" offset=\"2147483647\"/>"),
                "<input> in <controller id=\"quad-skin\">", "offset=\"2147483647\" is out of range");
    }

    @Test
    void largeInputOffsetIsCheckedAgainstTheIndices() {
        // offset 1000 makes the stride 1001: 3 corners need 3003 indices, <p> has 6.
        refused("large-offset.dae", with("<input semantic=\"NORMAL\" source=\"#quad-nrm\" offset=\"1\"/>\n"
                + "          <p>0 0 1 0 2 0</p>", "<input semantic=\"NORMAL\" source=\"#quad-nrm\" offset=\"1000\"/>\n"
                + "          <p>0 0 1 0 2 0</p>"), "<p> in <geometry id=\"quad\">",
                "count=\"1\" triangles with 1001 index offsets need 3003 indices, <p> has 6");
    }

    // --------------------------------------------------------------------------- nesting, instancing

    @Test
    void hundredThousandNestedElementsAreRefusedWithoutStackOverflow() {
        StringBuilder sb = new StringBuilder("<COLLADA>");
        for (int i = 0; i < 100_000; i++) {
            sb.append("<node>");
        }
        // Unclosed on purpose: the refusal must come at depth 512, long before the end.
        refused("deep.dae", sb.toString(), "<node> at line 1", "elements nested deeper than 512 levels");
    }

    @Test
    void instanceNodeCycleIsRefused() {
        String xml = with("<node id=\"marker\" name=\"marker\">", "<node id=\"marker\" name=\"marker\">"
                + "<node id=\"marker-child\"><instance_node url=\"#marker\"/></node>");
        refused("cycle.dae", xml, "<instance_node> in <node id=\"marker-child\">",
                "url=\"#marker\" instantiates a node that contains it (a cycle)");
    }

    @Test
    void instanceNodeTwoNodeCycleIsRefused() {
        String xml = with("<node id=\"marker\" name=\"marker\">", "<node id=\"ping\"><instance_node url=\"#pong\"/></node>"
                + "<node id=\"pong\"><instance_node url=\"#ping\"/></node><node id=\"marker\" name=\"marker\">"
                + "<instance_node url=\"#ping\"/>");
        refused("ping-pong.dae", xml, "<instance_node> in <node id=\"pong\">", "(a cycle)");
    }

    @Test
    void manyJointsSharingOneNameWithManyNodesResolveQuickly() {
        // 20,000 joints all named "x" and 20,000 nodes with id and sid "x", none under the
        // skeleton root: every joint falls back to the id lookup. Scanning every candidate per
        // joint (4 * 10^8 steps, about 20 s before the lookup was made logarithmic) is a denial of
        // service from a 1 MB file. The instance node quad-node is a top-level node, so no
        // candidate shares an ancestor with it and every joint takes the first "x" node: index 5
        // (after Armature, Root, Tip, the marker copy and quad-node).
        int n = 20_000;
        StringBuilder names = new StringBuilder();
        StringBuilder matrices = new StringBuilder();
        StringBuilder nodes = new StringBuilder();
        for (int i = 0; i < n; i++) {
            names.append("x ");
            matrices.append("1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1 ");
            nodes.append("<node id=\"x\" sid=\"x\"/>\n");
        }
        String xml = with("<Name_array id=\"quad-joints-array\" count=\"2\">Root Tip</Name_array>",
                "<Name_array id=\"quad-joints-array\" count=\"" + n + "\">" + names + "</Name_array>")
                .replace("<accessor source=\"#quad-joints-array\" count=\"2\"",
                        "<accessor source=\"#quad-joints-array\" count=\"" + n + "\"")
                .replace("count=\"32\">1 0 0 0  0 1 0 0  0 0 1 0  0 0 0 1\n            1 0 0 -1  0 1 0 0  0 0 1 0  0 0 0 1<",
                        "count=\"" + 16 * n + "\">" + matrices + "<")
                .replace("<accessor source=\"#quad-ibm-array\" count=\"2\"",
                        "<accessor source=\"#quad-ibm-array\" count=\"" + n + "\"")
                .replace("<node id=\"static-quad\"", nodes + "<node id=\"static-quad\"");
        Model m = assertTimeoutPreemptively(FAST, () -> Fixtures.read("shared-names.dae", xml));
        assertEquals(n, m.skins().get(0).jointCount());
        int[] joints = m.instances().stream().filter(i -> i.isSkinned()).findFirst().orElseThrow().jointNodes();
        assertEquals(n, joints.length);
        assertEquals("quad-node", m.node(4).id());
        assertEquals("x", m.node(5).id());
        for (int j : joints) {
            assertEquals(5, j);
        }
    }

    @Test
    void manySkeletonRootsAndManyJointsResolveQuickly() {
        // 100,000 <skeleton> roots (leaf nodes r0..r99999) and 100,000 joints named "x", while the
        // only sid "x" sits outside every root: each joint searches every root before it falls
        // back. Looping over the roots per joint is 10^10 steps (minutes); with a rank per node it
        // is one pass per joint name. The fallback finds the node with id "x" (index 4: marker 0,
        // Armature 1, Root 2, Tip 3, then the "x" node).
        int n = 100_000;
        StringBuilder names = new StringBuilder();
        StringBuilder matrices = new StringBuilder();
        StringBuilder rootNodes = new StringBuilder("<node id=\"x\" sid=\"x\"/>\n");
        StringBuilder skeletons = new StringBuilder();
        for (int i = 0; i < n; i++) {
            names.append("x ");
            matrices.append("1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1 ");
            rootNodes.append("<node id=\"r").append(i).append("\"/>\n");
            skeletons.append("<skeleton>#r").append(i).append("</skeleton>");
        }
        String xml = with("<Name_array id=\"quad-joints-array\" count=\"2\">Root Tip</Name_array>",
                "<Name_array id=\"quad-joints-array\" count=\"" + n + "\">" + names + "</Name_array>")
                .replace("<accessor source=\"#quad-joints-array\" count=\"2\"",
                        "<accessor source=\"#quad-joints-array\" count=\"" + n + "\"")
                .replace("count=\"32\">1 0 0 0  0 1 0 0  0 0 1 0  0 0 0 1\n            1 0 0 -1  0 1 0 0  0 0 1 0  0 0 0 1<",
                        "count=\"" + 16 * n + "\">" + matrices + "<")
                .replace("<accessor source=\"#quad-ibm-array\" count=\"2\"",
                        "<accessor source=\"#quad-ibm-array\" count=\"" + n + "\"")
                .replace("<skeleton>#Root</skeleton>", skeletons.toString())
                .replace("<node id=\"quad-node\"", rootNodes + "<node id=\"quad-node\"");
        Model m = assertTimeoutPreemptively(FAST, () -> Fixtures.read("many-roots.dae", xml));
        int[] joints = m.instances().stream().filter(i -> i.isSkinned()).findFirst().orElseThrow().jointNodes();
        assertEquals(n, joints.length);
        assertEquals(n, m.instances().stream().filter(i -> i.isSkinned()).findFirst().orElseThrow()
                .skeletonRoots().length);
        assertEquals("x", m.node(4).id());
        for (int j : joints) {
            assertEquals(4, j);
        }
        assertTrue(m.warnings().stream().anyMatch(w -> w.message().contains("found by id or name instead")),
                () -> m.warnings().toString());
    }

    @Test
    void instancingBombIsRefusedQuickly() {
        // Library node n_k instances n_(k-1) ten times, 8 levels: n8 expands to 10^8 + ... nodes.
        // n6 is the first to exceed 1,000,000 (1,111,111 nodes), so it is the one named.
        StringBuilder lib = new StringBuilder("<node id=\"n0\"/>");
        for (int level = 1; level <= 8; level++) {
            lib.append("<node id=\"n").append(level).append("\">");
            for (int k = 0; k < 10; k++) {
                lib.append("<instance_node url=\"#n").append(level - 1).append("\"/>");
            }
            lib.append("</node>");
        }
        String xml = with("<node id=\"marker\" name=\"marker\">", lib + "<node id=\"marker\" name=\"marker\">")
                .replace("<instance_node url=\"#marker\"/>", "<instance_node url=\"#n8\"/>");
        assertTimeoutPreemptively(Duration.ofSeconds(1), () -> {
            long before = allocatedBytes();
            refused("bomb.dae", xml, "<node id=\"n6\">", "more than 1000000 nodes");
            long after = allocatedBytes();
            if (before >= 0) {
                // A 2 KB file may not cost hundreds of megabytes before it is refused.
                assertTrue(after - before < 32_000_000, "allocated " + (after - before) + " bytes");
            }
        });
    }
}
