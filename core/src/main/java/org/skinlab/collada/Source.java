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
    private final XmlElement array;
    private final float[] floats;
    private final int[] ints;
    private final String[] names;
    private final boolean idrefs;
    private final int count;
    private final int stride;
    private final int offset;
    private final int[] components; // value offsets within one element, one per component
    private final int nonFinite;    // NaN and infinite values in the array
    private final String firstNonFinite; // the first of them: "value 3 \"NaN\"", or null
    private final String nonFiniteReason; // why it is refused where data must be finite
    private Source finite;          // this source with non-finite values as 0 (made on demand)

    private Source(XmlElement element, XmlElement array, float[] floats, int[] ints, String[] names, boolean idrefs,
            int count, int stride, int offset, int[] components, int nonFinite, String firstNonFinite,
            String nonFiniteReason) {
        this.element = element;
        this.array = array;
        this.floats = floats;
        this.ints = ints;
        this.names = names;
        this.idrefs = idrefs;
        this.count = count;
        this.stride = stride;
        this.offset = offset;
        this.components = components;
        this.nonFinite = nonFinite;
        this.firstNonFinite = firstNonFinite;
        this.nonFiniteReason = nonFiniteReason;
    }

    private Source(XmlElement element, XmlElement array, Values values, int count, int stride, int offset,
            int[] components) {
        this(element, array, values.floats, values.ints, values.names, values.idrefs, count, stride, offset,
                components, values.nonFinite, values.firstNonFinite, values.nonFiniteReason);
    }

    static Source parse(ImportContext ctx, XmlElement source) throws ColladaException {
        XmlElement own = ownArray(source);
        XmlElement technique = source.child("technique_common");
        XmlElement accessor = technique == null ? null : technique.child("accessor");
        XmlElement array = own;
        if (accessor != null) {
            array = accessorArray(ctx, accessor, own);
        }
        if (array == null) {
            throw ctx.error(source, "has no data array (float_array, int_array, Name_array or IDREF_array)");
        }
        Values values = Values.read(ctx, array);
        if (accessor == null) {
            ctx.warn(source, "no <technique_common><accessor>; every value read as one element");
            return new Source(source, array, values, values.length, 1, 0, new int[] {0});
        }
        int count = ctx.count(accessor, "count", -1);
        if (count < 0) {
            throw ctx.error(accessor, "missing attribute count");
        }
        int stride = ctx.count(accessor, "stride", 1);
        int offset = ctx.count(accessor, "offset", 0);
        if (stride == 0 && count > 0) {
            throw ctx.error(accessor, "stride=\"0\"");
        }
        List<XmlElement> params = accessor.children("param");
        boolean anyNamed = anyNamed(ctx, accessor, params);
        List<Integer> comps = new ArrayList<>();
        int slot = namedComponents(params, anyNamed, comps);
        if (stride == 0) {
            stride = Math.max(1, slot); // count="0" stride="0": an empty source, however it is laid out
        }
        if (slot > stride) {
            throw ctx.error(accessor, "its params span " + slot + " values but stride=\"" + stride + "\"");
        }
        if (params.isEmpty()) {
            for (int k = 0; k < stride; k++) {
                comps.add(k);
            }
        }
        int[] components = toArray(comps);
        count = elementsPresent(ctx, accessor, count, stride, offset, components, values.length);
        return new Source(source, array, values, count, stride, offset, components);
    }

    /** The source's own array, the first child that is one, or null. */
    private static XmlElement ownArray(XmlElement source) {
        for (XmlElement c : source.children()) {
            if (isArray(c)) {
                return c;
            }
        }
        return null;
    }

    /** Whether some param of the accessor has a name; warns (once per file) when none has. */
    private static boolean anyNamed(ImportContext ctx, XmlElement accessor, List<XmlElement> params) {
        boolean anyNamed = false;
        for (XmlElement param : params) {
            anyNamed |= param.attr("name") != null;
        }
        if (!params.isEmpty() && !anyNamed) {
            // The specification says an unnamed param skips its slot, which would leave nothing to
            // read; FBX-COLLADA, Mixamo, Softimage and 3ds Max write such accessors for joint
            // names and sampler inputs and outputs, meaning "the data".
            ctx.warnOnce("unnamed-params", accessor, "no <param> of this accessor has a name (and maybe others);"
                    + " their components are read as data");
        }
        return anyNamed;
    }

    /**
     * Adds to {@code comps} the value offsets the params pick (the named ones, or all when none
     * is named) and returns how many values the params span.
     */
    private static int namedComponents(List<XmlElement> params, boolean anyNamed, List<Integer> comps) {
        int slot = 0;
        for (XmlElement param : params) {
            int width = paramWidth(param.attr("type"));
            if (param.attr("name") != null || !anyNamed) {
                for (int k = 0; k < width; k++) {
                    comps.add(slot + k);
                }
            }
            slot += width;
        }
        return slot;
    }

    private static int[] toArray(List<Integer> comps) {
        int[] components = new int[comps.size()];
        for (int i = 0; i < components.length; i++) {
            components[i] = comps.get(i);
        }
        return components;
    }

    /**
     * The accessor's count, or the whole elements the array holds when the count promises more
     * (with a warning): element i reads values offset + i * stride + c for its components c.
     */
    private static int elementsPresent(ImportContext ctx, XmlElement accessor, int count, int stride, int offset,
            int[] components, int length) {
        int span = 0;
        for (int c : components) {
            span = Math.max(span, c + 1);
        }
        long needed = count == 0 ? 0 : (long) offset + (long) (count - 1) * stride + span;
        if (count > 0 && needed > length) {
            // The count attribute promises more than the array holds (the CTS has such files): the
            // whole elements present are read; an index past them is refused where it is used.
            int present = length < (long) offset + span ? 0 : (length - offset - span) / stride + 1;
            ctx.warn(accessor, "count=\"" + count + "\" stride=\"" + stride + "\" offset=\"" + offset + "\" needs "
                    + needed + " values but the array has " + length + "; the " + present + " whole elements present"
                    + " are read");
            return present;
        }
        return count;
    }

    /** The values of a data array, with what the scanner found non-finite among floats. */
    private static final class Values {
        float[] floats;
        int[] ints;
        String[] names;
        int length;
        int nonFinite;
        String firstNonFinite;
        String nonFiniteReason;
        boolean idrefs;

        /** Reads the array's values; warns when its count attribute disagrees with them. */
        static Values read(ImportContext ctx, XmlElement array) throws ColladaException {
            int declared = ctx.count(array, "count", -1);
            Values v = new Values();
            switch (array.name()) {
                case "float_array": {
                    NumberScanner n = NumberParser.scannedFloats(ctx, array);
                    v.floats = n.floats();
                    v.length = v.floats.length;
                    v.nonFinite = n.nonFiniteCount();
                    if (v.nonFinite > 0) {
                        v.firstNonFinite = "value " + n.nonFiniteIndex() + " \"" + n.nonFiniteToken() + "\"";
                        v.nonFiniteReason = n.nonFiniteReason();
                    }
                    break;
                }
                case "int_array":
                    v.ints = NumberParser.ints(ctx, array, -1);
                    v.length = v.ints.length;
                    break;
                case "bool_array":
                    throw ctx.error(array, "a bool_array cannot feed geometry, skin or animation data");
                default:
                    v.names = NumberParser.names(ctx, array, -1);
                    if (declared >= 0 && v.names.length > declared) {
                        v.names = SpacedNames.rejoin(ctx, array, v.names, declared);
                    }
                    v.length = v.names.length;
                    break;
            }
            if (declared >= 0 && declared != v.length) {
                // Exporters get the count attribute wrong (the CTS has such files); the values
                // present are what the accessor reads, and it is checked against them
                // (elementsPresent).
                ctx.warn(array, "count=\"" + declared + "\" but " + v.length + " values; the values present are read");
            }
            v.idrefs = array.name().equals("IDREF_array");
            return v;
        }
    }

    private static boolean isArray(XmlElement e) {
        switch (e.name()) {
            case "float_array":
            case "int_array":
            case "Name_array":
            case "IDREF_array":
            case "SIDREF_array":
            case "bool_array":
                return true;
            default:
                return false;
        }
    }

    /**
     * The array an accessor reads: usually the source's own, but the specification lets it read
     * any array of the file (several sources may share one). A reference that names nothing while
     * the source holds an array of its own is a slip of the exporter (or hand edit: the CTS has
     * one); that array is read, with a warning. References to other documents are refused.
     */
    private static XmlElement accessorArray(ImportContext ctx, XmlElement accessor, XmlElement own)
            throws ColladaException {
        String ref = ctx.attr(accessor, "source");
        if (own != null && ctx.byId(ImportContext.idPart(ref)) == null) {
            ctx.referencedId(accessor, "source"); // a reference into another document stays refused
            ctx.warn(accessor, "source=\"" + accessor.attr("source") + "\" refers to nothing in the file; its"
                    + " <source>'s own <" + own.name() + (own.id() == null ? "" : " id=\"" + own.id() + "\"")
                    + "> is read");
            return own;
        }
        return ctx.resolve(accessor, "source", "float_array", "int_array", "Name_array", "IDREF_array",
                "SIDREF_array", "bool_array");
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

    /** Refuses a source of names, and a source with NaN or infinite values. */
    void requireFloats(ImportContext ctx, XmlElement user, String what) throws ColladaException {
        requireNumbers(ctx, user, what);
        if (nonFinite > 0) {
            throw ctx.error(array, firstNonFinite + " is " + nonFiniteReason + " (" + what + " data must be finite)");
        }
    }

    private void requireNumbers(ImportContext ctx, XmlElement user, String what) throws ColladaException {
        if (floats == null && ints == null) {
            throw ctx.error(user, what + " source \"" + id() + "\" holds names, expected numbers");
        }
    }

    /**
     * This source with NaN and infinite values read as 0, for data a mesh can do without
     * (texture coordinates, colours, normals): the file's one broken UV set should not keep the
     * character from loading. Warns once per source.
     */
    Source finiteOrZero(ImportContext ctx, XmlElement user, String what) throws ColladaException {
        requireNumbers(ctx, user, what);
        if (nonFinite == 0) {
            return this;
        }
        if (finite == null) {
            float[] clean = floats.clone();
            for (int i = 0; i < clean.length; i++) {
                if (!Float.isFinite(clean[i])) {
                    clean[i] = 0f;
                }
            }
            finite = new Source(element, array, clean, null, null, false, count, stride, offset, components, 0, null, null);
            ctx.warn(array, nonFinite + " NaN or infinite values (first: " + firstNonFinite + ") in " + what
                    + " source \"" + id() + "\"; read as 0");
        }
        return finite;
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
