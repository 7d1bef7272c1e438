package org.skinlab.desktop.eval;

import java.awt.image.BufferedImage;

import org.joml.Vector4fc;
import org.skinlab.desktop.render.FloorGrid;

/**
 * What a test can check in the viewer's pictures: which pixels are the model's, how much of the
 * picture it covers (a blank or off-screen model covers nothing), and in how many of its pixels two
 * pictures of the same view differ. A pixel is the scene's (not the model's) when it is the
 * background, or the background with the floor's lines ({@link FloorGrid#COLOR}) blended over it
 * (at any opacity: where lines cross, blends add up); the background is the picture's top-left pixel, which the
 * viewer's framing (the model's bounding sphere fills the height) leaves free.
 */
final class PanelPixels {
    /** Colour levels (of 255, any channel) below which two pixels count as the same. */
    static final int TOLERANCE = 12;

    private PanelPixels() {
    }

    /** Per pixel (row by row), whether it shows the model. */
    static boolean[] model(BufferedImage picture) {
        int w = picture.getWidth();
        int h = picture.getHeight();
        int bg = picture.getRGB(0, 0);
        double br = (bg >> 16) & 0xFF;
        double bgr = (bg >> 8) & 0xFF;
        double bb = bg & 0xFF;
        Vector4fc floor = FloorGrid.COLOR;
        double fr = 255 * floor.x() - br;
        double fg = 255 * floor.y() - bgr;
        double fb = 255 * floor.z() - bb;
        double ff = fr * fr + fg * fg + fb * fb;
        boolean[] model = new boolean[w * h];
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int c = picture.getRGB(x, y);
                double dr = ((c >> 16) & 0xFF) - br;
                double dg = ((c >> 8) & 0xFF) - bgr;
                double db = (c & 0xFF) - bb;
                // The share of the floor's colour this pixel holds, if it were floor over background.
                double a = ff > 0 ? Math.max(0, Math.min(1, (dr * fr + dg * fg + db * fb) / ff)) : 0;
                double off = Math.max(Math.abs(dr - a * fr), Math.max(Math.abs(dg - a * fg), Math.abs(db - a * fb)));
                model[y * w + x] = off > TOLERANCE;
            }
        }
        return model;
    }

    /** The model's pixels in percent of the picture's. */
    static double coveragePercent(boolean[] model) {
        int n = 0;
        for (boolean m : model) {
            n += m ? 1 : 0;
        }
        return model.length == 0 ? 0 : 100.0 * n / model.length;
    }

    /**
     * Of the pixels either picture's model covers, the percent whose colours differ by more than
     * {@link #TOLERANCE} in some channel (shape or shading); 0 when neither shows a model.
     */
    static double differingPercent(BufferedImage a, boolean[] modelA, BufferedImage b, boolean[] modelB) {
        int w = a.getWidth();
        int union = 0;
        int differing = 0;
        for (int i = 0; i < modelA.length; i++) {
            if (!modelA[i] && !modelB[i]) {
                continue;
            }
            union++;
            int ca = a.getRGB(i % w, i / w);
            int cb = b.getRGB(i % w, i / w);
            if (channelDistance(ca, cb) > TOLERANCE) {
                differing++;
            }
        }
        return union == 0 ? 0 : 100.0 * differing / union;
    }

    private static int channelDistance(int a, int b) {
        int d = 0;
        for (int shift = 0; shift <= 16; shift += 8) {
            d = Math.max(d, Math.abs(((a >> shift) & 0xFF) - ((b >> shift) & 0xFF)));
        }
        return d;
    }
}
