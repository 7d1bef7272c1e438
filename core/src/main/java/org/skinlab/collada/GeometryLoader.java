package org.skinlab.collada;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashSet;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;

import org.skinlab.model.Mesh;
import org.skinlab.model.MeshPart;

/**
 * Reads a {@code <geometry><mesh>} into a {@link Mesh}: the {@code <vertices>} positions, and the
 * triangles of every {@code <triangles>}, {@code <polylist>}, {@code <polygons>},
 * {@code <trifans>} and {@code <tristrips>} element (each {@code <p>} of them), with normals,
 * texture coordinate sets and colours from inputs at any offset. Corners that use the same
 * combination of indices become one vertex.
 *
 * <p>Lenient (with a warning): {@code <lines>}/{@code <linestrips>} are skipped; polygons with
 * fewer than three corners yield no triangles; the holes of a {@code <ph>} are ignored (its outer
 * ring is fan-triangulated); a primitive without normals in a mesh that has them gets zero
 * normals. Refused: a missing POSITION input, indices out of range, and index lists whose length
 * disagrees with {@code count}, {@code vcount} and the number of input offsets.
 */
final class GeometryLoader {
    private static final int SLOT_NORMAL = 0;
    private static final int SLOT_COLOR = 1;
    private static final int FIRST_TEXCOORD_SLOT = 2;

    private final ImportContext ctx;

    GeometryLoader(ImportContext ctx) {
        this.ctx = ctx;
    }

    /** The mesh, or null (with a warning) when the geometry is not a {@code <mesh>}. */
    Mesh load(XmlElement geometry) throws ColladaException {
        XmlElement meshElement = geometry.child("mesh");
        if (meshElement == null) {
            String kind = geometry.children().isEmpty() ? "nothing" : "<" + geometry.children().get(0).name() + ">";
            ctx.warn(geometry, "holds " + kind + " instead of a <mesh>; skipped");
            return null;
        }
        return new Builder(geometry, meshElement).build();
    }

    /** Where one attribute slot of a primitive's vertices comes from. */
    private static final class SlotInput {
        final Source source;
        final int offset; // offset into <p>, or -1: indexed like the position (declared in <vertices>)

        SlotInput(Source source, int offset) {
            this.source = source;
            this.offset = offset;
        }
    }

    private final class Builder {
        private final XmlElement geometry;
        private final XmlElement meshElement;
        private Source positions;
        private int positionCount;
        private XmlElement positionInput;
        /** Attribute inputs declared in <vertices> (indexed with the position), per slot. */
        private SlotInput[] vertexSlots;
        private final List<Integer> vertexTexCoordSets = new ArrayList<>();
        private final List<SlotInput> vertexTexCoordSources = new ArrayList<>();
        private final Map<XmlElement, Integer> texCoordSetOfInput = new IdentityHashMap<>();
        private int[] texCoordSets; // sorted set numbers; slot FIRST_TEXCOORD_SLOT + i is set texCoordSets[i]
        private int slotCount;

        // The distinct vertices. A vertex's key is its position index followed by the bits of its
        // attribute values (normal, colour, texture coordinates): corners merge when their values
        // agree, even where an exporter wrote a separate index per corner (Blender writes one UV
        // index per polygon corner, which would otherwise triple the vertex count).
        private boolean hasNormals;
        private boolean hasColors;
        private int colorAt;
        private int texCoordAt;
        private int keyWidth;
        private int[] keys = new int[0];
        private int vertexCount;
        private int[] table = new int[1 << 10]; // open addressing, vertex index + 1, 0 = empty
        private int[] scratchKey;
        private final IntList triangles = new IntList(1024);
        private final List<MeshPart> parts = new ArrayList<>();
        private int degenerate; // polygons with fewer than 3 corners in the current primitive

        Builder(XmlElement geometry, XmlElement meshElement) {
            this.geometry = geometry;
            this.meshElement = meshElement;
        }

