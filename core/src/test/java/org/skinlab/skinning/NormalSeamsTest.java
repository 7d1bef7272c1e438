package org.skinlab.skinning;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** The seam measure on a hand-made fold whose jumps follow from the cross products by hand. */
class NormalSeamsTest {
    /** A unit square in z = 0 as triangles (0 1 2) and (0 2 3); corner 3 raised to height h. */
    private static float[] square(float h) {
        return new float[] {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, h};
    }

    private static final int[] TRIANGLES = {0, 1, 2, 0, 2, 3};
    private static final int[] IDENTITY = {0, 1, 2, 3};

    @Test
    void flatSurfaceHasNoJump() {
        NormalSeams seams = NormalSeams.of(TRIANGLES, IDENTITY);
        assertEquals(5, seams.edgeCount());
        assertEquals(0, seams.largest(square(0)).angle(), 1e-12);
    }

    @Test
    void foldJumpsBetweenTheUnsharedCornerAndItsNeighbours() {
        NormalSeams seams = NormalSeams.of(TRIANGLES, IDENTITY);
        // Cross products: (0 0 1) for the flat triangle, (h -h 1) for the raised one; corners 0 and 2
        // carry their sum (h -h 2), corner 1 (0 0 1), corner 3 (h -h 1). With h = 1 the largest
        // jump is between corner 1 and corners 0, 2: atan2(sqrt(2), 2); 3 to 0: acos(4 / sqrt(18)).
        NormalSeams.Jump jump = seams.largest(square(1));
        assertEquals(Math.atan2(Math.sqrt(2), 2), jump.angle(), 1e-12);
        assertTrue(jump.positionA() == 1 || jump.positionB() == 1, "an edge of corner 1: " + jump);
        // Against the flat square nothing but the fold is added; against itself nothing.
        assertEquals(Math.atan2(Math.sqrt(2), 2), seams.largestAdded(square(1), square(0)).angle(), 1e-12);
        assertEquals(0, seams.largestAdded(square(1), square(1)).angle(), 1e-12);
    }

    @Test
    void renderVerticesOfOnePositionCountOnce() {
        // Corner 2 written twice (points 2 and 4), the second triangle using point 4: positions
        // map both to position 2, so the surface is the same and so is the jump.
        float[] points = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 1, 1, 1, 0};
        NormalSeams seams = NormalSeams.of(TRIANGLES, IDENTITY);
        NormalSeams split = NormalSeams.of(TRIANGLES, new int[] {0, 1, 4, 3});
        assertEquals(seams.largest(square(1)).angle(), split.largest(points).angle(), 1e-12);
    }
}
