package org.skinlab.simulation;

import java.util.Locale;

import org.skinlab.collada.Fixtures;
import org.skinlab.model.Model;

/**
 * A small skinned model for the simulation tests, written as COLLADA and read by the importer: a
 * ribbon of {@code 2 * (SEGMENTS + 1)} vertices along x from 0 to 2 (rows at y = -0.5 and 0.5),
 * skinned to Root (at the origin) and Tip (at x = 1), blended between x = 0.5 and 1.5.
 *
 * <p>The clip runs from 0 to {@link #END} seconds. Both joints are keyed as whole matrices once a
 * second, so the rotation interpolation matters between keys:
 * <ul>
 * <li>Root translates along x by exactly the clip time (key k at time k sits at x = k) while
 *     turning about x; the vertices at rest x = 0 lie on that axis, so their deformed x <em>is</em>
 *     the clip time, whatever the method and interpolation: a frame's vertices say which time they
 *     were skinned at.</li>
 * <li>Tip twists about x against Root by 120 degrees between keys, so LBS (which collapses the
 *     blended vertices toward the axis) and DQS (which keeps their distance) differ clearly.</li>
 * </ul>
 */
final class TwistRibbon {
    static final int SEGMENTS = 16;
    static final float END = 4f;
    /** Root's turn about x at keys 0..4 (degrees), 90 apart: LERP, NLERP and SLERP differ between keys. */
    private static final double[] ROOT_DEGREES = {0, 90, 180, 270, 360};
    /** Tip's twist against Root at keys 0..4 (degrees). */
    private static final double[] TIP_DEGREES = {0, 120, 240, 120, 0};

    private TwistRibbon() {
    }

    static Model model() {
        return Fixtures.read("twist-ribbon.dae", xml());
    }

