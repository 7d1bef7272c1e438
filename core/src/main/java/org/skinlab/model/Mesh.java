package org.skinlab.model;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

/**
 * One {@code <geometry>}'s mesh, triangulated and ready to draw, with the link back to the
 * positions that skin weights refer to.
 *
 * <p>Two index spaces:
 * <ul>
 * <li><b>positions</b>: the entries of the geometry's {@code <vertices>} POSITION source, in file
 *     order. Skin influences and the command line's pose output use this space.</li>
 * <li><b>vertices</b>: the distinct combinations of position, normal, texture coordinate and
 *     colour indices the primitives use (a position on a UV seam or hard edge becomes several
 *     vertices). Triangles index vertices; {@link #vertexPosition(int)} maps back, and
 *     {@link #verticesOfPosition(int)} lists the vertices that share a position (the thesis'
 *     "vertex groups": deform a position once, copy it to all its vertices).</li>
 * </ul>
 * Polygons are fan-triangulated from their first corner. Arrays are copied in and out; the
 * accessors that return arrays return copies.
 */
public final class Mesh {
    private final String id;
    private final String name;
    private final float[] positions;
    private final int[] vertexPositions;
    private final float[] normals;
    private final List<float[]> texCoordSets;
    private final int[] texCoordSetNumbers;
    private final float[] colors;
    private final int[] triangles;
    private final List<MeshPart> parts;
    private final int[] positionVertexStart;
    private final int[] positionVertices;

    /**
     * A mesh whose texture coordinate sets the file numbers 0, 1, 2, ... in list order. Arrays and
     * lists are copied.
     *
     * @param id              the geometry's id (for glTF, the mesh's JSON path, e.g. {@code /meshes/0})
     * @param name            the geometry's name, or null
     * @param positions       3 floats per position
     * @param vertexPositions per vertex, its position index
     * @param normals         3 floats per vertex, or null when the geometry has none
     * @param texCoordSets    per texture coordinate set (in set order), 2 floats per vertex
     * @param colors          4 floats (RGBA) per vertex, or null
     * @param triangles       3 vertex indices per triangle, counter-clockwise as in the file
     * @param parts           the triangle runs, one per primitive element, in document order
     * @throws IllegalArgumentException when an array's length does not fit its layout, or a triangle's vertex
     *         index or a vertex's position index is out of range
     */
    public Mesh(String id, String name, float[] positions, int[] vertexPositions, float[] normals,
            List<float[]> texCoordSets, float[] colors, int[] triangles, List<MeshPart> parts) {
        this(id, name, positions, vertexPositions, normals, texCoordSets, null, colors, triangles, parts);
    }

