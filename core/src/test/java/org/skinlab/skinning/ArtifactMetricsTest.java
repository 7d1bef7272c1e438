package org.skinlab.skinning;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

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
    void relativeVolumeNeedsAMesh() {
        SkinnedGeometry arrays = SkinnedGeometry.fromArrays(CORNERS, new float[CORNERS.length], 1, new int[4],
                new float[] {1, 1, 1, 1}, new float[] {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1});
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> ArtifactMetrics.relativeVolume(arrays, CORNERS));
        assertTrue(e.getMessage().startsWith("relative volume needs a mesh's triangles"), e.getMessage());
    }
}
