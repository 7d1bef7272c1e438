package org.skinlab.desktop.eval;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

/**
 * The evaluation's fits, which only describe points they fit: every fit reports each point's
 * residual (in percent of the point) and r², says whether all the points it used lie within
 * {@value #TOLERANCE_PERCENT} % of it, and never predicts a negative time. A cost per item is a
 * proportional fit (time = slope x, through the origin); where the smallest sizes' fixed costs
 * keep it from fitting, they are left out, smallest first, and the fit says from which point on it
 * holds. A line (time = intercept + slope x) that would cross zero above x = 0 becomes the
 * proportional fit.
 */
final class EvalFits {
    /** The largest residual, in percent of the point, at which a fit still describes it. */
    static final double TOLERANCE_PERCENT = 10;
    /** The fewest points a proportional fit keeps when leaving out small sizes. */
    static final int MIN_POINTS = 3;

    private EvalFits() {
    }

    /**
     * A fit: its model, coefficients, r², per-point residuals (NaN for points it left out) and the
     * smallest x it used.
     */
    record Fit(String model, double intercept, double slope, double r2, double[] residualsPercent, double from) {
        /** Whether every point it used lies within the tolerance. */
        boolean holds() {
            for (double r : residualsPercent) {
                if (!Double.isNaN(r) && !(Math.abs(r) <= TOLERANCE_PERCENT)) {
                    return false;
                }
            }
            return true;
        }

        /** Into {@code node}: model, slope (times {@code slopeScale}), intercept, r², residuals, smallest x used, holds. */
        void put(ObjectNode node, double slopeScale) {
            node.put("model", model);
            node.put("slope", EvalReport.round(slope * slopeScale));
            node.put("intercept", EvalReport.round(intercept));
            node.put("r2", EvalReport.round(r2));
            node.put("from", EvalReport.round(from));
            node.put("holds", holds());
            node.put("tolerancePercent", TOLERANCE_PERCENT);
            ArrayNode residuals = node.putArray("residualsPercent");
            for (double r : residualsPercent) {
                if (Double.isNaN(r)) {
                    residuals.addNull();
                } else {
                    residuals.add(EvalReport.round(r));
                }
            }
        }
    }

    /**
     * y = slope x, minimising the points' relative residuals (each point as much as the others,
     * whatever its size), leaving out the smallest x while a residual is above the tolerance and
     * more than {@link #MIN_POINTS} points remain.
     */
    static Fit proportional(double[] x, double[] y) {
        double[] sorted = x.clone();
        java.util.Arrays.sort(sorted);
        int dropped = 0;
        Fit fit = proportionalFrom(x, y, sorted[0]);
        while (!fit.holds() && x.length - dropped > MIN_POINTS) {
            fit = proportionalFrom(x, y, sorted[++dropped]);
        }
        return fit;
    }

    private static Fit proportionalFrom(double[] x, double[] y, double from) {
        // Minimises sum ((y - c x) / y)^2 over the points used: c = sum (x / y) / sum (x / y)^2.
        double num = 0;
        double den = 0;
        for (int i = 0; i < x.length; i++) {
            if (x[i] >= from) {
                num += x[i] / y[i];
                den += (x[i] / y[i]) * (x[i] / y[i]);
            }
        }
        double slope = den > 0 ? num / den : 0;
        return finish("proportional", 0, slope, x, y, from);
    }

    /**
     * y = intercept + slope x by least squares over all points; when the line would give a
     * negative time for some x >= 0 (a negative intercept), the proportional fit instead.
     */
    static Fit line(double[] x, double[] y) {
        int n = x.length;
        double mx = 0;
        double my = 0;
        for (int i = 0; i < n; i++) {
            mx += x[i] / n;
            my += y[i] / n;
        }
        double sxx = 0;
        double sxy = 0;
        for (int i = 0; i < n; i++) {
            sxx += (x[i] - mx) * (x[i] - mx);
            sxy += (x[i] - mx) * (y[i] - my);
        }
        double slope = sxx == 0 ? 0 : sxy / sxx;
        double intercept = my - slope * mx;
        if (intercept < 0) {
            return proportional(x, y);
        }
        return finish("line", intercept, slope, x, y, Double.NEGATIVE_INFINITY);
    }

    private static Fit finish(String model, double intercept, double slope, double[] x, double[] y, double from) {
        double[] residuals = new double[x.length];
        double mean = 0;
        int used = 0;
        for (int i = 0; i < x.length; i++) {
            if (x[i] >= from) {
                mean += y[i];
                used++;
            }
        }
        mean /= Math.max(1, used);
        double ssRes = 0;
        double ssTot = 0;
        for (int i = 0; i < x.length; i++) {
            double fitted = intercept + slope * x[i];
            residuals[i] = x[i] < from ? Double.NaN : 100 * (y[i] - fitted) / y[i];
            if (x[i] >= from) {
                ssRes += (y[i] - fitted) * (y[i] - fitted);
                ssTot += (y[i] - mean) * (y[i] - mean);
            }
        }
        double r2 = ssTot == 0 ? 1 : 1 - ssRes / ssTot;
        double smallest = Double.POSITIVE_INFINITY;
        for (double v : x) {
            smallest = v >= from ? Math.min(smallest, v) : smallest;
        }
        return new Fit(model, intercept, slope, r2, residuals, smallest);
    }
}