        Mesh build() throws ColladaException {
            readVertices();
            List<XmlElement> primitives = new ArrayList<>();
            TreeSet<Integer> sets = new TreeSet<>();
            boolean normals = vertexSlots[SLOT_NORMAL] != null;
            boolean colors = vertexSlots[SLOT_COLOR] != null;
            for (XmlElement e : meshElement.children()) {
                switch (e.name()) {
                    case "triangles":
                    case "polylist":
                    case "polygons":
                    case "trifans":
                    case "tristrips":
                        primitives.add(e);
                        assignTexCoordSets(e);
                        for (XmlElement in : e.children("input")) {
                            String sem = in.attr("semantic");
                            if ("TEXCOORD".equals(sem) && texCoordSetOfInput.containsKey(in)) {
                                sets.add(texCoordSetOfInput.get(in));
                            } else if ("NORMAL".equals(sem)) {
                                normals = true;
                            } else if ("COLOR".equals(sem)) {
                                colors = true;
                            }
                        }
                        break;
                    case "lines":
                    case "linestrips":
                        ctx.warn(e, "line primitives are not drawn; skipped");
                        break;
                    default:
                        break;
                }
            }
            sets.addAll(vertexTexCoordSets);
            texCoordSets = sets.stream().mapToInt(Integer::intValue).toArray();
            slotCount = FIRST_TEXCOORD_SLOT + texCoordSets.length;
            hasNormals = normals;
            hasColors = colors;
            colorAt = 1 + (normals ? 3 : 0);
            texCoordAt = colorAt + (colors ? 4 : 0);
            keyWidth = texCoordAt + 2 * texCoordSets.length;
            scratchKey = new int[keyWidth];
            vertexSlots = Arrays.copyOf(vertexSlots, slotCount);
            for (int i = 0; i < vertexTexCoordSources.size(); i++) {
                int slot = FIRST_TEXCOORD_SLOT + Arrays.binarySearch(texCoordSets, vertexTexCoordSets.get(i));
                vertexSlots[slot] = vertexTexCoordSources.get(i);
            }
            for (XmlElement primitive : primitives) {
                readPrimitive(primitive);
            }
            return assemble();
        }

        private void readVertices() throws ColladaException {
            XmlElement vertices = ctx.child(meshElement, "vertices");
            vertexSlots = new SlotInput[FIRST_TEXCOORD_SLOT];
            assignTexCoordSets(vertices);
            for (XmlElement input : vertices.children("input")) {
                String semantic = ctx.attr(input, "semantic");
                switch (semantic) {
                    case "POSITION":
                        if (positions == null) {
                            positions = ctx.inputSource(input);
                            positionInput = input;
                        }
                        break;
                    case "NORMAL":
                        vertexSlots[SLOT_NORMAL] = new SlotInput(attributeSource(input, 3, 3), -1);
                        break;
                    case "COLOR":
                        vertexSlots[SLOT_COLOR] = new SlotInput(attributeSource(input, 3, 4), -1);
                        break;
                    case "TEXCOORD":
                        if (texCoordSetOfInput.containsKey(input)) {
                            vertexTexCoordSets.add(texCoordSetOfInput.get(input));
                            vertexTexCoordSources.add(new SlotInput(attributeSource(input, 2, 4), -1));
                        }
                        break;
                    default:
                        break; // tangents, binormals, ...: not used
                }
            }
            if (positions == null) {
                throw ctx.error(vertices, "has no POSITION input");
            }
            positions.requireFloats(ctx, positionInput, "POSITION");
            if (positions.width() == 2) {
                ctx.warn(positionInput, "POSITION source \"" + positions.id() + "\" has 2 components per element;"
                        + " read as X Y with Z = 0");
            } else if (positions.width() != 3) {
                throw ctx.error(positionInput, "POSITION source \"" + positions.id() + "\" has "
                        + positions.width() + " components per element, expected 3 (X Y Z)");
            }
            positionCount = positions.count();
            // Inputs declared in <vertices> are indexed like the position: one shorter than the
            // positions cannot be used at all.
            for (int slot = 0; slot < vertexSlots.length; slot++) {
                if (vertexSlots[slot] != null && vertexSlots[slot].source.count() < positionCount) {
                    warnDropped(vertices, vertexSlots[slot].source, positionCount - 1, "");
                    vertexSlots[slot] = null;
                }
            }
            for (int i = vertexTexCoordSources.size() - 1; i >= 0; i--) {
                if (vertexTexCoordSources.get(i).source.count() < positionCount) {
                    warnDropped(vertices, vertexTexCoordSources.get(i).source, positionCount - 1, "");
                    vertexTexCoordSources.remove(i);
                    vertexTexCoordSets.remove(i);
                }
            }
        }

