package org.skinlab.internal.metrics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.skinlab.collada.ColladaImporter;
import org.skinlab.model.Mesh;
import org.skinlab.model.MeshInstance;
import org.skinlab.testing.TestPaths;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinnedModel;

class ArtifactMetricsTest {
    // A tetrahedron (0,0,0), (1,0,0), (0,1,0), (0,0,1), faces wound counter-clockwise seen from
    // outside: volume 1/6 by the formula for a corner of the unit cube.
    private static final float[] CORNERS = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    private static final int[] FACES = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};

    @Test
    void signedVolumeOfATetrahedronIsASixthAndFlipsWithTheWinding() {
        assertEquals(1.0 / 6, ArtifactMetrics.signedVolume(CORNERS, FACES), 1e-12);
        int[] inward = FACES.clone();
        for (int t = 0; t < inward.length; t += 3) {
            int swap = inward[t + 1];
            inward[t + 1] = inward[t + 2];
            inward[t + 2] = swap;
        }
        assertEquals(-1.0 / 6, ArtifactMetrics.signedVolume(CORNERS, inward), 1e-12);
    }

    @Test
    void aTetrahedronIsClosedAndLosesThatWithAFace() {
        assertTrue(ArtifactMetrics.isClosed(tetrahedron(FACES, false)));
        assertFalse(ArtifactMetrics.isClosed(tetrahedron(java.util.Arrays.copyOf(FACES, 9), false)));
        // A face twice: three edges are shared by three triangles.
        int[] doubled = java.util.Arrays.copyOf(FACES, 15);
        System.arraycopy(FACES, 0, doubled, 12, 3);
        assertFalse(ArtifactMetrics.isClosed(tetrahedron(doubled, false)));
        // A face wound the other way: each of its edges is walked twice in one direction.
        assertFalse(ArtifactMetrics.isClosed(tetrahedron(new int[] {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 3, 2}, false)));
        // A triangle with two corners on one position encloses nothing (its terms of the volume
        // are 0, its two edges cancel): left out, the tetrahedron stays closed.
        assertTrue(ArtifactMetrics.isClosed(tetrahedron(new int[] {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3, 0, 0, 1},
                false)));
    }

    @Test
    void positionsAtTheSamePointAreJoinedSoASurfaceCutByMaterialStaysClosed() {
        // Every face its own three POSITION entries (a file that repeats a point per material or
        // per face): no position edge is shared, but every edge between points is.
        float[] corners = new float[3 * FACES.length];
        int[] vertexPositions = new int[FACES.length];
        for (int c = 0; c < FACES.length; c++) {
            System.arraycopy(CORNERS, 3 * FACES[c], corners, 3 * c, 3);
            vertexPositions[c] = c;
        }
        Mesh mesh = new Mesh("tetrahedron", "tetrahedron", corners, vertexPositions, null, List.of(), null,
                vertexPositions, List.of());
        assertTrue(ArtifactMetrics.isClosed(SkinnedGeometry.of(new MeshInstance(0, mesh, null, new int[0], new int[0],
                List.of()))));
    }

    @Test
    void edgesAreCountedBetweenPositionsSoSplitVerticesKeepTheMeshClosed() {
        // Every face its own three vertices (as hard edges or UV seams make them): no vertex
        // edge is shared, but every position edge is, twice.
        assertTrue(ArtifactMetrics.isClosed(tetrahedron(FACES, true)));
    }

    @Test
    void arraysWithoutAMeshAreNotClosed() {
        SkinnedGeometry arrays = SkinnedGeometry.fromArrays(CORNERS, new float[CORNERS.length], 1, new int[4],
                new float[] {1, 1, 1, 1}, new float[] {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1});
        assertFalse(ArtifactMetrics.isClosed(arrays));
    }

    @Test
    void theCylindersAreClosed() throws Exception {
        for (String asset : List.of("cylinder-twist-low.dae", "cylinder-twist-high.dae", "cylinder-bend.dae")) {
            SkinnedModel model = SkinnedModel.of(ColladaImporter.read(TestPaths.asset("cylinders/" + asset)));
            assertTrue(ArtifactMetrics.isClosed(model.geometries().get(0)), asset);
        }
    }

    /** The tetrahedron as a static mesh, with shared vertices or one vertex per face corner. */
    private static SkinnedGeometry tetrahedron(int[] faces, boolean splitVertices) {
        int[] vertexPositions;
        int[] triangles;
        if (splitVertices) {
            vertexPositions = faces.clone();
            triangles = new int[faces.length];
            for (int v = 0; v < triangles.length; v++) {
                triangles[v] = v;
            }
        } else {
            vertexPositions = new int[] {0, 1, 2, 3};
            triangles = faces;
        }
        Mesh mesh = new Mesh("tetrahedron", "tetrahedron", CORNERS, vertexPositions, null, List.of(), null,
                triangles, List.of());
        return SkinnedGeometry.of(new MeshInstance(0, mesh, null, new int[0], new int[0], List.of()));
    }
}
