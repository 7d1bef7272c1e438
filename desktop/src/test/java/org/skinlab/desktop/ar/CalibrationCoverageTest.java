package org.skinlab.desktop.ar;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

/** The coverage warnings name what is missing: too few views, which corners and edges, which tilts. */
class CalibrationCoverageTest {
    /** A 3 x 3 block of points centred at (x, y), 20 px apart. */
    private static double[] block(double x, double y) {
        double[] p = new double[18];
        for (int i = 0; i < 9; i++) {
            p[2 * i] = x + (i % 3 - 1) * 20;
            p[2 * i + 1] = y + (i / 3 - 1) * 20;
        }
        return p;
    }

    private static double[] normal(double turnDeg, double tipDeg) {
        double a = Math.toRadians(turnDeg);
        double b = Math.toRadians(tipDeg);
        return new double[] {Math.sin(a) * Math.cos(b), Math.sin(b), -Math.cos(a) * Math.cos(b)};
    }

    @Test
    void viewsInTheMiddleFacingTheCameraMissEverything() {
        List<double[]> points = List.of(block(320, 240), block(300, 250), block(340, 230));
        List<double[]> normals = List.of(normal(0, 0), normal(5, 3), normal(-8, 0));
        List<String> w = CalibrationCoverage.warnings(640, 480, points, normals);
        assertEquals(4, w.size(), w.toString());
        assertTrue(w.get(0).startsWith("only 3 views"), w.get(0));
        assertTrue(w.get(1).contains("top-left, top-right, bottom-right, bottom-left corners"), w.get(1));
        assertTrue(w.get(2).contains("top, right, bottom, left edges"), w.get(2));
        assertTrue(w.get(3).contains("turned left or right") && w.get(3).contains("most: 8 deg")
                && w.get(3).contains("tipped up or down"), w.get(3));
    }

    @Test
    void namesOnlyWhatIsMissing() {
        List<double[]> points = new ArrayList<>();
        List<double[]> normals = new ArrayList<>();
        // Three corners and the edges between them, views turned but never tipped.
        double[][] at = {{30, 30}, {610, 30}, {610, 450}, {320, 30}, {610, 240}, {320, 240}, {320, 450}, {30, 240},
            {320, 240}};
        for (int i = 0; i < at.length; i++) {
            points.add(block(at[i][0], at[i][1]));
            normals.add(normal(i % 2 == 0 ? 30 : -25, 5));
        }
        List<String> w = CalibrationCoverage.warnings(640, 480, points, normals);
        assertEquals(2, w.size(), w.toString());
        assertTrue(w.get(0).contains("bottom-left corner ") && !w.get(0).contains("top-left"), w.get(0));
        assertTrue(w.get(1).contains("tipped up or down") && !w.get(1).contains("turned"), w.get(1));
    }
}