        /** Warns that an optional input is dropped because an index is out of its source's range. */
        private void warnDropped(XmlElement where, Source source, int index, String scope) {
            ctx.warn(where, "index " + index + " is out of range: source \"" + source.id() + "\" has "
                    + source.count() + " elements; that input is dropped" + scope);
        }

        /** The positions, 3 floats each (2-D positions get Z = 0). */
        private float[] positionValues() throws ColladaException {
            if (positions.width() == 3) {
                return positions.floats(ctx, positionInput, 3, "POSITION");
            }
            float[] xy = positions.floats(ctx, positionInput, 2, "POSITION");
            float[] xyz = new float[3 * positionCount];
            for (int i = 0; i < positionCount; i++) {
                xyz[3 * i] = xy[2 * i];
                xyz[3 * i + 1] = xy[2 * i + 1];
            }
            return xyz;
        }

        /**
         * Numbers the TEXCOORD inputs of one element ({@code <vertices>} or a primitive): a
         * {@code set} as written; an input without one takes the lowest number no other input of
         * the element uses (so "set 1, unnamed" are sets 1 and 0). A second input for the same set
         * is ignored with a warning.
         */
        private void assignTexCoordSets(XmlElement owner) throws ColladaException {
            List<XmlElement> inputs = new ArrayList<>();
            Set<Integer> explicit = new HashSet<>();
            for (XmlElement in : owner.children("input")) {
                if ("TEXCOORD".equals(in.attr("semantic"))) {
                    inputs.add(in);
                    if (in.attr("set") != null) {
                        explicit.add(ctx.count(in, "set", 0));
                    }
                }
            }
            Set<Integer> taken = new HashSet<>();
            int next = 0;
            for (XmlElement in : inputs) {
                int set;
                if (in.attr("set") != null) {
                    set = ctx.count(in, "set", 0);
                } else {
                    while (explicit.contains(next)) {
                        next++;
                    }
                    set = next++;
                }
                if (taken.add(set)) {
                    texCoordSetOfInput.put(in, set);
                } else {
                    ctx.warn(in, "a second TEXCOORD input for set " + set + "; only the first is used");
                }
            }
        }

        /** A float source with between {@code min} and {@code max} components. */
        private Source attributeSource(XmlElement input, int min, int max) throws ColladaException {
            // Texture coordinates, colours and normals can do without a NaN: read as 0, warned.
            Source s = ctx.inputSource(input).finiteOrZero(ctx, input, input.attr("semantic"));
            if (s.width() < min || s.width() > max) {
                throw ctx.error(input, input.attr("semantic") + " source \"" + s.id() + "\" has " + s.width()
                        + " components per element, expected " + (min == max ? "" + min : min + " to " + max));
            }
            return s;
        }

