package org.skinlab.desktop.bench;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

/**
 * Writes a large, valid, skinned and animated COLLADA file for parse benchmarks: a wavy grid of
 * quads ({@code <polylist>} with positions, normals and texture coordinates at separate offsets,
 * as Blender writes them), a chain of joints along it with four influences per position, and
 * matrix keyframes. Deterministic: the same arguments give the same bytes.
 */
public final class SyntheticCollada {
    /** Joints in the chain along the grid. */
    public static final int JOINTS = 8;
    /** Keyframes per joint. */
    public static final int KEYS = 5;

    private SyntheticCollada() {
    }

    /**
     * Writes the file for benchmarks outside skinlab ({@code bench/compare-parse.sh} gives the
     * same bytes to every tool): {@code SyntheticCollada FILE TRIANGLES}; prints the triangle count.
     */
    public static void main(String[] args) throws IOException {
        if (args.length != 2) {
            System.err.println("usage: SyntheticCollada FILE TRIANGLES");
            System.exit(2);
        }
        System.out.println(write(Path.of(args[0]), Long.parseLong(args[1])));
    }

    /** Grid cells per side so that the grid has at least {@code triangles} triangles. */
    public static int cellsPerSide(long triangles) {
        return (int) Math.ceil(Math.sqrt(triangles / 2.0));
    }

    /** Writes the file and returns the number of triangles it holds (2 per grid cell). */
    public static long write(Path file, long minTriangles) throws IOException {
        int n = Math.max(1, cellsPerSide(minTriangles));
        int side = n + 1; // positions per side
        long positions = (long) side * side;
        long quads = (long) n * n;
        try (Writer w = new BufferedWriter(Files.newBufferedWriter(file, StandardCharsets.UTF_8), 1 << 16)) {
            w.write("<?xml version=\"1.0\" encoding=\"utf-8\"?>\n");
            w.write("<COLLADA xmlns=\"http://www.collada.org/2005/11/COLLADASchema\" version=\"1.4.1\">\n");
            w.write("  <asset><contributor><authoring_tool>skinlab SyntheticCollada</authoring_tool></contributor>"
                    + "<unit name=\"meter\" meter=\"1\"/><up_axis>Z_UP</up_axis></asset>\n");
            w.write("  <library_geometries><geometry id=\"grid-mesh\" name=\"grid\"><mesh>\n");

            StringBuilder sb = new StringBuilder(1 << 16);
            writePositions(w, sb, n, side, positions);
            writeNormals(w, sb, quads);
            writeUvs(w, sb, n, side, positions);
            writePolylist(w, sb, n, side, quads);
            w.write("  </mesh></geometry></library_geometries>\n");

            writeSkin(w, sb, n, side, positions);
            writeScene(w);
            writeAnimations(w);
            w.write("</COLLADA>\n");
        }
        return 2 * quads;
    }

    /** The grid's positions: a gentle sine surface over 4 m by 4 m. */
    private static void writePositions(Writer w, StringBuilder sb, int n, int side, long positions) throws IOException {
        w.write("    <source id=\"grid-positions\"><float_array id=\"grid-positions-array\" count=\""
                + positions * 3 + "\">");
        for (int y = 0; y < side; y++) {
            for (int x = 0; x < side; x++) {
                float px = x / (float) n * 4f;
                float py = y / (float) n * 4f;
                float pz = 0.1f * (float) Math.sin(px * 3.1) * (float) Math.cos(py * 2.3);
                sb.append(px).append(' ').append(py).append(' ').append(pz).append(' ');
            }
            flush(w, sb);
        }
        flush(w, sb);
        w.write("</float_array><technique_common><accessor source=\"#grid-positions-array\" count=\"" + positions
                + "\" stride=\"3\"><param name=\"X\" type=\"float\"/><param name=\"Y\" type=\"float\"/>"
                + "<param name=\"Z\" type=\"float\"/></accessor></technique_common></source>\n");
    }

    /** One normal per quad (flat shading), an index stream of its own beside the positions'. */
    private static void writeNormals(Writer w, StringBuilder sb, long quads) throws IOException {
        w.write("    <source id=\"grid-normals\"><float_array id=\"grid-normals-array\" count=\"" + quads * 3
                + "\">");
        for (long q = 0; q < quads; q++) {
            float a = (q % 7) * 0.01f;
            float len = (float) Math.sqrt(1 + a * a);
            sb.append(a / len).append(' ').append(0f).append(' ').append(1f / len).append(' ');
            if (sb.length() > (1 << 15)) {
                flush(w, sb);
            }
        }
        flush(w, sb);
        w.write("</float_array><technique_common><accessor source=\"#grid-normals-array\" count=\"" + quads
                + "\" stride=\"3\"><param name=\"X\" type=\"float\"/><param name=\"Y\" type=\"float\"/>"
                + "<param name=\"Z\" type=\"float\"/></accessor></technique_common></source>\n");
    }