    /**
     * As above, with the file's {@code set} number of each texture coordinate set (ascending;
     * null: 0, 1, 2, ...), which {@code <bind_vertex_input input_set>} refers to.
     *
     * @param id                 the geometry's id (for glTF, the mesh's JSON path, e.g. {@code /meshes/0})
     * @param name               the geometry's name, or null
     * @param positions          3 floats (x, y, z) per position, in the document's own frame and units
     * @param vertexPositions    per vertex, its position index
     * @param normals            3 floats per vertex, or null when the geometry has none
     * @param texCoordSets       per texture coordinate set (in set order), 2 floats per vertex; empty for none
     * @param texCoordSetNumbers per texture coordinate set, the file's {@code set} number, strictly ascending;
     *                           or null for 0, 1, 2, ...
     * @param colors             4 floats (RGBA) per vertex, or null
     * @param triangles          3 vertex indices per triangle, counter-clockwise as in the file
     * @param parts              the triangle runs, one per primitive element, in document order
     * @throws IllegalArgumentException when an array's length does not fit its layout, a triangle's vertex
     *         index or a vertex's position index is out of range, or the set numbers are not one per set
     *         in ascending order
     */
    public Mesh(String id, String name, float[] positions, int[] vertexPositions, float[] normals,
            List<float[]> texCoordSets, int[] texCoordSetNumbers, float[] colors, int[] triangles,
            List<MeshPart> parts) {
        int vertexCount = vertexPositions.length;
        int positionCount = positions.length / 3;
        if (positions.length % 3 != 0) {
            throw new IllegalArgumentException("positions must hold 3 floats each");
        }
        if (normals != null && normals.length != 3 * vertexCount) {
            throw new IllegalArgumentException("normals must hold 3 floats per vertex");
        }
        if (colors != null && colors.length != 4 * vertexCount) {
            throw new IllegalArgumentException("colors must hold 4 floats per vertex");
        }
        for (float[] t : texCoordSets) {
            if (t.length != 2 * vertexCount) {
                throw new IllegalArgumentException("texture coordinates must hold 2 floats per vertex");
            }
        }
        if (triangles.length % 3 != 0) {
            throw new IllegalArgumentException("triangles must hold 3 indices each");
        }
        for (int t : triangles) {
            if (t < 0 || t >= vertexCount) {
                throw new IllegalArgumentException("triangle index " + t + " out of range");
            }
        }
        this.id = id;
        this.name = name;
        this.positions = positions.clone();
        this.vertexPositions = vertexPositions.clone();
        this.normals = normals == null ? null : normals.clone();
        List<float[]> sets = new ArrayList<>(texCoordSets.size());
        for (float[] t : texCoordSets) {
            sets.add(t.clone());
        }
        this.texCoordSets = Collections.unmodifiableList(sets);
        if (texCoordSetNumbers == null) {
            texCoordSetNumbers = new int[sets.size()];
            for (int i = 0; i < texCoordSetNumbers.length; i++) {
                texCoordSetNumbers[i] = i;
            }
        } else if (texCoordSetNumbers.length != sets.size()) {
            throw new IllegalArgumentException("need one set number per texture coordinate set");
        }
        for (int i = 1; i < texCoordSetNumbers.length; i++) {
            if (texCoordSetNumbers[i] <= texCoordSetNumbers[i - 1]) {
                throw new IllegalArgumentException("texture coordinate set numbers must ascend");
            }
        }
        this.texCoordSetNumbers = texCoordSetNumbers.clone();
        this.colors = colors == null ? null : colors.clone();
        this.triangles = triangles.clone();
        this.parts = List.copyOf(parts);

        // Vertices grouped by position (CSR), vertices in increasing order within a group.
        positionVertexStart = new int[positionCount + 1];
        for (int p : this.vertexPositions) {
            if (p < 0 || p >= positionCount) {
                throw new IllegalArgumentException("vertex position index " + p + " out of range");
            }
            positionVertexStart[p + 1]++;
        }
        for (int p = 0; p < positionCount; p++) {
            positionVertexStart[p + 1] += positionVertexStart[p];
        }
        positionVertices = new int[vertexCount];
        int[] fill = new int[positionCount];
        for (int v = 0; v < vertexCount; v++) {
            int p = this.vertexPositions[v];
            positionVertices[positionVertexStart[p] + fill[p]++] = v;
        }
    }

    /**
     * The geometry's id.
     *
     * @return the id (for glTF, the mesh's JSON path)
     */
    public String id() {
        return id;
    }

    /**
     * The geometry's name, or null.
     *
     * @return the name, or null when the file gives none
     */
    public String name() {
        return name;
    }

    /**
     * Number of positions: the entries of the POSITION source, the index space of skin influences.
     *
     * @return the position count
     */
    public int positionCount() {
        return positions.length / 3;
    }

    /**
     * Number of vertices (see the class comment): the index space of the triangles, normals, colours
     * and texture coordinates.
     *
     * @return the vertex count
     */
    public int vertexCount() {
        return vertexPositions.length;
    }

    /**
     * Number of triangles, after fan triangulation of the file's polygons.
     *
     * @return the triangle count
     */
    public int triangleCount() {
        return triangles.length / 3;
    }

    /**
     * A copy of the positions, 3 floats each, in the document's own frame and units.
     *
     * @return a new array of 3 * {@link #positionCount()} floats: x, y, z of each position
     */
    public float[] positions() {
        return positions.clone();
    }

    /**
     * Component {@code c} (0..2) of position {@code p}.
     *
     * @param p the position index, 0 to {@link #positionCount()} - 1
     * @param c the component: 0 for x, 1 for y, 2 for z
     * @return the coordinate, in the document's own frame and units
     */
    public float position(int p, int c) {
        return positions[3 * p + c];
    }

    /**
     * The position index of vertex {@code v}.
     *
     * @param v the vertex index, 0 to {@link #vertexCount()} - 1
     * @return the index of the position the vertex sits at
     */
    public int vertexPosition(int v) {
        return vertexPositions[v];
    }

    /**
     * A copy of the vertex-to-position map.
     *
     * @return a new array with, per vertex, its position index
     */
    public int[] vertexPositions() {
        return vertexPositions.clone();
    }

    /**
     * The vertices that share position {@code p} (a copy, ascending).
     *
     * @param p the position index, 0 to {@link #positionCount()} - 1
     * @return a new array of vertex indices in ascending order; empty when no vertex uses the position
     */
    public int[] verticesOfPosition(int p) {
        int from = positionVertexStart[p];
        int to = positionVertexStart[p + 1];
        int[] result = new int[to - from];
        System.arraycopy(positionVertices, from, result, 0, result.length);
        return result;
    }

    /**
     * Whether the mesh has normals.
     *
     * @return true when {@link #normals()} is not null
     */
    public boolean hasNormals() {
        return normals != null;
    }