        private void readPrimitive(XmlElement primitive) throws ColladaException {
            // Inputs: where each slot's index comes from.
            int vertexOffset = -1;
            int maxOffset = -1;
            SlotInput[] layout = vertexSlots.clone();
            XmlElement[] slotInputs = new XmlElement[layout.length];
            for (XmlElement input : primitive.children("input")) {
                String semantic = ctx.attr(input, "semantic");
                int offset = ctx.inputOffset(input);
                maxOffset = Math.max(maxOffset, offset);
                int slot = -1;
                switch (semantic) {
                    case "VERTEX":
                        checkVertexReference(input);
                        vertexOffset = offset;
                        break;
                    case "NORMAL":
                        slot = SLOT_NORMAL;
                        layout[slot] = new SlotInput(attributeSource(input, 3, 3), offset);
                        break;
                    case "COLOR":
                        if (layout[SLOT_COLOR] == null || layout[SLOT_COLOR].offset < 0) {
                            slot = SLOT_COLOR;
                            layout[slot] = new SlotInput(attributeSource(input, 3, 4), offset);
                        }
                        break;
                    case "TEXCOORD": {
                        Integer set = texCoordSetOfInput.get(input);
                        if (set != null) {
                            slot = FIRST_TEXCOORD_SLOT + Arrays.binarySearch(texCoordSets, set);
                            layout[slot] = new SlotInput(attributeSource(input, 2, 4), offset);
                        }
                        break;
                    }
                    default:
                        break;
                }
                if (slot >= 0) {
                    slotInputs[slot] = input;
                }
            }
            if (vertexOffset < 0) {
                throw ctx.error(primitive, "has no VERTEX input");
            }
            int stride = maxOffset + 1;
            int count = ctx.count(primitive, "count", -1);
            if (count < 0) {
                throw ctx.error(primitive, "missing attribute count");
            }
            IndexLists lists;
            switch (primitive.name()) {
                case "triangles":
                    lists = triangleIndices(primitive, count, stride);
                    break;
                case "polylist":
                    lists = polylistIndices(primitive, count, stride);
                    break;
                default:
                    lists = polygonIndices(primitive, count, stride);
                    break;
            }
            dropInputsOutOfRange(lists, stride, layout, slotInputs);
            if (hasNormals && layout[SLOT_NORMAL] == null) {
                ctx.warn(primitive, "has no NORMAL input while other primitives do; its normals are zero");
            }
            for (int t = 0; t < texCoordSets.length; t++) {
                if (layout[FIRST_TEXCOORD_SLOT + t] == null) {
                    ctx.warn(primitive, "has no TEXCOORD set " + texCoordSets[t]
                            + " while other primitives do; its texture coordinates there are zero");
                }
            }
            int firstTriangle = triangles.size() / 3;
            degenerate = 0;
            Corners corners = new Corners(layout, vertexOffset, stride);
            switch (primitive.name()) {
                case "triangles":
                    readTriangles(lists, stride, corners);
                    break;
                case "polylist":
                    readPolylist(lists, stride, corners);
                    break;
                default:
                    readPolygonLists(primitive, lists, stride, corners);
                    break;
            }
            if (degenerate > 0) {
                ctx.warn(primitive, degenerate + (degenerate == 1 ? " polygon with fewer than 3 corners yields"
                        : " polygons with fewer than 3 corners yield") + " no triangles");
            }
            int triangleCount = triangles.size() / 3 - firstTriangle;
            parts.add(new MeshPart(primitive.name(), primitive.attr("material"), firstTriangle, triangleCount));
        }

        /**
         * A VERTEX input names the mesh's {@code <vertices>}, the only one it can have: a reference
         * to anything else (or nothing) is a slip, read as that {@code <vertices>} with a warning.
         */
        private void checkVertexReference(XmlElement input) throws ColladaException {
            XmlElement own = meshElement.child("vertices");
            if (ctx.byId(ctx.referencedId(input, "source")) != own) {
                ctx.warn(input, "source=\"" + input.attr("source") + "\" is not this mesh's <vertices>"
                        + (own.id() == null ? "" : " \"#" + own.id() + "\"") + ", the only one a VERTEX input can"
                        + " name; read as that");
            }
        }

        /** A primitive's index data: one list (triangles, polylist) or one per polygon, fan or strip. */
        private final class IndexLists {
            final List<int[]> lists;
            final List<XmlElement> elements; // the <p> of each list, for messages
            final int[] vcount;              // polylist only

            IndexLists(List<int[]> lists, List<XmlElement> elements, int[] vcount) {
                this.lists = lists;
                this.elements = elements;
                this.vcount = vcount;
            }
        }

        private IndexLists triangleIndices(XmlElement primitive, int count, int stride) throws ColladaException {
            List<XmlElement> ps = primitive.children("p");
            int[] p = concatenated(ps);
            long needed = 3L * count * stride;
            if (p.length != needed) {
                XmlElement where = ps.isEmpty() ? primitive : ps.get(0);
                if (p.length % (3 * stride) != 0) {
                    throw ctx.error(where, "count=\"" + count + "\" triangles with " + stride
                            + " index offsets need " + needed + " indices, <p> has " + p.length);
                }
                ctx.warn(primitive, "count=\"" + count + "\" but <p> holds " + p.length / (3 * stride)
                        + " triangles; they are read");
            }
            return new IndexLists(List.of(p), List.of(ps.isEmpty() ? primitive : ps.get(0)), null);
        }

