package org.skinlab.desktop.ar;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** Video colour matrices against cases worked by hand from H.273's formulas (YCbCr's comment). */
class YCbCrTest {
    private static int[] rgb(YCbCr m, int y, int cb, int cr) {
        byte[] out = new byte[3];
        m.toRgb(y, cb, cr, out, 0);
        return new int[] {out[0] & 0xFF, out[1] & 0xFF, out[2] & 0xFF};
    }

    /**
     * (Y, Cb, Cr) = (100, 150, 60), BT.601 limited: E'Y = 84/219 = 0.38356, E'Pb = 22/224 =
     * 0.09821, E'Pr = -68/224 = -0.30357;
     * R = 0.38356 + 1.402 (-0.30357) = -0.04205 -> 0;
     * G = 0.38356 - 0.34414 (0.09821) - 0.71414 (-0.30357) = 0.56655 -> 144.47 -> 144;
     * B = 0.38356 + 1.772 (0.09821) = 0.55760 -> 142.19 -> 142.
     * (180, 100, 160): E'Y = 164/219 = 0.74886, E'Pb = -0.125, E'Pr = 32/224 = 0.14286;
     * R = 0.74886 + 1.402 (0.14286) = 0.94914 -> 242.03 -> 242;
     * G = 0.74886 + 0.34414 (0.125) - 0.71414 (0.14286) = 0.68986 -> 175.91 -> 176;
     * B = 0.74886 - 1.772 (0.125) = 0.52736 -> 134.48 -> 134.
     * Limited range's ends: Y 16 is black and 235 white; red (81, 90, 240) is (254.4, -0.5, -1.0).
     */
    @Test
    void bt601LimitedRangeAsWorkedByHand() {
        assertArrayEquals(new int[] {0, 144, 142}, rgb(YCbCr.BT601, 100, 150, 60));
        assertArrayEquals(new int[] {242, 176, 134}, rgb(YCbCr.BT601, 180, 100, 160));
        assertArrayEquals(new int[] {0, 0, 0}, rgb(YCbCr.BT601, 16, 128, 128));
        assertArrayEquals(new int[] {255, 255, 255}, rgb(YCbCr.BT601, 235, 128, 128));
        assertArrayEquals(new int[] {254, 0, 0}, rgb(YCbCr.BT601, 81, 90, 240));
        // Beyond the range's ends, clamped.
        assertArrayEquals(new int[] {0, 0, 0}, rgb(YCbCr.BT601, 0, 128, 128));
        assertArrayEquals(new int[] {255, 255, 255}, rgb(YCbCr.BT601, 255, 128, 128));
    }

    /**
     * BT.709 (Kr 0.2126, Kb 0.0722; 2(1-Kr) = 1.5748, 2(1-Kb) = 1.8556, G's 0.18732 and 0.46812),
     * limited, (100, 150, 60): R = 0.38356 - 1.5748 (0.30357) = -0.0945 -> 0; G = 0.38356 -
     * 0.18732 (0.09821) + 0.46812 (0.30357) = 0.50727 -> 129.35 -> 129; B = 0.38356 + 1.8556
     * (0.09821) = 0.56581 -> 144.28 -> 144. BT.601 in full range: E'Y = 100/255 = 0.39216, E'Pb =
     * 22/255 = 0.08627, E'Pr = -68/255 = -0.26667; R = 0.01829 -> 4.66 -> 5; G = 0.39216 - 0.34414
     * (0.08627) + 0.71414 (0.26667) = 0.55290 -> 140.99 -> 141; B = 0.39216 + 1.772 (0.08627) =
     * 0.54504 -> 138.98 -> 139.
     */
    @Test
    void bt709AndFullRangeAsWorkedByHand() {
        assertArrayEquals(new int[] {0, 129, 144}, rgb(YCbCr.h264(1, false), 100, 150, 60));
        assertArrayEquals(new int[] {5, 141, 139}, rgb(YCbCr.h264(6, true), 100, 150, 60));
        assertArrayEquals(new int[] {255, 255, 255}, rgb(YCbCr.h264(5, true), 255, 128, 128));
    }

    @Test
    void h264MatrixNumbersAndTheUnspecifiedDefault() {
        assertSame(YCbCr.BT601, YCbCr.h264(2, false), "unspecified: BT.601");
        assertSame(YCbCr.BT601, YCbCr.h264(5, false));
        assertSame(YCbCr.BT601, YCbCr.h264(6, false));
        assertEquals(0.2126, YCbCr.h264(1, false).kr());
        assertEquals(0.0593, YCbCr.h264(9, true).kb());
        assertTrue(YCbCr.h264(9, true).fullRange());
        for (int unsupported : new int[] {0, 3, 8, 10, 14, 255}) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> YCbCr.h264(unsupported, false));
            assertTrue(e.getMessage().startsWith("colour matrix " + unsupported + " "), e.getMessage());
        }
    }

    /**
     * Every colour on a grid through Y'CbCr and back, each sample rounded: within 2 levels per
     * channel (limited range has 219 luma and 224 chroma levels for 256, and a chroma sample's
     * rounding moves red and blue by up to 1.4 x 255/224 / 2 = 0.8 level on top of luma's 0.6).
     */
    @Test
    void rgbRoundTripsWithinOneLevel() {
        for (YCbCr m : new YCbCr[] {YCbCr.BT601, YCbCr.h264(1, false), YCbCr.h264(5, true)}) {
            for (int r = 0; r < 256; r += 15) {
                for (int g = 0; g < 256; g += 15) {
                    for (int b = 0; b < 256; b += 15) {
                        int[] s = m.fromRgb(r, g, b);
                        int[] back = rgb(m, s[0], s[1], s[2]);
                        int[] want = {r, g, b};
                        for (int c = 0; c < 3; c++) {
                            assertEquals(want[c], back[c], 2.0, m + ": " + r + "," + g + "," + b + " -> "
                                    + java.util.Arrays.toString(s));
                        }
                    }
                }
            }
        }
    }
}
