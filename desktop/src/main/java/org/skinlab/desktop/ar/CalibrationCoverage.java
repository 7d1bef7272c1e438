package org.skinlab.desktop.ar;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * Whether a calibration's views can pin the lens down, in words a user can act on. A lens model is
 * only measured where the target was seen: radial distortion grows toward the image's corners, so
 * views must put target points there; and the focal length is only separable from the distance
 * when the target is seen tilted (Zhang 2000, section 3.3: parallel views are degenerate), both
 * turned left/right and tipped up/down.
 */
public final class CalibrationCoverage {
    /** Fewer views than this is a warning (OpenCV's and BoofCV's guides ask for 10 to 20). */
    public static final int ENOUGH_VIEWS = 8;
    /** A view counts as tilted about an axis from this angle on. */
    public static final double TILT_DEGREES = 20;
    /** The image is cut into this many cells per side; the outer ring is "the edges", its corner cells "the corners". */
    static final int CELLS = 5;

    private static final String[] CORNERS = {"top-left", "top-right", "bottom-right", "bottom-left"};

    private CalibrationCoverage() {
    }

    /**
     * The warnings for views of a {@code width x height} image: {@code points[v]} the target's
     * points in view v (x0, y0, x1, y1, ... in pixels), {@code normals[v]} the target plane's
     * normal in camera coordinates (x right, y down, z forward). Empty when nothing is missing.
     */
    public static List<String> warnings(int width, int height, List<double[]> points, List<double[]> normals) {
        List<String> out = new ArrayList<>();
        int views = points.size();
        if (views < ENOUGH_VIEWS) {
            out.add("only " + views + " view" + (views == 1 ? "" : "s") + " of the target: take 10 to 20 (at least "
                    + ENOUGH_VIEWS + ") for a reliable lens");
        }
        boolean[] seen = new boolean[CELLS * CELLS];
        for (double[] p : points) {
            for (int i = 0; i + 1 < p.length; i += 2) {
                int cx = Math.min(CELLS - 1, Math.max(0, (int) Math.floor(p[i] / width * CELLS)));
                int cy = Math.min(CELLS - 1, Math.max(0, (int) Math.floor(p[i + 1] / height * CELLS)));
                seen[cy * CELLS + cx] = true;
            }
        }
        int last = CELLS - 1;
        int[][] corner = {{0, 0}, {last, 0}, {last, last}, {0, last}};
        List<String> corners = new ArrayList<>();
        for (int i = 0; i < 4; i++) {
            if (!seen[corner[i][1] * CELLS + corner[i][0]]) {
                corners.add(CORNERS[i]);
            }
        }
        if (!corners.isEmpty()) {
            out.add("no target point in the image's " + String.join(", ", corners) + " corner"
                    + (corners.size() > 1 ? "s" : "") + " (the outer " + 100 / CELLS + "% of the image): the lens "
                    + "distortion there is extrapolated; hold the target so that it reaches into "
                    + (corners.size() > 1 ? "them" : "it"));
        }
        List<String> edges = new ArrayList<>();
        String[] names = {"top", "right", "bottom", "left"};
        for (int side = 0; side < 4; side++) {
            boolean any = false;
            for (int k = 1; k < last; k++) {
                int cx = side == 1 ? last : side == 3 ? 0 : k;
                int cy = side == 0 ? 0 : side == 2 ? last : k;
                any |= seen[cy * CELLS + cx];
            }
            if (!any) {
                edges.add(names[side]);
            }
        }
        if (!edges.isEmpty()) {
            out.add("no target point along the image's " + String.join(", ", edges) + " edge"
                    + (edges.size() > 1 ? "s" : "") + ": move the target there in some views");
        }
        double maxTurn = 0;
        double maxTip = 0;
        for (double[] n : normals) {
            double z = Math.abs(n[2]);
            maxTurn = Math.max(maxTurn, Math.toDegrees(Math.atan2(Math.abs(n[0]), z)));
            maxTip = Math.max(maxTip, Math.toDegrees(Math.atan2(Math.abs(n[1]), z)));
        }
        List<String> tilts = new ArrayList<>();
        if (maxTurn < TILT_DEGREES) {
            tilts.add(String.format(Locale.ROOT, "turned left or right (about the vertical axis; most: %.0f deg)",
                    maxTurn));
        }
        if (maxTip < TILT_DEGREES) {
            tilts.add(String.format(Locale.ROOT, "tipped up or down (about the horizontal axis; most: %.0f deg)",
                    maxTip));
        }
        if (!tilts.isEmpty() && views > 0) {
            out.add("no view with the target " + String.join(" or ", tilts) + " by " + (int) TILT_DEGREES
                    + " deg or more: tilt it 20 to 45 deg in some views, or the focal length is poorly determined");
        }
        return out;
    }
}