        private IndexLists polylistIndices(XmlElement primitive, int count, int stride) throws ColladaException {
            XmlElement vcountElement = primitive.child("vcount");
            List<XmlElement> ps = primitive.children("p");
            XmlElement where = ps.isEmpty() ? primitive : ps.get(0);
            int[] vcount = vcountElement == null ? new int[0] : NumberParser.ints(ctx, vcountElement, -1);
            long totalCorners = 0;
            for (int n : vcount) {
                if (n < 0) {
                    throw ctx.error(vcountElement, "negative corner count " + n);
                }
                totalCorners += n;
            }
            int[] p = concatenated(ps);
            if (totalCorners * stride != p.length) {
                if (vcount.length != count) {
                    throw ctx.error(vcountElement == null ? primitive : vcountElement, "count=\"" + count
                            + "\" polygons but <vcount> has " + vcount.length + " entries");
                }
                throw ctx.error(where, "<vcount> adds up to " + totalCorners + " corners, which with " + stride
                        + " index offsets need " + totalCorners * stride + " indices, <p> has " + p.length);
            }
            if (vcount.length != count) {
                // <vcount> and <p> agree with each other: the count attribute is the odd one out.
                ctx.warn(primitive, "count=\"" + count + "\" but <vcount> and <p> hold " + vcount.length
                        + " polygons; they are read");
            }
            return new IndexLists(List.of(p), List.of(where), vcount);
        }

        /** {@code <polygons>} (one polygon per {@code <p>} or {@code <ph>}), {@code <trifans>}, {@code <tristrips>}. */
        private IndexLists polygonIndices(XmlElement primitive, int count, int stride) throws ColladaException {
            List<XmlElement> rings = new ArrayList<>();
            int holes = 0;
            for (XmlElement c : primitive.children()) {
                if (c.name().equals("p")) {
                    rings.add(c);
                } else if (c.name().equals("ph") && primitive.name().equals("polygons")) {
                    rings.add(ctx.child(c, "p"));
                    holes += c.children("h").size();
                }
            }
            if (rings.size() != count) {
                ctx.warn(primitive, "count=\"" + count + "\" but it holds " + rings.size()
                        + (primitive.name().equals("polygons") ? " polygons" : " <p> elements") + "; they are read");
            }
            if (holes > 0) {
                ctx.warn(primitive, holes + " polygon holes (<h>) ignored; their outer rings are filled");
            }
            List<int[]> lists = new ArrayList<>(rings.size());
            for (XmlElement ring : rings) {
                int[] p = NumberParser.ints(ctx, ring, -1);
                if (p.length % stride != 0) {
                    throw ctx.error(ring, p.length + " indices are not a multiple of the " + stride
                            + " index offsets");
                }
                lists.add(p);
            }
            return new IndexLists(lists, rings, null);
        }

        /**
         * Drops, with a warning, the optional inputs (normals, colours, texture coordinates) of this
         * primitive that an index points past: the geometry stays usable without them, while
         * positions out of range are refused later. One pass over the indices finds each offset's
         * range.
         */
        private void dropInputsOutOfRange(IndexLists lists, int stride, SlotInput[] layout, XmlElement[] slotInputs) {
            int[] min = new int[stride];
            int[] max = new int[stride];
            Arrays.fill(min, Integer.MAX_VALUE);
            Arrays.fill(max, Integer.MIN_VALUE);
            for (int[] p : lists.lists) {
                for (int i = 0, k = 0; i < p.length; i++) {
                    int v = p[i];
                    if (v < min[k]) {
                        min[k] = v;
                    }
                    if (v > max[k]) {
                        max[k] = v;
                    }
                    if (++k == stride) {
                        k = 0;
                    }
                }
            }
            for (int slot = 0; slot < layout.length; slot++) {
                SlotInput in = layout[slot];
                if (in == null || in.offset < 0 || min[in.offset] > max[in.offset]) {
                    continue; // declared in <vertices> (checked there), or no index at all
                }
                int lo = min[in.offset];
                int hi = max[in.offset];
                if (lo < 0 || hi >= in.source.count()) {
                    warnDropped(slotInputs[slot], in.source, lo < 0 ? lo : hi, " for this primitive");
                    layout[slot] = null;
                }
            }
        }

        private void readTriangles(IndexLists lists, int stride, Corners corners) throws ColladaException {
            int[] p = lists.lists.get(0);
            XmlElement where = lists.elements.get(0);
            int count = p.length / (3 * stride);
            triangles.ensureCapacity(triangles.size() + 3 * count);
            int[] polygon = new int[3];
            for (int t = 0; t < count; t++) {
                corners.polygon(p, t * 3 * stride, 3, polygon, where);
                fan(polygon, 3);
            }
        }

