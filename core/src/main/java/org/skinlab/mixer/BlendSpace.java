package org.skinlab.mixer;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/**
 * Clips placed on a line (1-D: e.g. idle at 0, walk at 1.2, run at 3.5 m/s) or a plane (2-D: e.g.
 * sideways and forward speed), and the weight of each at any point of it. A {@link Layer} playing
 * a blend space keeps its clips in step by phase (see {@link Layer#setBlendSpace}). Immutable.
 *
 * <p><b>1-D</b>: between two neighbouring clips the weights are linear in the parameter; beyond
 * the ends the end clip plays alone.
 *
 * <p><b>2-D</b>: gradient-band interpolation in Cartesian form (Johansen 2009, "Automated
 * semi-procedural animation for character locomotion", section 6.3): each clip i has the
 * influence {@code h_i(p) = min over j != i of (1 - (p - p_i).(p_j - p_i) / |p_j - p_i|^2)},
 * clamped at 0, and the weights are the influences normalised to sum 1. On a clip's point it
 * plays alone; the weights change continuously everywhere; unlike barycentric weights on a
 * triangulation, no clip pops in or out along a triangle's edge.
 */
public final class BlendSpace {
    private final String[] clips;
    private final double[] xs;
    private final double[] ys;
    private final boolean planar;

    private BlendSpace(String[] clips, double[] xs, double[] ys, boolean planar) {
        this.clips = clips;
        this.xs = xs;
        this.ys = ys;
        this.planar = planar;
    }

    /**
     * A 1-D blend space.
     *
     * @param positions each clip's name and its place on the parameter's line; at least one
     * @return the blend space
     * @throws IllegalArgumentException for no clips, a position that is not finite, or two clips at one place
     */
    public static BlendSpace linear(Map<String, ? extends Number> positions) {
        List<String> names = new ArrayList<>(positions.keySet());
        double[] xs = new double[names.size()];
        for (int i = 0; i < xs.length; i++) {
            xs[i] = positions.get(names.get(i)).doubleValue();
        }
        return checked(names, xs, new double[xs.length], false);
    }

    /**
     * A 2-D blend space.
     *
     * @param positions each clip's name and its point (x, y) on the plane; at least one
     * @return the blend space
     * @throws IllegalArgumentException for no clips, a point that is not two finite numbers, or two clips at one point
     */
    public static BlendSpace planar(Map<String, double[]> positions) {
        List<String> names = new ArrayList<>(positions.keySet());
        double[] xs = new double[names.size()];
        double[] ys = new double[names.size()];
        for (int i = 0; i < xs.length; i++) {
            double[] p = positions.get(names.get(i));
            if (p == null || p.length != 2) {
                throw new IllegalArgumentException("blend space: clip \"" + names.get(i) + "\" needs a point (x, y)");
            }
            xs[i] = p[0];
            ys[i] = p[1];
        }
        return checked(names, xs, ys, true);
    }

    private static BlendSpace checked(List<String> names, double[] xs, double[] ys, boolean planar) {
        if (names.isEmpty()) {
            throw new IllegalArgumentException("blend space without clips");
        }
        for (int i = 0; i < xs.length; i++) {
            if (!Double.isFinite(xs[i]) || !Double.isFinite(ys[i])) {
                throw new IllegalArgumentException("blend space: clip \"" + names.get(i) + "\" is at "
                        + where(xs[i], ys[i], planar) + " (need finite numbers)");
            }
            for (int j = 0; j < i; j++) {
                if (xs[i] == xs[j] && ys[i] == ys[j]) {
                    throw new IllegalArgumentException("blend space: clips \"" + names.get(j) + "\" and \""
                            + names.get(i) + "\" are both at " + where(xs[i], ys[i], planar)
                            + " (each clip needs its own place)");
                }
            }
        }
        return new BlendSpace(names.toArray(new String[0]), xs, ys, planar);
    }

    private static String where(double x, double y, boolean planar) {
        return planar ? "(" + x + ", " + y + ")" : String.valueOf(x);
    }

    /**
     * The clips, in the order their weights are written.
     *
     * @return the clip names
     */
    public List<String> clips() {
        return List.of(clips);
    }

    /**
     * Whether the space is 2-D.
     *
     * @return true for {@link #planar}, false for {@link #linear}
     */
    public boolean isPlanar() {
        return planar;
    }

    /**
     * Each clip's weight at the point (x, y) (y is ignored in 1-D). Allocation-free.
     *
     * @param x the parameter, or the point's x
     * @param y the point's y (2-D only)
     * @param dest receives one weight per clip, in {@link #clips()} order; they sum to 1
     * @throws IllegalArgumentException when x or y (2-D) is NaN
     */
    public void weights(double x, double y, double[] dest) {
        if (Double.isNaN(x) || planar && Double.isNaN(y)) {
            throw new IllegalArgumentException("blend space parameter is NaN");
        }
        if (planar) {
            gradientBands(x, y, dest);
        } else {
            linearWeights(x, dest);
        }
    }

    private void linearWeights(double x, double[] dest) {
        int below = -1;
        int above = -1;
        for (int i = 0; i < xs.length; i++) {
            dest[i] = 0;
            if (xs[i] <= x && (below < 0 || xs[i] > xs[below])) {
                below = i;
            }
            if (xs[i] >= x && (above < 0 || xs[i] < xs[above])) {
                above = i;
            }
        }
        if (below < 0 || above < 0 || below == above) {
            dest[below >= 0 ? below : above] = 1;
            return;
        }
        double u = (x - xs[below]) / (xs[above] - xs[below]);
        dest[below] = 1 - u;
        dest[above] = u;
    }

    private void gradientBands(double x, double y, double[] dest) {
        double sum = 0;
        for (int i = 0; i < xs.length; i++) {
            double h = xs.length == 1 ? 1 : Double.POSITIVE_INFINITY;
            for (int j = 0; j < xs.length; j++) {
                if (j != i) {
                    double ex = xs[j] - xs[i];
                    double ey = ys[j] - ys[i];
                    h = Math.min(h, 1 - ((x - xs[i]) * ex + (y - ys[i]) * ey) / (ex * ex + ey * ey));
                }
            }
            dest[i] = Math.max(0, h);
            sum += dest[i];
        }
        if (sum > 0) {
            for (int i = 0; i < xs.length; i++) {
                dest[i] /= sum;
            }
            return;
        }
        // Every influence clamped to 0 (possible only through rounding): the nearest clip plays alone.
        int nearest = 0;
        for (int i = 1; i < xs.length; i++) {
            if (Math.hypot(x - xs[i], y - ys[i]) < Math.hypot(x - xs[nearest], y - ys[nearest])) {
                nearest = i;
            }
        }
        dest[nearest] = 1;
    }

    @Override
    public String toString() {
        StringBuilder b = new StringBuilder(planar ? "2-D blend space [" : "1-D blend space [");
        for (int i = 0; i < clips.length; i++) {
            b.append(i > 0 ? ", " : "").append(clips[i]).append(" at ").append(where(xs[i], ys[i], planar));
        }
        return b.append(']').toString();
    }
}
