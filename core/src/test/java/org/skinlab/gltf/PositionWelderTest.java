package org.skinlab.gltf;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * {@link PositionWelder} on hand-made vertices: which share a position and what the per-position
 * arrays hold. Influences are given per vertex as compressed rows (start, joints, weights).
 */
class PositionWelderTest {
    private static final float[][] NO_TARGETS = new float[0][];

    @Test
    void seamVerticesWithEqualPositionAndInfluencesWeld() {
        // Vertices 0, 1 and 3 are one point split at a UV or normal seam (the welder sees neither).
        float[] xyz = {1, 2, 3, 1, 2, 3, 4, 5, 6, 1, 2, 3};
        int[] start = {0, 1, 2, 3, 4};
        int[] joints = {0, 0, 1, 0};
        float[] weights = {1, 1, 1, 1};
        PositionWelder weld = new PositionWelder(xyz, start, joints, weights, NO_TARGETS);
        assertArrayEquals(new int[] {0, 0, 1, 0}, weld.positionOfVertex);
        assertArrayEquals(new int[] {0, 2}, weld.firstVertex);
        assertArrayEquals(new float[] {1, 2, 3, 4, 5, 6}, weld.perPosition(xyz, 3));
    }

    @Test
    void equalPositionsWithOtherInfluencesStayApart() {
        // Five vertices at one point: the reference; another weight; another joint; the same
        // influences in another order; one influence more. Only the last vertex repeats the first.
        float[] xyz = new float[3 * 6];
        int[] start = {0, 2, 4, 6, 8, 11, 13};
        int[] joints = {0, 1, 0, 1, 0, 2, 1, 0, 0, 1, 2, 0, 1};
        float[] weights = {0.5f, 0.5f, 0.25f, 0.75f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.25f, 0.25f, 0.5f, 0.5f};
        PositionWelder weld = new PositionWelder(xyz, start, joints, weights, NO_TARGETS);
        assertArrayEquals(new int[] {0, 1, 2, 3, 4, 0}, weld.positionOfVertex);
        int[] positionStart = weld.influenceStart();
        assertArrayEquals(new int[] {0, 2, 4, 6, 8, 11}, positionStart);
        assertArrayEquals(new int[] {0, 1, 0, 1, 0, 2, 1, 0, 0, 1, 2}, weld.influenceJoints(positionStart));
        assertArrayEquals(new float[] {0.5f, 0.5f, 0.25f, 0.75f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.25f, 0.25f},
                weld.influenceWeights(positionStart));
    }

    @Test
    void equalPositionsWithOtherMorphOffsetsStayApart() {
        float[] xyz = new float[3 * 3];
        int[] start = new int[4];
        float[][] targets = {{0, 0, 0, 0, 0, 0, 0, 1, 0}, {0, 0, 1, 0, 0, 1, 0, 0, 1}};
        PositionWelder weld = new PositionWelder(xyz, start, new int[0], new float[0], targets);
        assertArrayEquals(new int[] {0, 0, 1}, weld.positionOfVertex);
        assertArrayEquals(new float[] {0, 0, 0, 0, 1, 0}, weld.perPosition(targets[0], 3));
    }

    @Test
    void positionsDifferingOnlyInTheSignOfZeroStayApart() {
        // Bitwise equality: -0 and +0 deform alike, but keeping them apart costs nothing and the
        // rule stays simple.
        float[] xyz = {0, 0, 0, -0f, 0, 0};
        PositionWelder weld = new PositionWelder(xyz, new int[3], new int[0], new float[0], NO_TARGETS);
        assertArrayEquals(new int[] {0, 1}, weld.positionOfVertex);
    }

    @Test
    void manyPointsEachSplitFourTimesWeldInFirstUseOrder() {
        // 5,000 points, each written as 4 vertices spread through the list (vertex v is point
        // (v * 7919) % 5000): the table grows several times while vertices are placed.
        int points = 5000;
        int n = 4 * points;
        float[] xyz = new float[3 * n];
        int[] start = new int[n + 1];
        int[] joints = new int[n];
        float[] weights = new float[n];
        for (int v = 0; v < n; v++) {
            int point = (int) ((long) v * 7919 % points);
            xyz[3 * v] = point % 71;
            xyz[3 * v + 1] = point / 71;
            xyz[3 * v + 2] = 0.5f;
            start[v + 1] = v + 1;
            joints[v] = point % 3;
            weights[v] = 1;
        }
        PositionWelder weld = new PositionWelder(xyz, start, joints, weights, NO_TARGETS);
        assertEquals(points, weld.firstVertex.length);
        for (int v = 0; v < n; v++) {
            int p = weld.positionOfVertex[v];
            int first = weld.firstVertex[p];
            assertEquals((long) first * 7919 % points, (long) v * 7919 % points, "vertex " + v);
            assertEquals(p, weld.positionOfVertex[first]);
        }
        for (int p = 1; p < points; p++) {
            assertTrue(weld.firstVertex[p - 1] < weld.firstVertex[p], "positions in first-use order");
        }
    }
}