        private void readPolylist(IndexLists lists, int stride, Corners corners) throws ColladaException {
            int[] p = lists.lists.get(0);
            XmlElement where = lists.elements.get(0);
            long totalTriangles = 0;
            int maxCorners = 0;
            for (int n : lists.vcount) {
                totalTriangles += Math.max(0, n - 2);
                maxCorners = Math.max(maxCorners, n);
            }
            triangles.ensureCapacity((int) Math.min(Integer.MAX_VALUE - 8, triangles.size() + 3 * totalTriangles));
            int[] polygon = new int[maxCorners];
            int base = 0;
            for (int n : lists.vcount) {
                corners.polygon(p, base, n, polygon, where);
                fan(polygon, n);
                base += n * stride;
            }
        }

        private void readPolygonLists(XmlElement primitive, IndexLists lists, int stride, Corners corners)
                throws ColladaException {
            int[] polygon = new int[0];
            for (int r = 0; r < lists.lists.size(); r++) {
                int[] p = lists.lists.get(r);
                int n = p.length / stride;
                if (polygon.length < n) {
                    polygon = new int[n];
                }
                corners.polygon(p, 0, n, polygon, lists.elements.get(r));
                switch (primitive.name()) {
                    case "tristrips":
                        for (int i = 2; i < n; i++) {
                            // Every other triangle of a strip is flipped to keep the winding.
                            boolean odd = (i & 1) != 0;
                            addTriangle(polygon[i - 2], odd ? polygon[i] : polygon[i - 1], odd ? polygon[i - 1] : polygon[i]);
                        }
                        if (n < 3) {
                            degenerate++;
                        }
                        break;
                    default: // polygons and trifans are both fans from the first corner
                        fan(polygon, n);
                        break;
                }
            }
        }

        private int[] concatenated(List<XmlElement> ps) throws ColladaException {
            if (ps.size() == 1) {
                return NumberParser.ints(ctx, ps.get(0), -1);
            }
            IntList all = new IntList(0);
            for (XmlElement p : ps) {
                all.addAll(NumberParser.ints(ctx, p, -1));
            }
            return all.toArray();
        }

        private void fan(int[] polygon, int n) {
            if (n < 3) {
                degenerate++;
            }
            for (int i = 2; i < n; i++) {
                addTriangle(polygon[0], polygon[i - 1], polygon[i]);
            }
        }

        private void addTriangle(int a, int b, int c) {
            triangles.add(a);
            triangles.add(b);
            triangles.add(c);
        }

        /** Resolves the corners of polygons to vertex indices, checking every index. */
        private final class Corners {
            final SlotInput[] layout;
            final int vertexOffset;
            final int stride;

            Corners(SlotInput[] layout, int vertexOffset, int stride) {
                this.layout = layout;
                this.vertexOffset = vertexOffset;
                this.stride = stride;
            }

            /** Vertex indices of the {@code n} corners starting at {@code p[base]} into {@code out}. */
            void polygon(int[] p, int base, int n, int[] out, XmlElement where) throws ColladaException {
                int[] key = scratchKey;
                for (int c = 0; c < n; c++) {
                    int at = base + c * stride;
                    int position = p[at + vertexOffset];
                    if (position < 0 || position >= positionCount) {
                        throw ctx.error(where, "index " + position + " (value " + (at + vertexOffset)
                                + ") is out of range: <vertices> has " + positionCount + " positions");
                    }
                    key[0] = position;
                    if (hasNormals) {
                        putValues(key, 1, layout[SLOT_NORMAL], 3, 0f, p, at, position, where);
                    }
                    if (hasColors) {
                        putValues(key, colorAt, layout[SLOT_COLOR], 4, 1f, p, at, position, where);
                    }
                    for (int t = 0; t < texCoordSets.length; t++) {
                        putValues(key, texCoordAt + 2 * t, layout[FIRST_TEXCOORD_SLOT + t], 2, 0f, p, at, position,
                                where);
                    }
                    out[c] = vertexFor(key);
                }
            }

