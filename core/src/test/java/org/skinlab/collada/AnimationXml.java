package org.skinlab.collada;

/**
 * Builds small COLLADA documents for the animation tests: a visual scene with the given nodes, a
 * {@code <library_animations>} and optionally a {@code <library_animation_clips>}. The pieces are
 * written out by the tests (text blocks) or by {@link #animation} for the common one-channel case,
 * so that every fixture stays short enough to read next to its assertions. Public for the sampler
 * tests in {@code org.skinlab.animation}.
 */
public final class AnimationXml {
    private AnimationXml() {
    }

    /** A document whose visual scene holds {@code nodes} and whose animations are {@code animations}. */
    public static String document(String nodes, String animations) {
        return document(nodes, animations, null);
    }

    /** As {@link #document(String, String)}, plus {@code <library_animation_clips>} when clips is not null. */
    public static String document(String nodes, String animations, String clips) {
        return document("", nodes, animations, clips);
    }

    /** As above, with extra libraries (e.g. {@code <library_nodes>}) written before the scene. */
    public static String document(String libraries, String nodes, String animations, String clips) {
        return """
                <?xml version="1.0" encoding="utf-8"?>
                <COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
                  <asset><unit name="meter" meter="1"/><up_axis>Y_UP</up_axis></asset>
                """ + libraries + """
                  <library_animations>
                """ + animations + """
                  </library_animations>
                """ + (clips == null ? "" : "  <library_animation_clips>\n" + clips + "  </library_animation_clips>\n")
                + """
                  <library_visual_scenes>
                    <visual_scene id="scene">
                """ + nodes + """
                    </visual_scene>
                  </library_visual_scenes>
                  <scene><instance_visual_scene url="#scene"/></scene>
                </COLLADA>
                """;
    }

    /**
     * One {@code <animation id=id>} with one LINEAR channel: INPUT {@code times}, OUTPUT
     * {@code values} with {@code stride} values per key, sampler {@code id-sampler}.
     */
    public static String animation(String id, String target, String times, String values, int stride) {
        return animation(id, target, times, values, stride, null);
    }

    /** As above, with an INTERPOLATION source of the given names (one per key) when not null. */
    public static String animation(String id, String target, String times, String values, int stride,
            String interpolations) {
        StringBuilder sb = new StringBuilder();
        sb.append("    <animation id=\"").append(id).append("\">\n");
        sb.append(floatSource(id + "-input", times, 1));
        sb.append(floatSource(id + "-output", values, stride));
        if (interpolations != null) {
            sb.append(nameSource(id + "-interpolation", interpolations));
        }
        sb.append("      <sampler id=\"").append(id).append("-sampler\">\n");
        sb.append("        <input semantic=\"INPUT\" source=\"#").append(id).append("-input\"/>\n");
        sb.append("        <input semantic=\"OUTPUT\" source=\"#").append(id).append("-output\"/>\n");
        if (interpolations != null) {
            sb.append("        <input semantic=\"INTERPOLATION\" source=\"#").append(id).append("-interpolation\"/>\n");
        }
        sb.append("      </sampler>\n");
        sb.append("      <channel source=\"#").append(id).append("-sampler\" target=\"").append(target).append("\"/>\n");
        sb.append("    </animation>\n");
        return sb.toString();
    }

    /**
     * An animation {@code id} with one channel on {@code target} and a sampler with INPUT, OUTPUT
     * ({@code stride} values per key) and, when not null, INTERPOLATION, IN_TANGENT and OUT_TANGENT
     * sources ({@code tangentStride} values per key): the shape of a curve with tangents.
     */
    public static String curve(String id, String target, String times, String values, int stride,
            String interpolations, String in, String out, int tangentStride) {
        StringBuilder sb = new StringBuilder("    <animation id=\"").append(id).append("\">\n");
        sb.append(floatSource(id + "-input", times, 1)).append(floatSource(id + "-output", values, stride));
        if (interpolations != null) {
            sb.append(nameSource(id + "-interpolation", interpolations));
        }
        if (in != null) {
            sb.append(floatSource(id + "-in", in, tangentStride));
        }
        if (out != null) {
            sb.append(floatSource(id + "-out", out, tangentStride));
        }
        sb.append("      <sampler id=\"").append(id).append("-sampler\">\n");
        sb.append("        <input semantic=\"INPUT\" source=\"#").append(id).append("-input\"/>\n");
        sb.append("        <input semantic=\"OUTPUT\" source=\"#").append(id).append("-output\"/>\n");
        if (interpolations != null) {
            sb.append("        <input semantic=\"INTERPOLATION\" source=\"#").append(id).append("-interpolation\"/>\n");
        }
        if (in != null) {
            sb.append("        <input semantic=\"IN_TANGENT\" source=\"#").append(id).append("-in\"/>\n");
        }
        if (out != null) {
            sb.append("        <input semantic=\"OUT_TANGENT\" source=\"#").append(id).append("-out\"/>\n");
        }
        sb.append("      </sampler>\n");
        sb.append("      <channel source=\"#").append(id).append("-sampler\" target=\"").append(target).append("\"/>\n");
        sb.append("    </animation>\n");
        return sb.toString();
    }

    /**
     * A float {@code <source>} with {@code stride} named components per element (one
     * {@code float4x4} param when the stride is 16, as Blender writes keyed matrices).
     */
    public static String floatSource(String id, String values, int stride) {
        int n = count(values);
        if (n % stride != 0) {
            throw new IllegalArgumentException(n + " values are not a multiple of " + stride);
        }
        StringBuilder params = new StringBuilder();
        if (stride == 16) {
            params.append("<param name=\"TRANSFORM\" type=\"float4x4\"/>");
        } else {
            for (int i = 0; i < stride; i++) {
                params.append("<param name=\"V").append(i).append("\" type=\"float\"/>");
            }
        }
        return "      <source id=\"" + id + "\">\n"
                + "        <float_array id=\"" + id + "-array\" count=\"" + n + "\">" + values.trim() + "</float_array>\n"
                + "        <technique_common><accessor source=\"#" + id + "-array\" count=\"" + (n / stride)
                + "\" stride=\"" + stride + "\">" + params + "</accessor></technique_common>\n"
                + "      </source>\n";
    }

    /** A {@code Name_array} source with one name per element (interpolations). */
    public static String nameSource(String id, String names) {
        int n = count(names);
        return "      <source id=\"" + id + "\">\n"
                + "        <Name_array id=\"" + id + "-array\" count=\"" + n + "\">" + names.trim() + "</Name_array>\n"
                + "        <technique_common><accessor source=\"#" + id + "-array\" count=\"" + n
                + "\" stride=\"1\"><param name=\"INTERPOLATION\" type=\"name\"/></accessor></technique_common>\n"
                + "      </source>\n";
    }

    private static int count(String values) {
        String t = values.trim();
        return t.isEmpty() ? 0 : t.split("\\s+").length;
    }
}
