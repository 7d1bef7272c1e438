package org.skinlab.collada;

import java.util.ArrayList;
import java.util.List;

/**
 * The vertices of a mesh being built: each polygon corner's position index and attribute values
 * (normal, colour, texture coordinates, each present only when the mesh has them) make a key,
 * and corners with equal keys are one vertex ({@link VertexTable}). Every index is checked
 * against its source here.
 */
final class MeshVertices {
    /** Attribute slots of a primitive's layout: normal, colour, then one per texture coordinate set. */
    static final int SLOT_NORMAL = 0;
    static final int SLOT_COLOR = 1;
    static final int FIRST_TEXCOORD_SLOT = 2;

    /** Where one attribute slot of a primitive's vertices comes from. */
    static final class Slot {
        final Source source;
        final int offset; // offset into <p>, or -1: indexed like the position (declared in <vertices>)

        Slot(Source source, int offset) {
            this.source = source;
            this.offset = offset;
        }
    }

    private final ImportContext ctx;
    private final int positionCount;
    private final boolean hasNormals;
    private final boolean hasColors;
    private final int texCoordSets;
    // Key layout: position index, normal (3), colour (4), texture coordinates (2 per set).
    private final int colorAt;
    private final int texCoordAt;
    private final int[] key;
    private final VertexTable table;

    MeshVertices(ImportContext ctx, int positionCount, boolean hasNormals, boolean hasColors, int texCoordSets) {
        this.ctx = ctx;
        this.positionCount = positionCount;
        this.hasNormals = hasNormals;
        this.hasColors = hasColors;
        this.texCoordSets = texCoordSets;
        this.colorAt = 1 + (hasNormals ? 3 : 0);
        this.texCoordAt = colorAt + (hasColors ? 4 : 0);
        this.key = new int[texCoordAt + 2 * texCoordSets];
        this.table = new VertexTable(key.length);
    }

    /** The corners of a primitive with this layout. */
    Corners corners(Slot[] layout, int vertexOffset, int stride) {
        return new Corners(layout, vertexOffset, stride);
    }

    /** Resolves the corners of polygons to vertex indices, checking every index. */
    final class Corners {
        final Slot[] layout;
        final int vertexOffset;
        final int stride;

        Corners(Slot[] layout, int vertexOffset, int stride) {
            this.layout = layout;
            this.vertexOffset = vertexOffset;
            this.stride = stride;
        }

        /** Vertex indices of the {@code n} corners starting at {@code p[base]} into {@code out}. */
        void polygon(int[] p, int base, int n, int[] out, XmlElement where) throws ColladaException {
            int[] key = MeshVertices.this.key;
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
                for (int t = 0; t < texCoordSets; t++) {
                    putValues(key, texCoordAt + 2 * t, layout[FIRST_TEXCOORD_SLOT + t], 2, 0f, p, at, position,
                            where);
                }
                out[c] = table.vertexFor(key);
            }
        }

        /** Writes {@code n} components of the slot's value for this corner into the key, as bits. */
        private void putValues(int[] key, int keyAt, Slot in, int n, float missing, int[] p, int at,
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

    /** Per vertex, its position index. */
    int[] vertexPositions() {
        int[] result = new int[table.count()];
        for (int v = 0; v < result.length; v++) {
            result[v] = table.key(v, 0);
        }
        return result;
    }

    /** 3 floats per vertex, or null when the mesh has no normals. */
    float[] normals() {
        return hasNormals ? values(1, 3) : null;
    }

    /** 4 floats (RGBA) per vertex, or null when the mesh has no colours. */
    float[] colors() {
        return hasColors ? values(colorAt, 4) : null;
    }

    /** 2 floats per vertex for each texture coordinate set, in set order. */
    List<float[]> texCoords() {
        List<float[]> sets = new ArrayList<>(texCoordSets);
        for (int t = 0; t < texCoordSets; t++) {
            sets.add(values(texCoordAt + 2 * t, 2));
        }
        return sets;
    }

    /** Key ints [at, at + n) of every vertex, as floats. */
    private float[] values(int at, int n) {
        float[] result = new float[n * table.count()];
        for (int v = 0, o = 0; v < table.count(); v++) {
            for (int k = 0; k < n; k++) {
                result[o++] = Float.intBitsToFloat(table.key(v, at + k));
            }
        }
        return result;
    }
}
