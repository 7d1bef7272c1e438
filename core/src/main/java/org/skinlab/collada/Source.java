package org.skinlab.collada;

import java.util.ArrayList;
import java.util.List;

/**
 * A parsed {@code <source>}: its array and the accessor that reads it. Elements are
 * {@link #count()} groups of {@code stride} values starting at {@code offset}; the named
 * {@code <param>}s pick the components (an unnamed param skips its slot, as the specification
 * says), and a typed param such as {@code float4x4} spans several values.
 */
final class Source {
    final XmlElement element;
    private final float[] floats;
    private final int[] ints;
    private final String[] names;
    private final boolean idrefs;
    private final int count;
    private final int stride;
    private final int offset;
    private final int[] components; // value offsets within one element, one per component

    private Source(XmlElement element, float[] floats, int[] ints, String[] names, boolean idrefs, int count,
            int stride, int offset, int[] components) {
        this.element = element;
        this.floats = floats;
        this.ints = ints;
        this.names = names;
        this.idrefs = idrefs;
        this.count = count;
        this.stride = stride;
        this.offset = offset;
        this.components = components;
    }

    static Source parse(ImportContext ctx, XmlElement source) throws ColladaException {
        XmlElement array = null;
        for (XmlElement c : source.children()) {
            switch (c.name()) {
                case "float_array":
                case "int_array":
                case "Name_array":
                case "IDREF_array":
                case "SIDREF_array":
                case "bool_array":
                    if (array == null) {
                        array = c;
                    }
                    break;
                default:
                    break;
            }
        }
        XmlElement technique = source.child("technique_common");
        XmlElement accessor = technique == null ? null : technique.child("accessor");
        if (accessor != null) {
            // Usually the source's own array, but the specification lets an accessor read any
            // array (several sources may share one); only arrays in this file are followed.
            array = ctx.resolve(accessor, "source", "float_array", "int_array", "Name_array", "IDREF_array",
                    "SIDREF_array", "bool_array");
        }
        if (array == null) {
            throw ctx.error(source, "has no data array (float_array, int_array, Name_array or IDREF_array)");
        }
        int declared = ctx.count(array, "count", -1);
        float[] floats = null;
        int[] ints = null;
        String[] names = null;
        int length;
        switch (array.name()) {
            case "float_array":
                floats = NumberParser.floats(ctx, array, declared);
                length = floats.length;
                break;
            case "int_array":
                ints = NumberParser.ints(ctx, array, declared);
                length = ints.length;
                break;
            case "bool_array":
                throw ctx.error(array, "a bool_array cannot feed geometry, skin or animation data");
            default:
                names = NumberParser.names(ctx, array, declared);
                length = names.length;
                break;
        }
        boolean idrefs = array.name().equals("IDREF_array");

        if (accessor == null) {
            ctx.warn(source, "no <technique_common><accessor>; every value read as one element");
            return new Source(source, floats, ints, names, idrefs, length, 1, 0, new int[] {0});
        }
        int count = ctx.count(accessor, "count", -1);
        if (count < 0) {
            throw ctx.error(accessor, "missing attribute count");
        }
        int stride = ctx.count(accessor, "stride", 1);
        int offset = ctx.count(accessor, "offset", 0);
        if (stride == 0) {
            throw ctx.error(accessor, "stride=\"0\"");
        }
        List<Integer> comps = new ArrayList<>();
        int slot = 0;
        for (XmlElement param : accessor.children("param")) {
            int width = paramWidth(param.attr("type"));
            if (param.attr("name") != null) {
                for (int k = 0; k < width; k++) {
                    comps.add(slot + k);
                }
            }
            slot += width;
        }
        if (slot > stride) {
            throw ctx.error(accessor, "its params span " + slot + " values but stride=\"" + stride + "\"");
        }
        if (accessor.children("param").isEmpty()) {
            for (int k = 0; k < stride; k++) {
                comps.add(k);
            }
        }
        long needed = count == 0 ? 0 : (long) offset + (long) (count - 1) * stride + stride;
        if (count > 0 && needed > length) {
            throw ctx.error(accessor, "count=\"" + count + "\" stride=\"" + stride + "\" offset=\"" + offset
                    + "\" reads " + needed + " values but the array has " + length);
        }
        int[] components = new int[comps.size()];
        for (int i = 0; i < components.length; i++) {
            components[i] = comps.get(i);
        }
        return new Source(source, floats, ints, names, idrefs, count, stride, offset, components);
    }

    /** How many array values a param of this type spans. */
    private static int paramWidth(String type) {
        if (type == null) {
            return 1;
        }
        switch (type) {
            case "float2": case "int2": case "bool2":
                return 2;
            case "float3": case "int3": case "bool3":
                return 3;
            case "float4": case "int4": case "bool4": case "float2x2":
                return 4;
            case "float3x3":
                return 9;
            case "float4x4":
                return 16;
            default:
                return 1;
        }
    }

    String id() {
        return element.id();
    }

    /** Number of elements. */
    int count() {
        return count;
    }

    /** Number of named components per element. */
    int width() {
        return components.length;
    }

    boolean isFloat() {
        return floats != null;
    }

    boolean isNames() {
        return names != null;
    }

    boolean isIdrefs() {
        return idrefs;
    }

    /** Component {@code c} of element {@code i}, as a float. */
    float floatAt(int i, int c) {
        int at = offset + i * stride + components[c];
        return floats != null ? floats[at] : ints[at];
    }

    /** Component 0 of element {@code i}, as a name. */
    String nameAt(int i) {
        return names[offset + i * stride + components[0]];
    }

    /**
     * All elements with exactly {@code width} components each, or an error naming the element
     * that asked ({@code user}) when the source has a different width.
     */
    float[] floats(ImportContext ctx, XmlElement user, int width, String what) throws ColladaException {
        requireFloats(ctx, user, what);
        if (components.length != width) {
            throw ctx.error(user, what + " source \"" + id() + "\" has " + components.length
                    + " components per element, expected " + width);
        }
        float[] out = new float[count * width];
        if (floats != null && stride == width && offset == 0 && isIdentity(components)) {
            System.arraycopy(floats, 0, out, 0, out.length);
            return out;
        }
        for (int i = 0, o = 0; i < count; i++) {
            for (int c = 0; c < width; c++) {
                out[o++] = floatAt(i, c);
            }
        }
        return out;
    }

    /** All names, one per element. */
    String[] names(ImportContext ctx, XmlElement user, String what) throws ColladaException {
        if (names == null) {
            throw ctx.error(user, what + " source \"" + id() + "\" holds numbers, expected names");
        }
        requireComponent(ctx, user, what);
        String[] out = new String[count];
        for (int i = 0; i < count; i++) {
            out[i] = nameAt(i);
        }
        return out;
    }

    void requireFloats(ImportContext ctx, XmlElement user, String what) throws ColladaException {
        if (floats == null && ints == null) {
            throw ctx.error(user, what + " source \"" + id() + "\" holds names, expected numbers");
        }
    }

    /**
     * Refuses a source whose accessor selects no component (every {@code <param>} unnamed) where
     * the caller reads component 0 of each element.
     */
    void requireComponent(ImportContext ctx, XmlElement user, String what) throws ColladaException {
        if (components.length == 0) {
            throw ctx.error(user, what + " source \"" + id() + "\" has 0 components per element (no <param> has"
                    + " a name), expected 1");
        }
    }

    private static boolean isIdentity(int[] components) {
        for (int i = 0; i < components.length; i++) {
            if (components[i] != i) {
                return false;
            }
        }
        return true;
    }
}
