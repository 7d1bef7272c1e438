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
    private static final int SLOT_NORMAL = MeshVertices.SLOT_NORMAL;
    private static final int SLOT_COLOR = MeshVertices.SLOT_COLOR;
    private static final int FIRST_TEXCOORD_SLOT = MeshVertices.FIRST_TEXCOORD_SLOT;

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

    private final class Builder {
        private final XmlElement geometry;
        private final XmlElement meshElement;
        private Source positions;
        private int positionCount;
        private XmlElement positionInput;
        /** Attribute inputs declared in <vertices> (indexed with the position), per slot. */
        private MeshVertices.Slot[] vertexSlots;
        private final List<Integer> vertexTexCoordSets = new ArrayList<>();
        private final List<MeshVertices.Slot> vertexTexCoordSources = new ArrayList<>();
        private final Map<XmlElement, Integer> texCoordSetOfInput = new IdentityHashMap<>();
        private int[] texCoordSets; // sorted set numbers; slot FIRST_TEXCOORD_SLOT + i is set texCoordSets[i]
        private int slotCount;

        private boolean hasNormals;
        private MeshVertices vertices;
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
            vertices = new MeshVertices(ctx, positionCount, normals, colors, texCoordSets.length);
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
            vertexSlots = new MeshVertices.Slot[FIRST_TEXCOORD_SLOT];
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
                        vertexSlots[SLOT_NORMAL] = new MeshVertices.Slot(attributeSource(input, 3, 3), -1);
                        break;
                    case "COLOR":
                        vertexSlots[SLOT_COLOR] = new MeshVertices.Slot(attributeSource(input, 3, 4), -1);
                        break;
                    case "TEXCOORD":
                        if (texCoordSetOfInput.containsKey(input)) {
                            vertexTexCoordSets.add(texCoordSetOfInput.get(input));
                            vertexTexCoordSources.add(new MeshVertices.Slot(attributeSource(input, 2, 4), -1));
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
            MeshVertices.Slot[] layout = vertexSlots.clone();
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
                        layout[slot] = new MeshVertices.Slot(attributeSource(input, 3, 3), offset);
                        break;
                    case "COLOR":
                        if (layout[SLOT_COLOR] == null || layout[SLOT_COLOR].offset < 0) {
                            slot = SLOT_COLOR;
                            layout[slot] = new MeshVertices.Slot(attributeSource(input, 3, 4), offset);
                        }
                        break;
                    case "TEXCOORD": {
                        Integer set = texCoordSetOfInput.get(input);
                        if (set != null) {
                            slot = FIRST_TEXCOORD_SLOT + Arrays.binarySearch(texCoordSets, set);
                            layout[slot] = new MeshVertices.Slot(attributeSource(input, 2, 4), offset);
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
            PrimitiveIndices lists = PrimitiveIndices.read(ctx, primitive, count, stride);
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
            MeshVertices.Corners corners = vertices.corners(layout, vertexOffset, stride);
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

        /**
         * Drops, with a warning, the optional inputs (normals, colours, texture coordinates) of this
         * primitive that an index points past: the geometry stays usable without them, while
         * positions out of range are refused later. One pass over the indices finds each offset's
         * range.
         */
        private void dropInputsOutOfRange(PrimitiveIndices lists, int stride, MeshVertices.Slot[] layout, XmlElement[] slotInputs) {
            int[][] ranges = lists.ranges(stride);
            int[] min = ranges[0];
            int[] max = ranges[1];
            for (int slot = 0; slot < layout.length; slot++) {
                MeshVertices.Slot in = layout[slot];
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

        private void readTriangles(PrimitiveIndices lists, int stride, MeshVertices.Corners corners) throws ColladaException {
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

        private void readPolylist(PrimitiveIndices lists, int stride, MeshVertices.Corners corners) throws ColladaException {
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

        private void readPolygonLists(XmlElement primitive, PrimitiveIndices lists, int stride, MeshVertices.Corners corners)
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

        private Mesh assemble() throws ColladaException {
            return new Mesh(geometry.id(), geometry.attr("name"), positionValues(), vertices.vertexPositions(),
                    vertices.normals(), vertices.texCoords(), texCoordSets, vertices.colors(), triangles.toArray(),
                    parts);
        }
    }
}
