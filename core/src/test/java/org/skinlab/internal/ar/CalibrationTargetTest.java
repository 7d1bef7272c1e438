package org.skinlab.internal.ar;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.skinlab.internal.synthetic.PlacedMarker;
import org.skinlab.internal.synthetic.PlacedTarget;
import org.skinlab.internal.synthetic.SyntheticCamera;

/** The target's geometry (sizes, squares, points), its names, and the inputs it refuses. */
class CalibrationTargetTest {
    @Test
    void aChessboardAlternatesFromABlackTopLeftSquare() {
        CalibrationTarget t = CalibrationTarget.chessboard(7, 10, 0.02);
        assertEquals(0.20, t.width(), 1e-12);
        assertEquals(0.14, t.height(), 1e-12);
        assertEquals(54, t.points());
        assertTrue(t.isBlackAt(0.001, 0.001));
        assertFalse(t.isBlackAt(0.021, 0.001));
        assertTrue(t.isBlackAt(0.021, 0.021));
        assertTrue(t.isBlackAt(0.001, 0.139), "the bottom-left square, row 6 + column 0 even: black");
        assertFalse(t.isBlackAt(0.199, 0.139), "the bottom-right square, row 6 + column 9 odd: white");
        assertFalse(t.isBlackAt(-0.001, 0.01), "outside: paper");
        assertFalse(t.isBlackAt(0.2, 0.01), "outside: paper");
    }

    @Test
    void aGridHasWhiteSpaceBetweenItsSquares() {
        CalibrationTarget t = CalibrationTarget.grid(5, 7, 0.02, 0.01);
        assertEquals(7 * 0.02 + 6 * 0.01, t.width(), 1e-12);
        assertEquals(5 * 0.02 + 4 * 0.01, t.height(), 1e-12);
        assertEquals(140, t.points());
        assertTrue(t.isBlackAt(0.019, 0.019));
        assertFalse(t.isBlackAt(0.025, 0.01), "the space");
        assertTrue(t.isBlackAt(0.031, 0.031), "the second square");
    }

    @Test
    void namesItselfAsThePageAndTheCommandLineDo() {
        assertEquals("chessboard, 7 x 10 squares of 20 mm", CalibrationTarget.chessboard(7, 10, 0.02).describe());
        assertEquals("--target grid --rows 5 --cols 7 --square-mm 20 --space-mm 7.5",
                CalibrationTarget.grid(5, 7, 0.02, 0.0075).options());
        assertEquals(CalibrationTarget.Kind.GRID, CalibrationTarget.Kind.byKey("grid"));
    }

    @Test
    void refusesTargetsThatCannotBeDetected() {
        assertTrue(assertThrows(IllegalArgumentException.class, () -> CalibrationTarget.chessboard(2, 5, 0.02))
                .getMessage().contains("3 to 40"));
        assertThrows(IllegalArgumentException.class, () -> CalibrationTarget.chessboard(5, 7, 0));
        assertThrows(IllegalArgumentException.class, () -> CalibrationTarget.grid(5, 7, 0.02, 0));
        assertThrows(IllegalArgumentException.class, () -> new CalibrationTarget(CalibrationTarget.Kind.CHESSBOARD, 5, 7,
                0.02, 0.01));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> CalibrationTarget.Kind.byKey("circles"))
                .getMessage().contains("chessboard or grid"));
    }

    @Test
    void thePlacedSheetCentresThePatternWithItsTopUp() {
        CalibrationTarget t = CalibrationTarget.chessboard(7, 10, 0.02);
        PlacedTarget p = new PlacedTarget(t, PlacedMarker.facingCamera(0, 0, 0), new double[] {0, 0, 1});
        assertEquals(0.12, p.paperHalfWidth(), 1e-12, "half the pattern and a square of paper");
        assertEquals(0.09, p.paperHalfHeight(), 1e-12);
        assertEquals(SyntheticCamera.INK, p.grayAt(-0.099, 0.069), "top-left square: black");
        assertEquals(SyntheticCamera.PAPER, p.grayAt(-0.079, 0.069));
        assertEquals(SyntheticCamera.PAPER, p.grayAt(0.11, 0), "the paper margin");
    }
}
