package org.skinlab.skinning;

import java.util.Arrays;

import org.skinlab.model.Mesh;

/**
 * Where a mesh's positions go among a geometry's points: first the render vertices in vertex
 * order, each carrying its position, then every position no vertex carries, so that every entry
 * of the {@code <vertices>} POSITION source is a point somewhere.
 */
final class PointLayout {
    /** Render vertices: points {@code [0, vertexCount)}. */
    final int vertexCount;
    /** Per POSITION entry, the point that carries it (the first vertex of each position). */
    final int[] pointOfPosition;
    /** Per point, its POSITION entry. */
    final int[] positionOfPoint;

    private PointLayout(int vertexCount, int[] pointOfPosition, int[] positionOfPoint) {
        this.vertexCount = vertexCount;
        this.pointOfPosition = pointOfPosition;
        this.positionOfPoint = positionOfPoint;
    }

    static PointLayout of(Mesh mesh) {
        int vertices = mesh.vertexCount();
        int[] pointOfPosition = new int[mesh.positionCount()];
        Arrays.fill(pointOfPosition, -1);
        for (int v = vertices - 1; v >= 0; v--) {
            pointOfPosition[mesh.vertexPosition(v)] = v; // the first vertex of each position wins
        }
        int orphans = 0;
        for (int p = 0; p < pointOfPosition.length; p++) {
            if (pointOfPosition[p] < 0) {
                pointOfPosition[p] = vertices + orphans++;
            }
        }
        int[] positionOfPoint = new int[vertices + orphans];
        for (int v = 0; v < vertices; v++) {
            positionOfPoint[v] = mesh.vertexPosition(v);
        }
        for (int p = 0; p < pointOfPosition.length; p++) {
            if (pointOfPosition[p] >= vertices) {
                positionOfPoint[pointOfPosition[p]] = p;
            }
        }
        return new PointLayout(vertices, pointOfPosition, positionOfPoint);
    }

    int pointCount() {
        return positionOfPoint.length;
    }

    /** Whether some position is carried by more than one point. */
    boolean sharesPositions() {
        return positionOfPoint.length != pointOfPosition.length;
    }

    /** The mesh's positions per point, 3 floats each. */
    float[] positions(Mesh mesh) {
        float[] meshPositions = mesh.positions();
        int points = pointCount();
        float[] positions = new float[3 * points];
        for (int i = 0; i < points; i++) {
            System.arraycopy(meshPositions, 3 * positionOfPoint[i], positions, 3 * i, 3);
        }
        return positions;
    }

    /** The mesh's normals per point, 3 floats each: zero for the points past the vertices, and where the mesh has none. */
    float[] normals(Mesh mesh) {
        float[] normals = new float[3 * pointCount()];
        if (mesh.hasNormals()) {
            System.arraycopy(mesh.normals(), 0, normals, 0, 3 * vertexCount);
        }
        return normals;
    }
}
