package org.skinlab.desktop.ar;

import java.util.Locale;

/**
 * A video's colour matrix: how its 8-bit Y'CbCr samples map to R'G'B' (ITU-T H.273, the table
 * H.264's VUI {@code matrix_coefficients} indexes), with the luma weights Kr and Kb and the sample
 * range. With E'Y in [0, 1] and E'Pb, E'Pr in [-0.5, 0.5]:
 * <pre>
 * E'R = E'Y + 2 (1 - Kr) E'Pr
 * E'B = E'Y + 2 (1 - Kb) E'Pb
 * E'G = E'Y - (2 Kb (1 - Kb) / Kg) E'Pb - (2 Kr (1 - Kr) / Kg) E'Pr,   Kg = 1 - Kr - Kb
 * limited ("video") range: E'Y = (Y - 16) / 219,  E'Pb = (Cb - 128) / 224
 * full range:              E'Y = Y / 255,          E'Pb = (Cb - 128) / 255
 * </pre>
 * and R = 255 E'R, rounded and clamped to [0, 255]. {@link #toRgb} runs on every pixel of a video
 * frame, so the formula is folded into five tables of 256 fixed-point terms (16 fraction bits,
 * rounded once per pixel): no floating point and no allocation per pixel. {@link #fromRgb} is the
 * inverse, for writing test and demo videos.
 */
public final class YCbCr {
    /** BT.601 (SD video, JPEG's matrix) in limited range: what H.264 means when its stream says nothing. */
    public static final YCbCr BT601 = new YCbCr("BT.601", 0.299, 0.114, false);

    private static final int SHIFT = 16;
    private static final int HALF = 1 << (SHIFT - 1);

    private final String name;
    private final double kr;
    private final double kb;
    private final boolean fullRange;
    /** 255 E'Y of each Y sample, and each chroma sample's term in R, G (two) and B, fixed point. */
    private final int[] luma = new int[256];
    private final int[] crToR = new int[256];
    private final int[] cbToG = new int[256];
    private final int[] crToG = new int[256];
    private final int[] cbToB = new int[256];

    private YCbCr(String name, double kr, double kb, boolean fullRange) {
        this.name = name;
        this.kr = kr;
        this.kb = kb;
        this.fullRange = fullRange;
        double kg = 1 - kr - kb;
        double one = 1 << SHIFT;
        for (int v = 0; v < 256; v++) {
            double y = fullRange ? v / 255.0 : (v - 16) / 219.0;
            double c = (v - 128) / (fullRange ? 255.0 : 224.0);
            luma[v] = (int) Math.round(255 * y * one);
            crToR[v] = (int) Math.round(255 * 2 * (1 - kr) * c * one);
            cbToG[v] = (int) Math.round(-255 * 2 * kb * (1 - kb) / kg * c * one);
            crToG[v] = (int) Math.round(-255 * 2 * kr * (1 - kr) / kg * c * one);
            cbToB[v] = (int) Math.round(255 * 2 * (1 - kb) * c * one);
        }
    }

    /**
     * The matrix an H.264 stream's VUI names: {@code matrixCoefficients} as H.273 numbers them (1
     * BT.709; 4 FCC; 5 and 6 BT.601; 7 SMPTE 240M; 9 BT.2020 non-constant luminance; 2, or a
     * stream without a colour description, unspecified: BT.601) and its
     * {@code video_full_range_flag}.
     *
     * @throws IllegalArgumentException for a matrix that is not a Kr/Kb matrix (0 identity/GBR, 8
     *                                  YCgCo, 10 BT.2020 constant luminance, 11 and above) or a
     *                                  reserved number
     */
    public static YCbCr h264(int matrixCoefficients, boolean fullRange) {
        switch (matrixCoefficients) {
            case 1:
                return new YCbCr("BT.709", 0.2126, 0.0722, fullRange);
            case 2:
            case 5:
            case 6:
                return fullRange ? new YCbCr("BT.601", 0.299, 0.114, true) : BT601;
            case 4:
                return new YCbCr("FCC", 0.30, 0.11, fullRange);
            case 7:
                return new YCbCr("SMPTE 240M", 0.212, 0.087, fullRange);
            case 9:
                return new YCbCr("BT.2020", 0.2627, 0.0593, fullRange);
            default:
                throw new IllegalArgumentException("colour matrix " + matrixCoefficients + " (H.273's matrix_coefficients)"
                        + " is not supported: only the Kr/Kb matrices 1 (BT.709), 4, 5, 6 (BT.601), 7 and 9 (BT.2020)");
        }
    }

    /** Luma weight of red. */
    public double kr() {
        return kr;
    }

    /** Luma weight of blue. */
    public double kb() {
        return kb;
    }

    /** Whether samples use the full 0-255 range (else Y 16-235, Cb and Cr 16-240). */
    public boolean fullRange() {
        return fullRange;
    }

    /**
     * The colour of samples {@code y}, {@code cb}, {@code cr} (0-255 each) as R, G, B bytes into
     * {@code rgb[at..at+2]}.
     */
    public void toRgb(int y, int cb, int cr, byte[] rgb, int at) {
        int l = luma[y] + HALF;
        rgb[at] = clamp(l + crToR[cr]);
        rgb[at + 1] = clamp(l + cbToG[cb] + crToG[cr]);
        rgb[at + 2] = clamp(l + cbToB[cb]);
    }

    private static byte clamp(int fixed) {
        int v = fixed >> SHIFT;
        return (byte) (v < 0 ? 0 : v > 255 ? 255 : v);
    }

    /** The samples (Y, Cb, Cr; rounded and clamped to this range) of colour {@code r, g, b} (0-255 each). */
    public int[] fromRgb(int r, int g, int b) {
        double er = r / 255.0;
        double eg = g / 255.0;
        double eb = b / 255.0;
        double ey = kr * er + (1 - kr - kb) * eg + kb * eb;
        double pb = (eb - ey) / (2 * (1 - kb));
        double pr = (er - ey) / (2 * (1 - kr));
        if (fullRange) {
            return new int[] {sample(255 * ey, 0, 255), sample(128 + 255 * pb, 0, 255), sample(128 + 255 * pr, 0, 255)};
        }
        return new int[] {sample(16 + 219 * ey, 16, 235), sample(128 + 224 * pb, 16, 240),
                sample(128 + 224 * pr, 16, 240)};
    }

    private static int sample(double v, int min, int max) {
        return (int) Math.max(min, Math.min(max, Math.round(v)));
    }

    @Override
    public String toString() {
        return String.format(Locale.ROOT, "%s, %s range", name, fullRange ? "full" : "limited");
    }
}
