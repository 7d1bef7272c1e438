package org.skinlab.desktop.eval;

import com.fasterxml.jackson.databind.node.ArrayNode;

import org.skinlab.skinning.SkinningMethod;

/**
 * How far every pair of skinning methods places the same points apart over a clip: the largest
 * distance in the scene (over the model's size) and the largest shift on a phone's screen
 * ({@link PhoneView}), each with the clip time it happened at.
 */
final class MethodPairs {
    private static final SkinningMethod[] METHODS = SkinningMethod.values();

    private final int pairs = METHODS.length * (METHODS.length - 1) / 2;
    private final double[] distance = new double[pairs];
    private final double[] distanceTime = new double[pairs];
    private final double[] pixels = new double[pairs];
    private final double[] pixelsTime = new double[pairs];
    private final int[] pixelsView = new int[pairs];
    private final PhoneView view;
    private final double[][] projected;

    MethodPairs(PhoneView view, int points) {
        this.view = view;
        projected = new double[METHODS.length][2 * points];
    }

    /** The pairs' distances in the pose {@code posed} holds, at clip time {@code time}. */
    void add(PosedMethods posed, double time) {
        int n = posed.points();
        int k = 0;
        for (int a = 0; a < METHODS.length; a++) {
            for (int b = a + 1; b < METHODS.length; b++, k++) {
                double d = largestDistance(posed.scene(METHODS[a]), posed.scene(METHODS[b]), n);
                if (d > distance[k]) {
                    distance[k] = d;
                    distanceTime[k] = time;
                }
            }
        }
        for (int v = 0; v < PhoneView.VIEWS; v++) {
            for (int m = 0; m < METHODS.length; m++) {
                view.project(posed.scene(METHODS[m]), n, v, projected[m]);
            }
            k = 0;
            for (int a = 0; a < METHODS.length; a++) {
                for (int b = a + 1; b < METHODS.length; b++, k++) {
                    double px = PhoneView.largestShift(projected[a], projected[b], n);
                    if (px > pixels[k]) {
                        pixels[k] = px;
                        pixelsTime[k] = time;
                        pixelsView[k] = v;
                    }
                }
            }
        }
    }

    private static double largestDistance(float[] a, float[] b, int count) {
        double max = 0;
        for (int i = 0; i < 3 * count; i += 3) {
            double dx = a[i] - b[i];
            double dy = a[i + 1] - b[i + 1];
            double dz = a[i + 2] - b[i + 2];
            max = Math.max(max, dx * dx + dy * dy + dz * dz);
        }
        return Math.sqrt(max);
    }

    /** Every pair into {@code out}: its methods, the largest distance in percent of {@code size}, the pixels, and when. */
    void put(ArrayNode out, double size) {
        int k = 0;
        for (int a = 0; a < METHODS.length; a++) {
            for (int b = a + 1; b < METHODS.length; b++, k++) {
                out.addObject().put("a", METHODS[a].key()).put("b", METHODS[b].key())
                        .put("maxPercent", EvalReport.round(size > 0 ? 100 * distance[k] / size : 0))
                        .put("maxPercentTime", EvalReport.round(distanceTime[k]))
                        .put("maxPixels", EvalReport.round(pixels[k]))
                        .put("maxPixelsTime", EvalReport.round(pixelsTime[k]))
                        .put("maxPixelsYawDegrees", 360 * pixelsView[k] / PhoneView.VIEWS);
            }
        }
    }
}
