package org.skinlab.android.logic;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;

/**
 * The two camera streams' sizes, chosen from the sizes the camera lists: the tracking stream
 * (YUV, analysed by the tracker) and the preview (drawn as the background). Camera2 crops every
 * stream from the sensor to the stream's own aspect, so only streams of one aspect see the same
 * part of the world: a preview of another aspect than the tracked image would put the model
 * beside the marker. The tracking stream is preferred near {@value #TRACKING_WIDTH}x{@value
 * #TRACKING_HEIGHT} (the tracker's speed and accuracy were measured there, docs/ar.md) and 4:3
 * (the most of a 4:3 sensor); the preview is the largest of the same aspect up to {@value
 * #PREVIEW_MAX_PIXELS} pixels (a sharp background without pushing a 12 MP stream through the GPU).
 *
 * @param trackingWidth  the tracking stream's width in pixels
 * @param trackingHeight its height
 * @param previewWidth   the preview's width
 * @param previewHeight  the preview's height
 * @param sameAspect     whether both have the same aspect (false only when the camera lists no pair)
 */
public record StreamSizes(int trackingWidth, int trackingHeight, int previewWidth, int previewHeight,
        boolean sameAspect) {
    public static final int TRACKING_WIDTH = 640;
    public static final int TRACKING_HEIGHT = 480;
    public static final int PREVIEW_MAX_PIXELS = 1920 * 1440;
    /**
     * Aspects closer than this are the same: 1920x1088 is 16:9 to a camera driver (a crop of 0.7%),
     * while the nearest real neighbours (4:3 and 5:4, 16:10 and 16:9) differ by 0.08 or more.
     */
    private static final double SAME_ASPECT = 0.02;

    /**
     * The choice among the listed sizes ({@code {width, height}} pairs, in any order).
     *
     * @throws IllegalArgumentException when either list is empty
     */
    public static StreamSizes choose(int[][] tracking, int[][] preview) {
        if (tracking.length == 0 || preview.length == 0) {
            throw new IllegalArgumentException("the camera lists no " + (tracking.length == 0 ? "YUV" : "preview")
                    + " stream size");
        }
        List<int[]> candidates = new ArrayList<>(List.of(tracking));
        candidates.sort(Comparator.comparingDouble(StreamSizes::trackingCost));
        for (int[] t : candidates) {
            int[] p = largestPreview(preview, aspect(t));
            if (p != null) {
                return new StreamSizes(t[0], t[1], p[0], p[1], true);
            }
        }
        // No pair of one aspect: the preferred tracking size and the preview nearest its aspect.
        int[] t = candidates.get(0);
        int[] best = preview[0];
        for (int[] p : preview) {
            double d = Math.abs(aspect(p) - aspect(t)) - Math.abs(aspect(best) - aspect(t));
            if (d < 0 || d == 0 && fits(p) && area(p) > area(best)) {
                best = p;
            }
        }
        return new StreamSizes(t[0], t[1], best[0], best[1], false);
    }

    /** What the status line says when the streams do not line up, or "" when they do. */
    public String problem() {
        return sameAspect ? "" : String.format(Locale.ROOT, "the camera lists no preview of the tracked image's shape "
                + "(%dx%d, preview %dx%d): the model may not sit exactly on the marker", trackingWidth, trackingHeight,
                previewWidth, previewHeight);
    }

    /** Smaller is better: 4:3 first, then the nearest pixel count to 640x480. */
    private static double trackingCost(int[] size) {
        double aspectCost = Math.abs(aspect(size) - 4.0 / 3) < SAME_ASPECT ? 0 : 1;
        double pixels = Math.abs(Math.log((double) area(size) / (TRACKING_WIDTH * TRACKING_HEIGHT)));
        return aspectCost * 100 + pixels;
    }

    /** The largest preview of this aspect within the pixel budget (else the smallest of it), or null. */
    private static int[] largestPreview(int[][] preview, double aspect) {
        int[] best = null;
        for (int[] p : preview) {
            if (Math.abs(aspect(p) - aspect) >= SAME_ASPECT) {
                continue;
            }
            if (best == null || (fits(p) && (!fits(best) || area(p) > area(best)))
                    || (!fits(p) && !fits(best) && area(p) < area(best))) {
                best = p;
            }
        }
        return best;
    }

    private static boolean fits(int[] size) {
        return area(size) <= PREVIEW_MAX_PIXELS;
    }

    private static long area(int[] size) {
        return (long) size[0] * size[1];
    }

    private static double aspect(int[] size) {
        return (double) size[0] / size[1];
    }
}