            /** Writes {@code n} components of the slot's value for this corner into the key, as bits. */
            private void putValues(int[] key, int keyAt, SlotInput in, int n, float missing, int[] p, int at,
                    int position, XmlElement where) throws ColladaException {
                if (in == null) {
                    for (int k = 0; k < n; k++) {
                        key[keyAt + k] = Float.floatToRawIntBits(missing);
                    }
                    return;
                }
                int index = in.offset < 0 ? position : p[at + in.offset];
                if (index < 0 || index >= in.source.count()) {
                    throw ctx.error(where, "index " + index + " (value " + (at + in.offset) + ") is out of range: source \""
                            + in.source.id() + "\" has " + in.source.count() + " elements");
                }
                int width = in.source.width();
                for (int k = 0; k < n; k++) {
                    // "+ 0f" turns -0 into +0 so that the two zeros merge.
                    float value = k < width ? in.source.floatAt(index, k) + 0f : missing;
                    key[keyAt + k] = Float.floatToRawIntBits(value);
                }
            }
        }

        /** The vertex with this key, created when new (open addressing over the key table). */
        private int vertexFor(int[] key) {
            int h = 1;
            for (int k : key) {
                h = 31 * h + k;
            }
            h ^= h >>> 16;
            h *= 0x85EBCA6B;
            h ^= h >>> 13;
            int mask = table.length - 1;
            int slot = h & mask;
            while (true) {
                int v = table[slot] - 1;
                if (v < 0) {
                    break;
                }
                int off = v * keyWidth;
                boolean same = true;
                for (int i = 0; i < keyWidth; i++) {
                    if (keys[off + i] != key[i]) {
                        same = false;
                        break;
                    }
                }
                if (same) {
                    return v;
                }
                slot = (slot + 1) & mask;
            }
            int v = vertexCount++;
            if ((v + 1) * keyWidth > keys.length) {
                keys = Arrays.copyOf(keys, Math.max(keyWidth * 64, keys.length * 2));
            }
            System.arraycopy(key, 0, keys, v * keyWidth, keyWidth);
            table[slot] = v + 1;
            if (2 * vertexCount > table.length) {
                rehash();
            }
            return v;
        }

        private void rehash() {
            int[] bigger = new int[table.length * 2];
            int mask = bigger.length - 1;
            for (int v = 0; v < vertexCount; v++) {
                int h = 1;
                int off = v * keyWidth;
                for (int i = 0; i < keyWidth; i++) {
                    h = 31 * h + keys[off + i];
                }
                h ^= h >>> 16;
                h *= 0x85EBCA6B;
                h ^= h >>> 13;
                int slot = h & mask;
                while (bigger[slot] != 0) {
                    slot = (slot + 1) & mask;
                }
                bigger[slot] = v + 1;
            }
            table = bigger;
        }

        private Mesh assemble() throws ColladaException {
            int v = vertexCount;
            int[] vertexPositions = new int[v];
            float[] normals = hasNormals ? new float[3 * v] : null;
            float[] colors = hasColors ? new float[4 * v] : null;
            List<float[]> texCoords = new ArrayList<>();
            for (int i = 0; i < texCoordSets.length; i++) {
                texCoords.add(new float[2 * v]);
            }
            for (int i = 0; i < v; i++) {
                int off = i * keyWidth;
                vertexPositions[i] = keys[off];
                if (normals != null) {
                    for (int k = 0; k < 3; k++) {
                        normals[3 * i + k] = Float.intBitsToFloat(keys[off + 1 + k]);
                    }
                }
                if (colors != null) {
                    for (int k = 0; k < 4; k++) {
                        colors[4 * i + k] = Float.intBitsToFloat(keys[off + colorAt + k]);
                    }
                }
                for (int t = 0; t < texCoordSets.length; t++) {
                    float[] uv = texCoords.get(t);
                    uv[2 * i] = Float.intBitsToFloat(keys[off + texCoordAt + 2 * t]);
                    uv[2 * i + 1] = Float.intBitsToFloat(keys[off + texCoordAt + 2 * t + 1]);
                }
            }
            float[] positionValues = positionValues();
            return new Mesh(geometry.id(), geometry.attr("name"), positionValues, vertexPositions, normals, texCoords,
                    texCoordSets, colors, triangles.toArray(), parts);
        }
    }
}
