package org.skinlab.collada;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.stream.Collectors;

import org.joml.Matrix4fc;
import org.skinlab.model.ImportWarning;
import org.skinlab.model.Model;
import org.skinlab.model.Node;

/**
 * Building blocks for the small inline COLLADA documents of the skin and scene tests, so that each
 * test shows only the part it is about. Everything written here is plain COLLADA 1.4.1.
 */
final class Snippets {
    private Snippets() {
    }

    /** A whole document around the given library and scene elements. */
    static String collada(String... parts) {
        return "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
                + "<COLLADA xmlns=\"http://www.collada.org/2005/11/COLLADASchema\" version=\"1.4.1\">\n"
                + "<asset><unit name=\"meter\" meter=\"1\"/><up_axis>Y_UP</up_axis></asset>\n"
                + String.join("\n", parts) + "\n</COLLADA>\n";
    }

    /**
     * A {@code <geometry id>} whose mesh has {@code positions} positions, position i at (i, 0, 0)
     * except position 1 at (0, 1, 0) so that the first triangle (0 1 2) is not degenerate.
     */
    static String geometry(String id, int positions) {
        StringBuilder values = new StringBuilder();
        for (int i = 0; i < positions; i++) {
            values.append(i == 1 ? "0 1 0 " : i + " 0 0 ");
        }
        return "<geometry id=\"" + id + "\" name=\"" + id + "\"><mesh>\n"
                + "  <source id=\"" + id + "-pos\"><float_array id=\"" + id + "-pos-array\" count=\"" + 3 * positions
                + "\">" + values.toString().trim() + "</float_array>\n"
                + "    <technique_common><accessor source=\"#" + id + "-pos-array\" count=\"" + positions
                + "\" stride=\"3\"><param name=\"X\" type=\"float\"/><param name=\"Y\" type=\"float\"/>"
                + "<param name=\"Z\" type=\"float\"/></accessor></technique_common></source>\n"
                + "  <vertices id=\"" + id + "-vtx\"><input semantic=\"POSITION\" source=\"#" + id + "-pos\"/></vertices>\n"
                + "  <triangles count=\"1\"><input semantic=\"VERTEX\" source=\"#" + id + "-vtx\" offset=\"0\"/>"
                + "<p>0 1 2</p></triangles>\n"
                + "</mesh></geometry>";
    }

    /**
     * A {@code <controller id><skin source="#geometry">} with an identity bind shape matrix,
     * identity inverse bind matrices, joints in a {@code jointArray} ("Name_array" or
     * "IDREF_array") and the given weights, {@code <vcount>} and {@code <v>} (joint offset 0,
     * weight offset 1).
     */
    static String skin(String controllerId, String geometryId, String jointArray, String joints, String weights,
            String vcount, String v) {
        return skin(controllerId, geometryId, "1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1", jointArray, joints,
                identities(joints.trim().split("\\s+").length), weights, vcount, v);
    }

    /** As above with every part given: bind shape and inverse bind matrices row-major as in a file. */
    static String skin(String controllerId, String geometryId, String bindShape, String jointArray, String joints,
            String inverseBinds, String weights, String vcount, String v) {
        int jointCount = joints.trim().split("\\s+").length;
        int weightCount = weights.trim().split("\\s+").length;
        String c = controllerId;
        return "<controller id=\"" + c + "\" name=\"" + c + "\"><skin source=\"#" + geometryId + "\">\n"
                + (bindShape == null ? "" : "  <bind_shape_matrix>" + bindShape + "</bind_shape_matrix>\n")
                + "  <source id=\"" + c + "-joints\"><" + jointArray + " id=\"" + c + "-joints-array\" count=\""
                + jointCount + "\">" + joints + "</" + jointArray + ">\n"
                + "    <technique_common><accessor source=\"#" + c + "-joints-array\" count=\"" + jointCount
                + "\" stride=\"1\"><param name=\"JOINT\" type=\"" + (jointArray.equals("IDREF_array") ? "IDREF" : "name")
                + "\"/></accessor></technique_common></source>\n"
                + "  <source id=\"" + c + "-ibm\"><float_array id=\"" + c + "-ibm-array\" count=\"" + 16 * jointCount
                + "\">" + inverseBinds + "</float_array>\n"
                + "    <technique_common><accessor source=\"#" + c + "-ibm-array\" count=\"" + jointCount
                + "\" stride=\"16\"><param name=\"TRANSFORM\" type=\"float4x4\"/></accessor></technique_common></source>\n"
                + "  <source id=\"" + c + "-weights\"><float_array id=\"" + c + "-weights-array\" count=\"" + weightCount
                + "\">" + weights + "</float_array>\n"
                + "    <technique_common><accessor source=\"#" + c + "-weights-array\" count=\"" + weightCount
                + "\" stride=\"1\"><param name=\"WEIGHT\" type=\"float\"/></accessor></technique_common></source>\n"
                + "  <joints><input semantic=\"JOINT\" source=\"#" + c + "-joints\"/>"
                + "<input semantic=\"INV_BIND_MATRIX\" source=\"#" + c + "-ibm\"/></joints>\n"
                + "  <vertex_weights count=\"" + vcount.trim().split("\\s+").length + "\">"
                + "<input semantic=\"JOINT\" source=\"#" + c + "-joints\" offset=\"0\"/>"
                + "<input semantic=\"WEIGHT\" source=\"#" + c + "-weights\" offset=\"1\"/>\n"
                + "    <vcount>" + vcount + "</vcount><v>" + v + "</v></vertex_weights>\n"
                + "</skin></controller>";
    }

    /** {@code n} row-major identity matrices. */
    static String identities(int n) {
        StringBuilder sb = new StringBuilder();
        for (int i = 0; i < n; i++) {
            sb.append(" 1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1");
        }
        return sb.toString().trim();
    }

    /** Asserts the column-major JOML matrix equals the given rows (row-major, 3 rows of 4). */
    static void assertRows(float[][] rows, Matrix4fc m, float tolerance) {
        for (int r = 0; r < 4; r++) {
            for (int c = 0; c < 4; c++) {
                float expected = r < 3 ? rows[r][c] : (c == 3 ? 1f : 0f);
                int row = r;
                int col = c;
                assertEquals(expected, m.get(c, r), tolerance, () -> "row " + row + " column " + col + " of\n" + m);
            }
        }
    }

    /** The warnings whose message contains {@code text}. */
    static List<ImportWarning> warningsContaining(Model m, String text) {
        return m.warnings().stream().filter(w -> w.message().contains(text)).collect(Collectors.toList());
    }

    /** Asserts exactly one warning contains {@code text}, and returns it. */
    static ImportWarning oneWarning(Model m, String text) {
        List<ImportWarning> found = warningsContaining(m, text);
        assertEquals(1, found.size(), () -> "warnings containing \"" + text + "\": " + m.warnings());
        return found.get(0);
    }

    /** The one node with the given id (fails when there are none or several). */
    static Node node(Model m, String id) {
        List<Node> found = m.nodes().stream().filter(n -> id.equals(n.id())).collect(Collectors.toList());
        assertEquals(1, found.size(), () -> "nodes with id " + id + ": " + found);
        return found.get(0);
    }

    /** Asserts the model has no warnings. */
    static void assertNoWarnings(Model m) {
        assertTrue(m.warnings().isEmpty(), () -> "unexpected warnings: " + m.warnings());
    }
}