    /** One UV per position, a third index stream. */
    private static void writeUvs(Writer w, StringBuilder sb, int n, int side, long positions) throws IOException {
        w.write("    <source id=\"grid-uv\"><float_array id=\"grid-uv-array\" count=\"" + positions * 2 + "\">");
        for (int y = 0; y < side; y++) {
            for (int x = 0; x < side; x++) {
                sb.append(x / (float) n).append(' ').append(y / (float) n).append(' ');
            }
            flush(w, sb);
        }
        w.write("</float_array><technique_common><accessor source=\"#grid-uv-array\" count=\"" + positions
                + "\" stride=\"2\"><param name=\"S\" type=\"float\"/><param name=\"T\" type=\"float\"/>"
                + "</accessor></technique_common></source>\n");
    }

    /** The quads: vertex, normal and UV index of each corner. */
    private static void writePolylist(Writer w, StringBuilder sb, int n, int side, long quads) throws IOException {
        w.write("    <vertices id=\"grid-vertices\"><input semantic=\"POSITION\" source=\"#grid-positions\"/>"
                + "</vertices>\n");
        w.write("    <polylist count=\"" + quads + "\"><input semantic=\"VERTEX\" source=\"#grid-vertices\" "
                + "offset=\"0\"/><input semantic=\"NORMAL\" source=\"#grid-normals\" offset=\"1\"/>"
                + "<input semantic=\"TEXCOORD\" source=\"#grid-uv\" offset=\"2\" set=\"0\"/>\n      <vcount>");
        for (long q = 0; q < quads; q++) {
            sb.append("4 ");
            if (sb.length() > (1 << 15)) {
                flush(w, sb);
            }
        }
        flush(w, sb);
        w.write("</vcount>\n      <p>");
        long q = 0;
        for (int y = 0; y < n; y++) {
            for (int x = 0; x < n; x++, q++) {
                int a = y * side + x;
                int[] corners = {a, a + 1, a + 1 + side, a + side};
                for (int c : corners) {
                    sb.append(c).append(' ').append(q).append(' ').append(c).append(' ');
                }
            }
            flush(w, sb);
        }
        w.write("</p>\n    </polylist>\n");
    }

    private static void writeSkin(Writer w, StringBuilder sb, int n, int side, long positions) throws IOException {
        w.write("  <library_controllers><controller id=\"grid-skin\" name=\"grid-skin\"><skin source=\"#grid-mesh\">\n");
        w.write("    <bind_shape_matrix>1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1</bind_shape_matrix>\n");
        w.write("    <source id=\"grid-joints\"><Name_array id=\"grid-joints-array\" count=\"" + JOINTS + "\">");
        for (int j = 0; j < JOINTS; j++) {
            w.write("Bone" + j + " ");
        }
        w.write("</Name_array><technique_common><accessor source=\"#grid-joints-array\" count=\"" + JOINTS
                + "\" stride=\"1\"><param name=\"JOINT\" type=\"name\"/></accessor></technique_common></source>\n");
        w.write("    <source id=\"grid-bind\"><float_array id=\"grid-bind-array\" count=\"" + 16 * JOINTS + "\">");
        float segment = 4f / JOINTS;
        for (int j = 0; j < JOINTS; j++) {
            // Joint j sits at x = j * segment: the inverse bind moves it back to the origin.
            w.write(String.format(Locale.ROOT, "1 0 0 %s 0 1 0 0 0 0 1 0 0 0 0 1 ", -j * segment));
        }
        w.write("</float_array><technique_common><accessor source=\"#grid-bind-array\" count=\"" + JOINTS
                + "\" stride=\"16\"><param name=\"TRANSFORM\" type=\"float4x4\"/></accessor></technique_common>"
                + "</source>\n");
        // Four weights per position: a falloff over the four nearest joints, normalised.
        w.write("    <source id=\"grid-weights\"><float_array id=\"grid-weights-array\" count=\"" + positions * 4
                + "\">");
        int[] nearest = new int[4];
        float[] weights = new float[4];
        for (int y = 0; y < side; y++) {
            for (int x = 0; x < side; x++) {
                influences(x / (float) n * 4f, segment, nearest, weights);
                for (float wgt : weights) {
                    sb.append(wgt).append(' ');
                }
            }
            flush(w, sb);
        }
        w.write("</float_array><technique_common><accessor source=\"#grid-weights-array\" count=\"" + positions * 4
                + "\" stride=\"1\"><param name=\"WEIGHT\" type=\"float\"/></accessor></technique_common></source>\n");
        w.write("    <joints><input semantic=\"JOINT\" source=\"#grid-joints\"/><input semantic=\"INV_BIND_MATRIX\" "
                + "source=\"#grid-bind\"/></joints>\n");
        w.write("    <vertex_weights count=\"" + positions + "\"><input semantic=\"JOINT\" source=\"#grid-joints\" "
                + "offset=\"0\"/><input semantic=\"WEIGHT\" source=\"#grid-weights\" offset=\"1\"/>\n      <vcount>");
        for (long p = 0; p < positions; p++) {
            sb.append("4 ");
            if (sb.length() > (1 << 15)) {
                flush(w, sb);
            }
        }
        flush(w, sb);
        w.write("</vcount>\n      <v>");
        long weightIndex = 0;
        for (int y = 0; y < side; y++) {
            for (int x = 0; x < side; x++) {
                influences(x / (float) n * 4f, segment, nearest, weights);
                for (int k = 0; k < 4; k++) {
                    sb.append(nearest[k]).append(' ').append(weightIndex++).append(' ');
                }
            }
            flush(w, sb);
        }
        w.write("</v>\n    </vertex_weights>\n  </skin></controller></library_controllers>\n");
    }