    /**
     * A copy of the normals, 3 floats per vertex as written (not renormalised), or null.
     *
     * @return a new array of 3 * {@link #vertexCount()} floats, or null when the mesh has no normals
     */
    public float[] normals() {
        return normals == null ? null : normals.clone();
    }

    /**
     * Number of texture coordinate sets.
     *
     * @return the set count, 0 when the mesh has no texture coordinates
     */
    public int texCoordSetCount() {
        return texCoordSets.size();
    }

    /**
     * The file's {@code set} number of texture coordinate set {@code index}.
     *
     * @param index the set's index, 0 to {@link #texCoordSetCount()} - 1, as {@link #texCoords(int)} takes it
     * @return the set's number in the file; the numbers ascend with the index
     */
    public int texCoordSetNumber(int index) {
        return texCoordSetNumbers[index];
    }

    /**
     * The index of the texture coordinate set the file numbers {@code setNumber}, or -1.
     *
     * @param setNumber a set number as the file writes it, e.g. in {@code <bind_vertex_input input_set>}
     * @return the set's index for {@link #texCoords(int)}, or -1 when the mesh has no set of that number
     */
    public int texCoordSetIndex(int setNumber) {
        int i = java.util.Arrays.binarySearch(texCoordSetNumbers, setNumber);
        return i >= 0 ? i : -1;
    }

    /**
     * A copy of texture coordinate set {@code set} (in set order), 2 floats per vertex.
     *
     * @param set the set's index, 0 to {@link #texCoordSetCount()} - 1 (not the file's set number: see
     *            {@link #texCoordSetIndex(int)})
     * @return a new array of 2 * {@link #vertexCount()} floats
     */
    public float[] texCoords(int set) {
        return texCoordSets.get(set).clone();
    }

    /**
     * Whether the mesh has vertex colours.
     *
     * @return true when {@link #colors()} is not null
     */
    public boolean hasColors() {
        return colors != null;
    }

    /**
     * A copy of the vertex colours, RGBA per vertex (alpha 1 when the file has RGB), or null.
     *
     * @return a new array of 4 * {@link #vertexCount()} floats, or null when the mesh has no colours
     */
    public float[] colors() {
        return colors == null ? null : colors.clone();
    }

    /**
     * A copy of the triangles, 3 vertex indices each.
     *
     * @return a new array of 3 * {@link #triangleCount()} vertex indices, counter-clockwise as in the file
     */
    public int[] triangles() {
        return triangles.clone();
    }

    /**
     * Vertex {@code corner} (0..2) of triangle {@code t}.
     *
     * @param t      the triangle index, 0 to {@link #triangleCount()} - 1
     * @param corner the corner, 0, 1 or 2 in winding order
     * @return the vertex index
     */
    public int triangleVertex(int t, int corner) {
        return triangles[3 * t + corner];
    }

    /**
     * The triangle runs, one per primitive element, in document order.
     *
     * @return an unmodifiable list of the parts
     */
    public List<MeshPart> parts() {
        return parts;
    }

    /**
     * This mesh with other positions (same count) under another id and name: the topology,
     * normals, colours and texture coordinates are shared as they are. A morph's result is made so.
     *
     * @param newId        the new mesh's id
     * @param newName      the new mesh's name, or null
     * @param newPositions 3 floats per position, as many positions as this mesh has (copied)
     * @return a new mesh; this one is unchanged
     * @throws IllegalArgumentException when {@code newPositions} has another length than {@link #positions()}
     */
    public Mesh withPositions(String newId, String newName, float[] newPositions) {
        return withPositionsAndNormals(newId, newName, newPositions, normals);
    }

    /**
     * As {@link #withPositions}, with other normals too (3 floats per vertex, or null for none): a
     * morph target whose normals are offsets, or a morph's result with morphed normals.
     *
     * @param newId        the new mesh's id
     * @param newName      the new mesh's name, or null
     * @param newPositions 3 floats per position, as many positions as this mesh has (copied)
     * @param newNormals   3 floats per vertex (copied), or null for a mesh without normals
     * @return a new mesh; this one is unchanged
     * @throws IllegalArgumentException when {@code newPositions} has another length than {@link #positions()},
     *         or {@code newNormals} does not hold 3 floats per vertex
     */
    public Mesh withPositionsAndNormals(String newId, String newName, float[] newPositions, float[] newNormals) {
        if (newPositions.length != positions.length) {
            throw new IllegalArgumentException("need " + positions.length / 3 + " positions");
        }
        return new Mesh(newId, newName, newPositions, vertexPositions, newNormals, texCoordSets, texCoordSetNumbers,
                colors, triangles, parts);
    }

    @Override
    public String toString() {
        return "Mesh[" + id + ", " + positionCount() + " positions, " + vertexCount() + " vertices, "
                + triangleCount() + " triangles]";
    }
}