    static String xml() {
        int columns = SEGMENTS + 1;
        int positions = 2 * columns;
        StringBuilder pos = new StringBuilder();
        for (int i = 0; i < columns; i++) {
            float x = 2f * i / SEGMENTS;
            pos.append(f(x)).append(" -0.5 0  ").append(f(x)).append(" 0.5 0  ");
        }
        StringBuilder tri = new StringBuilder();
        for (int i = 0; i < SEGMENTS; i++) {
            int a = 2 * i;
            int b = a + 1;
            int c = a + 2;
            int d = a + 3;
            tri.append(a).append(" 0 ").append(c).append(" 0 ").append(b).append(" 0  ");
            tri.append(b).append(" 0 ").append(c).append(" 0 ").append(d).append(" 0  ");
        }
        StringBuilder weights = new StringBuilder();
        StringBuilder vcount = new StringBuilder();
        StringBuilder v = new StringBuilder();
        int w = 0;
        for (int p = 0; p < positions; p++) {
            float x = 2f * (p / 2) / SEGMENTS;
            float tip = Math.max(0f, Math.min(1f, x - 0.5f));
            if (tip == 0f || tip == 1f) {
                vcount.append("1 ");
                weights.append("1 ");
                v.append(tip == 0f ? 0 : 1).append(' ').append(w++).append("  ");
            } else {
                vcount.append("2 ");
                weights.append(f(1f - tip)).append(' ').append(f(tip)).append(' ');
                v.append("0 ").append(w++).append(" 1 ").append(w++).append("  ");
            }
        }
        int keys = ROOT_DEGREES.length;
        StringBuilder times = new StringBuilder();
        StringBuilder rootKeys = new StringBuilder();
        StringBuilder tipKeys = new StringBuilder();
        StringBuilder linear = new StringBuilder();
        for (int k = 0; k < keys; k++) {
            times.append(k).append(' ');
            rootKeys.append(rotationX(k, ROOT_DEGREES[k])).append("  ");
            tipKeys.append(rotationX(1, TIP_DEGREES[k])).append("  ");
            linear.append("LINEAR ");
        }
        return """
                <?xml version="1.0" encoding="utf-8"?>
                <COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
                  <asset><unit name="meter" meter="1"/><up_axis>Z_UP</up_axis></asset>
                  <library_geometries>
                    <geometry id="ribbon" name="ribbon"><mesh>
                """
                + source("ribbon-pos", pos.toString(), 3, "<param name=\"X\" type=\"float\"/><param name=\"Y\" type=\"float\"/><param name=\"Z\" type=\"float\"/>")
                + source("ribbon-nrm", "0 0 1", 3, "<param name=\"X\" type=\"float\"/><param name=\"Y\" type=\"float\"/><param name=\"Z\" type=\"float\"/>")
                + """
                      <vertices id="ribbon-vtx"><input semantic="POSITION" source="#ribbon-pos"/></vertices>
                """
                + "      <triangles count=\"" + 2 * SEGMENTS + "\">\n"
                + """
                        <input semantic="VERTEX" source="#ribbon-vtx" offset="0"/>
                        <input semantic="NORMAL" source="#ribbon-nrm" offset="1"/>
                """
                + "        <p>" + tri.toString().trim() + "</p>\n"
                + """
                      </triangles>
                    </mesh></geometry>
                  </library_geometries>
                  <library_controllers>
                    <controller id="ribbon-skin"><skin source="#ribbon">
                      <bind_shape_matrix>1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1</bind_shape_matrix>
                      <source id="ribbon-joints"><Name_array id="ribbon-joints-array" count="2">Root Tip</Name_array>
                        <technique_common><accessor source="#ribbon-joints-array" count="2" stride="1"><param name="JOINT" type="name"/></accessor></technique_common></source>
                """
                + source("ribbon-ibm", "1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1  1 0 0 -1 0 1 0 0 0 0 1 0 0 0 0 1", 16,
                        "<param name=\"TRANSFORM\" type=\"float4x4\"/>")
                + source("ribbon-weights", weights.toString(), 1, "<param name=\"WEIGHT\" type=\"float\"/>")
                + """
                      <joints>
                        <input semantic="JOINT" source="#ribbon-joints"/>
                        <input semantic="INV_BIND_MATRIX" source="#ribbon-ibm"/>
                      </joints>
                """
                + "      <vertex_weights count=\"" + positions + "\">\n"
                + """
                        <input semantic="JOINT" source="#ribbon-joints" offset="0"/>
                        <input semantic="WEIGHT" source="#ribbon-weights" offset="1"/>
                """
                + "        <vcount>" + vcount.toString().trim() + "</vcount>\n"
                + "        <v>" + v.toString().trim() + "</v>\n"
                + """
                      </vertex_weights>
                    </skin></controller>
                  </library_controllers>
                  <library_animations>
                    <animation id="root-anim">
                """
                + source("root-time", times.toString(), 1, "<param name=\"TIME\" type=\"float\"/>")
                + source("root-out", rootKeys.toString(), 16, "<param name=\"TRANSFORM\" type=\"float4x4\"/>")
                + names("root-interp", linear.toString())
                + """
                      <sampler id="root-sampler">
                        <input semantic="INPUT" source="#root-time"/>
                        <input semantic="OUTPUT" source="#root-out"/>
                        <input semantic="INTERPOLATION" source="#root-interp"/>
                      </sampler>
                      <channel source="#root-sampler" target="Root/transform"/>
                    </animation>
                    <animation id="tip-anim">
                """
                + source("tip-time", times.toString(), 1, "<param name=\"TIME\" type=\"float\"/>")
                + source("tip-out", tipKeys.toString(), 16, "<param name=\"TRANSFORM\" type=\"float4x4\"/>")
                + names("tip-interp", linear.toString())
                + """
                      <sampler id="tip-sampler">
                        <input semantic="INPUT" source="#tip-time"/>
                        <input semantic="OUTPUT" source="#tip-out"/>
                        <input semantic="INTERPOLATION" source="#tip-interp"/>
                      </sampler>
                      <channel source="#tip-sampler" target="Tip/transform"/>
                    </animation>
                  </library_animations>
                  <library_animation_clips>
                """
                + "    <animation_clip id=\"twist\" name=\"twist\" start=\"0\" end=\"" + f(END) + "\">"
                + "<instance_animation url=\"#root-anim\"/><instance_animation url=\"#tip-anim\"/></animation_clip>\n"
                + """
                  </library_animation_clips>
                  <library_visual_scenes>
                    <visual_scene id="scene">
                      <node id="Root" name="Root" sid="Root" type="JOINT">
                        <matrix sid="transform">1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1</matrix>
                        <node id="Tip" name="Tip" sid="Tip" type="JOINT">
                          <matrix sid="transform">1 0 0 1 0 1 0 0 0 0 1 0 0 0 0 1</matrix>
                        </node>
                      </node>
                      <node id="ribbon-node" name="ribbon-node">
                        <instance_controller url="#ribbon-skin"><skeleton>#Root</skeleton></instance_controller>
                      </node>
                    </visual_scene>
                  </library_visual_scenes>
                  <scene><instance_visual_scene url="#scene"/></scene>
                </COLLADA>
                """;
    }

    /** Row-major translate(tx, 0, 0) * rotateX(degrees), as COLLADA writes a matrix. */
    private static String rotationX(double tx, double degrees) {
        double r = Math.toRadians(degrees);
        double c = Math.cos(r);
        double s = Math.sin(r);
        return "1 0 0 " + f(tx) + " 0 " + f(c) + " " + f(-s) + " 0 0 " + f(s) + " " + f(c) + " 0 0 0 0 1";
    }

    private static String source(String id, String values, int stride, String params) {
        String t = values.trim();
        int n = t.split("\\s+").length;
        return "      <source id=\"" + id + "\"><float_array id=\"" + id + "-array\" count=\"" + n + "\">" + t
                + "</float_array>\n        <technique_common><accessor source=\"#" + id + "-array\" count=\""
                + n / stride + "\" stride=\"" + stride + "\">" + params + "</accessor></technique_common></source>\n";
    }

    private static String names(String id, String values) {
        String t = values.trim();
        int n = t.split("\\s+").length;
        return "      <source id=\"" + id + "\"><Name_array id=\"" + id + "-array\" count=\"" + n + "\">" + t
                + "</Name_array>\n        <technique_common><accessor source=\"#" + id + "-array\" count=\"" + n
                + "\" stride=\"1\"><param name=\"INTERPOLATION\" type=\"name\"/></accessor></technique_common></source>\n";
    }

    private static String f(double v) {
        return String.format(Locale.ROOT, "%.9g", v);
    }
}