    /** The four joints nearest to x along the chain and normalised inverse-distance weights. */
    static void influences(float x, float segment, int[] joints, float[] weights) {
        int centre = Math.min(JOINTS - 1, Math.max(0, Math.round(x / segment)));
        int first = Math.max(0, Math.min(JOINTS - 4, centre - 1));
        float sum = 0f;
        for (int k = 0; k < 4; k++) {
            joints[k] = first + k;
            float d = Math.abs(x - (first + k) * segment) / segment;
            weights[k] = 1f / (1f + d * d * d * d);
            sum += weights[k];
        }
        for (int k = 0; k < 4; k++) {
            weights[k] /= sum;
        }
    }

    private static void writeScene(Writer w) throws IOException {
        float segment = 4f / JOINTS;
        w.write("  <library_visual_scenes><visual_scene id=\"Scene\" name=\"Scene\">\n");
        w.write("    <node id=\"Armature\" name=\"Armature\" type=\"NODE\"><matrix sid=\"transform\">"
                + "1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1</matrix>\n");
        StringBuilder close = new StringBuilder();
        for (int j = 0; j < JOINTS; j++) {
            float x = j == 0 ? 0f : segment;
            w.write("      <node id=\"Armature_Bone" + j + "\" name=\"Bone" + j + "\" sid=\"Bone" + j
                    + "\" type=\"JOINT\"><matrix sid=\"transform\">1 0 0 " + x + " 0 1 0 0 0 0 1 0 0 0 0 1</matrix>\n");
            close.append("</node>");
        }
        w.write(close.toString());
        w.write("\n      <node id=\"grid\" name=\"grid\" type=\"NODE\"><instance_controller url=\"#grid-skin\">"
                + "<skeleton>#Armature_Bone0</skeleton></instance_controller></node>\n");
        w.write("    </node>\n  </visual_scene></library_visual_scenes>\n");
        w.write("  <scene><instance_visual_scene url=\"#Scene\"/></scene>\n");
    }

    private static void writeAnimations(Writer w) throws IOException {
        float segment = 4f / JOINTS;
        w.write("  <library_animations>\n");
        for (int j = 0; j < JOINTS; j++) {
            String id = "Bone" + j + "-anim";
            float x = j == 0 ? 0f : segment;
            w.write("    <animation id=\"" + id + "\"><source id=\"" + id + "-input\"><float_array id=\"" + id
                    + "-input-array\" count=\"" + KEYS + "\">");
            for (int k = 0; k < KEYS; k++) {
                w.write(k * 0.25f + " ");
            }
            w.write("</float_array><technique_common><accessor source=\"#" + id + "-input-array\" count=\"" + KEYS
                    + "\" stride=\"1\"><param name=\"TIME\" type=\"float\"/></accessor></technique_common></source>");
            w.write("<source id=\"" + id + "-output\"><float_array id=\"" + id + "-output-array\" count=\"" + 16 * KEYS
                    + "\">");
            for (int k = 0; k < KEYS; k++) {
                double angle = Math.sin(k * Math.PI / 2) * 0.3;
                float c = (float) Math.cos(angle);
                float s = (float) Math.sin(angle);
                w.write(String.format(Locale.ROOT, "%s 0 %s %s 0 1 0 0 %s 0 %s 0 0 0 0 1 ", c, s, x, -s, c));
            }
            w.write("</float_array><technique_common><accessor source=\"#" + id + "-output-array\" count=\"" + KEYS
                    + "\" stride=\"16\"><param name=\"TRANSFORM\" type=\"float4x4\"/></accessor></technique_common>"
                    + "</source>");
            w.write("<source id=\"" + id + "-interp\"><Name_array id=\"" + id + "-interp-array\" count=\"" + KEYS
                    + "\">");
            for (int k = 0; k < KEYS; k++) {
                w.write("LINEAR ");
            }
            w.write("</Name_array><technique_common><accessor source=\"#" + id + "-interp-array\" count=\"" + KEYS
                    + "\" stride=\"1\"><param name=\"INTERPOLATION\" type=\"name\"/></accessor></technique_common>"
                    + "</source>");
            w.write("<sampler id=\"" + id + "-sampler\"><input semantic=\"INPUT\" source=\"#" + id + "-input\"/>"
                    + "<input semantic=\"OUTPUT\" source=\"#" + id + "-output\"/><input semantic=\"INTERPOLATION\" "
                    + "source=\"#" + id + "-interp\"/></sampler><channel source=\"#" + id + "-sampler\" target=\"Armature_Bone"
                    + j + "/transform\"/></animation>\n");
        }
        w.write("  </library_animations>\n");
    }

    private static void flush(Writer w, StringBuilder sb) throws IOException {
        w.append(sb);
        sb.setLength(0);
    }
}
